// SPDX-License-Identifier: MIT
#include "state/walkthrough.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace hsr::viz {
namespace {

constexpr double turn_step = 5.0 * M_PI / 180;  // a key press turns by 5°
constexpr double look_per_point = 0.3 * M_PI / 180;  // a drag of one point turns by 0.3°
constexpr double max_pitch = 80.0 * M_PI / 180;

}  // namespace

Walkthrough::Walkthrough(const algo::Scene& scene, std::vector<algo::Stage> stages, algo::Viewport viewport, algo::PipelineOptions options)
    : options_(std::move(options)) {
    options_.viewport = viewport;
    // prepared with every stage that may be switched on, so that a switch never prepares again
    algo::PipelineOptions all = options_;
    all.stages.assign(std::begin(algo::all_stages), std::end(algo::all_stages));
    prepared_ = algo::prepare_scene(scene, all);
    options_.stages = std::move(stages);
    camera_ = prepared_.scene.camera;
    const algo::Vec3 d = camera_.target - camera_.eye;
    yaw_ = std::atan2(d.x, -d.z);
    pitch_ = std::clamp(std::atan2(d.y, std::hypot(d.x, d.z)), -max_pitch, max_pitch);
    // a step: 1/150 of the scene's size across (3 m in the lesson's city, 10 cm in its rooms)
    const algo::Aabb& all_boxes = prepared_.hierarchy.nodes.empty() ? algo::Aabb{} : prepared_.hierarchy.nodes.front().box;
    const double size = all_boxes.empty() ? 1.0 : glm::length(all_boxes.size());
    step_ = std::max(1e-6, size / 150);
    aim();
}

void Walkthrough::aim() {
    const algo::Vec3 d{std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
    camera_.target = camera_.eye + d;
    camera_.up = {0, 1, 0};
    dirty_ = true;
}

void Walkthrough::walk(int forward, int turn_left) {
    if (forward) camera_.eye += algo::Vec3(std::sin(yaw_), 0, -std::cos(yaw_)) * (step_ * forward);  // on the level
    yaw_ -= turn_left * turn_step;
    aim();
}

void Walkthrough::look(double right, double down) {
    yaw_ += right * look_per_point;
    pitch_ = std::clamp(pitch_ - down * look_per_point, -max_pitch, max_pitch);
    aim();
}

void Walkthrough::toggle(algo::Stage stage) {
    if (stage == algo::Stage::hse) return;
    auto& s = options_.stages;
    if (const auto at = std::find(s.begin(), s.end(), stage); at != s.end()) s.erase(at);
    else s.push_back(stage);
    dirty_ = true;
}

bool Walkthrough::on(algo::Stage stage) const {
    return stage == algo::Stage::hse || std::find(options_.stages.begin(), options_.stages.end(), stage) != options_.stages.end();
}

std::vector<algo::Stage> Walkthrough::switchable() const {
    std::vector<algo::Stage> out;
    for (const algo::Stage s : algo::all_stages)
        if (s != algo::Stage::hse && (s != algo::Stage::portals || prepared_.pvs)) out.push_back(s);
    return out;
}

void Walkthrough::set_coherent(bool coherent) {
    dirty_ = dirty_ || coherent != coherent_;
    coherent_ = coherent;
}

const algo::PipelineResult& Walkthrough::frame() {
    if (!dirty_) return last_;
    dirty_ = false;
    error_.clear();
    const bool from_before = coherent_ && on(algo::Stage::hiz);
    try {
        const auto start = std::chrono::steady_clock::now();
        last_ = algo::run_frame(prepared_, camera_, options_, from_before ? seen_ : std::vector<std::uint8_t>{});
        frame_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    } catch (const std::exception& e) {  // a stage that cannot run from here (the portals stage outside every room)
        error_ = e.what();
        last_ = {};
        seen_.clear();
        return last_;
    }
    drawn_first_ = 0;
    const auto hiz = std::find_if(last_.stages.begin(), last_.stages.end(), [](const algo::StageReport& r) { return r.stage == algo::Stage::hiz; });
    if (from_before && hiz != last_.stages.end())
        for (std::size_t i = 0; i < seen_.size() && i < hiz->candidates.size(); ++i) drawn_first_ += seen_[i] && hiz->candidates[i];
    seen_ = algo::seen_in(last_, prepared_.scene.polygons.size());
    ++frames_;
    return last_;
}

std::string Walkthrough::summary() const {
    char head[160];
    std::snprintf(head, sizeof head, "walk: eye %.3f,%.3f,%.3f heading %.1f°", camera_.eye.x, camera_.eye.y, camera_.eye.z, yaw_ * 180 / M_PI);
    std::string s = head;
    for (const algo::StageReport& r : last_.stages)
        if (r.ran) s += "; " + std::string(to_string(r.stage)) + " " + std::to_string(r.in) + " in, " + std::to_string(r.left_out) + " left out";
    char tail[64];
    std::snprintf(tail, sizeof tail, "; frame %.2f ms", frame_ms_);
    return s + tail + (coherent_ ? " (Hi-Z from the previous frame's view)" : "");
}

}  // namespace hsr::viz
