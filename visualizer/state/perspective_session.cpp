// SPDX-License-Identifier: MIT
#include "state/perspective_session.h"

#include <random>

#include "core/overloaded.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The Greek notes' occluding pairs, and the transform that makes them cheap.
const Pseudocode<TransformEvent> transform_lines = {
    {"eye space: the view volume, the eye at its apex", {step<VolumeShown>()}},
    {"scale the volume to the canonical one", {step<WarpStep>([](const WarpStep& e) { return e.stage == 1; })}},
    {"perspective transform: frustum → box, eye → ∞", {step<WarpStep>([](const WarpStep& e) { return e.stage == 2; })}},
    {"for each point p:", {}},
    {"  p′ = (M · p) / w        (3 divisions, once)", {step<PointTransformed>(), step<PointLeftOut>()}},
    {"for each pair of points a, b:", {}},
    {"  before: x_a/z_a = x_b/z_b and y_a/z_a = y_b/z_b", {}},
    {"  after:  x′_a = x′_b and y′_a = y′_b", {step<PairCompared>()}},
    {"    then the smaller z′ occludes the other", {}},
    {"done", {step<TransformFinished>()}},
};

// Ten points in front of a camera, half of them in pairs on one projector (one a power of two farther along it).
std::optional<Scene> random_points(std::uint32_t seed, bool) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), depth(1.5, 4.5);
    Scene s;
    s.name = "random points " + std::to_string(seed);
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 0, -1}, s.camera.near = 1, s.camera.far = 10;
    const auto add = [&](Vec3 p, std::uint8_t hue) {
        s.points.push_back({SceneId(s.points.size() + 1), Color{hue, std::uint8_t(255 - hue), 200}, glm::dvec4(p, 1)});
    };
    for (int i = 0; i < 5; ++i) {
        const double z = -depth(rng);
        const Vec3 p(unit(rng) * -z * 0.5, unit(rng) * -z * 0.45, z);
        add(p, std::uint8_t(40 * i));
        add(i % 2 == 0 ? p * 2.0 : Vec3(unit(rng) * 2, unit(rng) * 2, -depth(rng) * 2), std::uint8_t(40 * i + 20));
    }
    return s;
}

}  // namespace

PerspectiveView perspective_initial_view(const Scene& scene) {
    auto input = std::make_shared<PerspectiveInput>();
    input->maps = view_volume_maps(scene.camera);
    input->corners = view_volume_corners(scene.camera);
    for (const ScenePoint& p : scene.points) input->points.push_back(Vec3(input->maps.view * p.p));
    input->near = scene.camera.near, input->far = scene.camera.far;
    PerspectiveView v;
    v.transformed.resize(input->points.size());
    v.left_out.resize(input->points.size());
    v.input = std::move(input);
    return v;
}

PerspectiveSession::RunType PerspectiveSession::machine(const Lesson& lesson) {
    PerspectiveView initial = perspective_initial_view(lesson.scene);
    return {perspective_transform(lesson.scene), std::move(initial)};
}

void reduce(PerspectiveView& v, const TransformEvent& event) {
    std::visit(overloaded{
                   [&](const VolumeShown&) {},
                   [&](const WarpStep& e) { v.stage = e.stage, v.s = e.s; },
                   [&](const PointTransformed& e) { v.transformed[e.point] = e; },
                   [&](const PointLeftOut& e) { v.left_out[e.point] = true; },
                   [&](const PairCompared& e) {
                       v.pair = e;
                       ++v.comparisons;
                       if (e.same_after) v.occluding.push_back(e.nearer == std::int32_t(e.b) ? std::pair(e.b, e.a) : std::pair(e.a, e.b));
                   },
                   [&](const TransformFinished& e) { v.finished = e, v.pair.reset(); },
               },
               event);
}

std::size_t approx_bytes(const PerspectiveView& v) {
    return sizeof(PerspectiveView) + v.transformed.capacity() * sizeof(std::optional<PointTransformed>) + v.left_out.capacity() / 8 +
           v.occluding.capacity() * sizeof(std::pair<std::uint32_t, std::uint32_t>);
}

PerspectiveSession::PerspectiveSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string PerspectiveSession::sentence_of(const TransformEvent& e, const PerspectiveView&) { return describe(e); }
std::string PerspectiveSession::describe_event(const TransformEvent& e) const { return sentence_of(e, view()); }
std::string PerspectiveSession::speak_event(const TransformEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<TransformEvent>& PerspectiveSession::table() const { return transform_lines; }

const FamilyFacts PerspectiveSession::facts = {
    .topic = "Perspective transform",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &random_points,
    .measure = &analysis::measure_perspective,
};

}  // namespace hsr::viz
