// SPDX-License-Identifier: MIT
#include "render/clip_renderer.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>


#include "render/palette.h"
#include "render/scene_color.h"
#include "state/clip_regions.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::ClipPlane;
using algo::Vec4;

// Clip space → world space, as float points for the line batches.
class ToWorld {
public:
    explicit ToWorld(const algo::Camera& c) : world_(c) {}
    std::optional<glm::vec3> operator()(const Vec4& clip) const {
        if (auto p = world_(clip)) return glm::vec3(*p);
        return std::nullopt;
    }

private:
    ClipToWorld world_;
};

// The clip volume's corner for NDC signs (±1, ±1, ±1).
Vec4 corner(int x, int y, int z) { return {double(x), double(y), double(z), 1.0}; }

// The four NDC corners of the face of the volume that plane r bounds (none for w ≥ ε: it is at the eye).
std::optional<std::array<Vec4, 4>> face(ClipPlane r) {
    switch (r) {
        case ClipPlane::x_min: return std::array{corner(-1, -1, -1), corner(-1, 1, -1), corner(-1, 1, 1), corner(-1, -1, 1)};
        case ClipPlane::x_max: return std::array{corner(1, -1, -1), corner(1, 1, -1), corner(1, 1, 1), corner(1, -1, 1)};
        case ClipPlane::y_min: return std::array{corner(-1, -1, -1), corner(1, -1, -1), corner(1, -1, 1), corner(-1, -1, 1)};
        case ClipPlane::y_max: return std::array{corner(-1, 1, -1), corner(1, 1, -1), corner(1, 1, 1), corner(-1, 1, 1)};
        case ClipPlane::z_min: return std::array{corner(-1, -1, -1), corner(1, -1, -1), corner(1, 1, -1), corner(-1, 1, -1)};
        case ClipPlane::z_max: return std::array{corner(-1, -1, 1), corner(1, -1, 1), corner(1, 1, 1), corner(-1, 1, 1)};
        case ClipPlane::w_min: return std::nullopt;
    }
    return std::nullopt;
}

template <class Points>  // std::vector<Vec4> or CowVector<Vec4, N>
void polyline(LineBatch& b, const ToWorld& world, const Points& v, bool closed, glm::vec4 color) {
    const std::size_t n = v.size();
    if (n == 1)
        if (auto p = world(v[0])) b.point(*p, color);
    for (std::size_t i = 0; i + 1 < n + (closed && n > 2 ? 1 : 0); ++i) {
        const auto a = world(v[i]), c = world(v[(i + 1) % n]);
        if (a && c) b.line(*a, *c, color);
    }
}

void draw_volume(const ClipView& view, const ToWorld& world, const algo::Camera& camera, LineBatches& out,
                 std::vector<Label>& labels) {
    // the 12 edges of the frustum (or box)
    for (int a = -1; a <= 1; a += 2)
        for (int b = -1; b <= 1; b += 2) {
            const std::array<std::pair<Vec4, Vec4>, 3> edges = {std::pair{corner(-1, a, b), corner(1, a, b)},
                                                                std::pair{corner(a, -1, b), corner(a, 1, b)},
                                                                std::pair{corner(a, b, -1), corner(a, b, 1)}};
            for (const auto& [p, q] : edges)
                if (auto wp = world(p), wq = world(q); wp && wq) out.faint.line(*wp, *wq, palette::volume);
        }
    const glm::vec3 eye(camera.eye);
    out.faint.point(eye, palette::eye);
    labels.push_back({eye, tr("view.eye"), palette::eye});
    if (!view.plane) return;
    if (const auto f = face(*view.plane)) {
        std::array<glm::vec3, 4> c{};
        for (int i = 0; i < 4; ++i)
            if (auto p = world((*f)[std::size_t(i)])) c[std::size_t(i)] = *p;
        out.faint.triangle(c[0], c[1], c[2], palette::plane_fill);
        out.faint.triangle(c[0], c[2], c[3], palette::plane_fill);
        for (int i = 0; i < 4; ++i) out.bold.line(c[std::size_t(i)], c[std::size_t((i + 1) % 4)], palette::plane_edge);
        labels.push_back({(c[0] + c[2]) * 0.5f, std::string(algo::plane_inequality(*view.plane, view.space)),
                          palette::plane_edge});
    } else {
        labels.push_back({eye, "w ≥ ε", palette::plane_edge});
    }
}

// The 27 regions of the outcodes (state/clip_regions.h): the planes drawn on past the volume, a label per region.
void draw_outcode_regions(const algo::Camera& camera, LineBatches& out, std::vector<Label>& labels) {
    const glm::vec4 grid{palette::volume.x, palette::volume.y, palette::volume.z, 0.45f};
    for (const auto& [a, b] : outcode_region_lines(camera)) out.faint.line(glm::vec3(a), glm::vec3(b), grid);
    for (const OutcodeRegion& r : outcode_regions(camera))
        labels.push_back({glm::vec3(r.at), algo::to_string(r.code), r.code.inside() ? palette::inside : grid});
}

void draw_active_segment(const ClipView& view, const PrimitiveState& p, const ToWorld& world, LineBatches& out,
                         std::vector<Label>& labels, Tween tween) {
    const Vec4 a = p.input[0], b = p.input[1];
    // the tween applies only while the same primitive is being clipped before and after the step
    const ClipView* before = tween.before && tween.before->active == view.active ? tween.before : nullptr;
    const double t = before ? double(tween.t) : 1.0;
    const auto slide = [&](auto from, auto to) { return from + (to - from) * t; };
    if (view.algorithm == algo::ClipAlgorithm::liang_barsky) {  // the part [t_enter, t_leave] of the input
        const double t_enter = before ? slide(before->t_enter, view.t_enter) : view.t_enter;
        const double t_leave = before ? slide(before->t_leave, view.t_leave) : view.t_leave;
        const Vec4 e = a + t_enter * (b - a), l = a + t_leave * (b - a);
        if (auto we = world(e), wl = world(l); we && wl) {
            out.bold.line(*we, *wl, palette::working);
            out.bold.point(*we, palette::parameter);
            out.bold.point(*wl, palette::parameter);
            char buf[64];
            std::snprintf(buf, sizeof buf, "t_enter %.3g", view.t_enter);
            labels.push_back({*we, buf, palette::parameter});
            std::snprintf(buf, sizeof buf, "t_leave %.3g", view.t_leave);
            labels.push_back({*wl, buf, palette::parameter});
        }
        return;
    }
    const auto w1 = world(before ? slide(before->p1, view.p1) : view.p1);
    const auto w2 = world(before ? slide(before->p2, view.p2) : view.p2);
    if (w1 && w2) out.bold.line(*w1, *w2, palette::working);
    const auto end = [&](const std::optional<glm::vec3>& at, const char* name, algo::Outcode c, bool known) {
        if (!at) return;
        const glm::vec4 color = !known ? palette::working : c.inside() ? palette::inside : palette::outside;
        out.bold.point(*at, color);
        labels.push_back({*at, known ? std::string(name) + " " + algo::to_string(c) : std::string(name), color});
    };
    end(w1, "p1", view.c1, view.c1_known);
    end(w2, "p2", view.c2, view.c2_known);
}

void draw_active_polygon(const ClipView& view, const SceneColors& colors, const PrimitiveState& p, const ToWorld& world,
                         LineBatches& out) {
    polyline(out.faint, world, view.stage_input, true, palette::working);
    polyline(out.bold, world, view.stage_output, false, colors(p.id, 1));
    if (view.edge >= 0 && !view.stage_input.empty()) {
        const std::size_t i = std::size_t(view.edge), n = view.stage_input.size();
        if (auto s = world(view.stage_input[i]), e = world(view.stage_input[(i + 1) % n]); s && e) {
            out.bold.line(*s, *e, palette::current_edge);
            out.bold.point(*e, palette::current_edge);
        }
    }
}

}  // namespace

void draw_clip_view(const ClipView& view, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels,
                    Tween tween, bool regions) {
    const SceneColors colors(scene);
    const ToWorld world(scene.camera);
    draw_volume(view, world, scene.camera, out, labels);
    if (regions) draw_outcode_regions(scene.camera, out, labels);

    for (std::size_t i = 0; i < view.primitives.size(); ++i) {
        const PrimitiveState& p = view.primitives[i];
        const bool active = int(i) == view.active && p.status == PrimitiveStatus::clipping;
        const float input_alpha = p.status == PrimitiveStatus::waiting ? 0.7f : 0.3f;
        polyline(p.kind == PrimitiveKind::point ? out.bold : out.faint, world, p.input,
                 p.kind == PrimitiveKind::polygon, colors(p.id, input_alpha));
        if (p.status == PrimitiveStatus::done)
            polyline(out.bold, world, p.visible, p.kind == PrimitiveKind::polygon, colors(p.id, 1));
        if (!p.input.empty())
            if (auto at = world(p.input[0])) labels.push_back({*at, std::to_string(p.id), colors(p.id, 0.9f)});
        if (!active) continue;
        if (p.kind == PrimitiveKind::segment) draw_active_segment(view, p, world, out, labels, tween);
        if (p.kind == PrimitiveKind::polygon) {
            draw_active_polygon(view, colors, p, world, out);
            // the stage's vertices named as the narration and the questions name them ("the edge v0 → v1")
            if (view.stage_input.size() <= 12)
                for (std::size_t k = 0; k < view.stage_input.size(); ++k)
                    if (auto at = world(view.stage_input[k])) labels.push_back({*at, "v" + std::to_string(k), palette::current_edge});
        }
    }
    for (std::size_t k = 0; k < view.intersections.size(); ++k)
        if (auto at = world(view.intersections[k])) {
            out.bold.point(*at, palette::intersection);
            labels.push_back({*at, "i" + std::to_string(k + 1), palette::intersection});
        }
}

std::vector<glm::vec3> clip_view_points(const ClipView& view, const algo::Scene& scene) {
    const ToWorld world(scene.camera);
    std::vector<glm::vec3> volume;
    for (int x = -1; x <= 1; x += 2)
        for (int y = -1; y <= 1; y += 2)
            for (int z = -1; z <= 1; z += 2)
                if (auto p = world(corner(x, y, z))) volume.push_back(*p);
    volume.emplace_back(scene.camera.eye);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : volume) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 centre = (lo + hi) * 0.5f;
    const float reach = 0.8f * std::max(0.5f, glm::length(hi - lo));
    // the polygons too (one beside the volume was cut off under the panels), those within its size (not the extreme
    // cases' 1e307); segments may run off the picture, what is clipped of them lies in the volume
    std::vector<glm::vec3> points = volume;
    for (const PrimitiveState& p : view.primitives) {
        if (p.kind != PrimitiveKind::polygon) continue;
        for (const auto& q : p.input)
            if (auto at = world(q); at && glm::length(*at - centre) < reach) points.push_back(*at);
    }
    return points;
}

}  // namespace hsr::viz
