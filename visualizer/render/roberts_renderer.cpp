// SPDX-License-Identifier: MIT
#include "render/roberts_renderer.h"

#include <glm/geometric.hpp>

#include "render/palette.h"
#include "render/scene_color.h"

namespace hsr::viz {

using algo::Vec3;

namespace {

// A part [t0, t1] of a → b as short dashes (hidden lines drawn the draughtsman's way).
void dashes(LineBatch& out, Vec3 a, Vec3 b, double t0, double t1, glm::vec4 colour) {
    const int n = std::max(1, int(std::round((t1 - t0) * glm::length(b - a) / 0.12)));
    for (int k = 0; k < n; ++k) {
        const double s0 = t0 + (t1 - t0) * k / n, s1 = t0 + (t1 - t0) * (k + 0.5) / n;
        out.line(glm::vec3(a + s0 * (b - a)), glm::vec3(a + s1 * (b - a)), colour);
    }
}

}  // namespace

glm::mat4 roberts_camera(const algo::Scene& scene, float aspect) {
    algo::Camera c = scene.camera;
    c.aspect = aspect;
    return glm::mat4(algo::view_projection(c));
}

void draw_roberts_view(const RobertsView& v, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels) {
    const SceneColors colours(scene);
    const algo::LineDrawingInput& in = *v.input;
    const auto body_colour = [&](std::uint32_t body, float alpha) {
        return colours(scene.polygons[in.bodies[body].faces.front()].id, alpha);
    };
    // the body the current edge is tested against, outlined
    if (v.by >= 0)
        for (const algo::BodyEdge& e : in.edges)
            if (int(e.body) == v.by) out.bold.line(glm::vec3(e.a), glm::vec3(e.b), palette::outside);
    for (std::size_t i = 0; i < in.edges.size(); ++i) {
        const algo::BodyEdge& e = in.edges[i];
        const RobertsEdgeView& state = v.edges[i];
        const bool under_test = int(i) == v.edge && !state.finished;
        if (state.removed) {
            dashes(out.faint, e.a, e.b, 0, 1, glm::vec4(0.6f, 0.6f, 0.65f, 0.25f));
            continue;
        }
        if (!state.finished && !under_test) {  // not yet compared: faint
            out.faint.line(glm::vec3(e.a), glm::vec3(e.b), body_colour(e.body, 0.3f));
            continue;
        }
        // drawn where visible, dashed where hidden: the edge under test in yellow with its hidden parts so far dashed
        // bold (one mark for "hidden" everywhere; orange dashes beside the vermillion body read as that body)
        const glm::vec4 shown = int(i) == v.edge ? palette::current_edge : body_colour(e.body, 1);
        double at = 0;
        for (const auto& [t0, t1] : state.hidden) {
            if (t0 > at) out.bold.line(glm::vec3(e.a + at * (e.b - e.a)), glm::vec3(e.a + t0 * (e.b - e.a)), shown);
            if (under_test) dashes(out.bold, e.a, e.b, t0, t1, glm::vec4(0.85f, 0.85f, 0.9f, 0.9f));
            else dashes(out.faint, e.a, e.b, t0, t1, glm::vec4(0.75f, 0.75f, 0.8f, 0.45f));
            at = t1;
        }
        if (at < 1) out.bold.line(glm::vec3(e.a + at * (e.b - e.a)), glm::vec3(e.b), shown);
    }
    // the edge under test named as the narration names it, at its middle, and the next one to be tested (a question
    // asks about it before its turn), dimmer
    if (v.edge >= 0) {
        const algo::BodyEdge& e = in.edges[std::size_t(v.edge)];
        labels.push_back({glm::vec3((e.a + e.b) * 0.5), std::to_string(v.edge), palette::current_edge});
        for (std::size_t i = std::size_t(v.edge) + 1; i < in.edges.size(); ++i)
            if (!v.edges[i].removed && !v.edges[i].finished) {
                labels.push_back({glm::vec3((in.edges[i].a + in.edges[i].b) * 0.5), std::to_string(i), body_colour(in.edges[i].body, 0.9f)});
                break;
            }
    }
    // each body's number at its centre
    for (std::size_t b = 0; b < in.bodies.size(); ++b) {
        Vec3 c(0);
        int n = 0;
        for (const algo::BodyEdge& e : in.edges)
            if (e.body == b) c += e.a + e.b, n += 2;
        if (n) labels.push_back({glm::vec3(c / double(n)), "B" + std::to_string(b), int(b) == v.by ? palette::outside : body_colour(std::uint32_t(b), 0.9f)});
    }
}

}  // namespace hsr::viz
