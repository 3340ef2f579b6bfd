// SPDX-License-Identifier: MIT
#include "render/backface_renderer.h"

#include <cstdio>

#include <glm/geometric.hpp>

#include "render/palette.h"
#include "state/state_colours.h"
#include "state/strings.h"

namespace hsr::viz {

using algo::Vec3;

glm::vec4 opaque(const StateColour& c) { return {c.r, c.g, c.b, 1}; }

void draw_backface_view(const BackfaceView& v, glm::vec3 camera_eye, LineBatches& out, std::vector<Label>& labels) {
    // the faces are coloured by their verdict alone (the scene's own colours would clash with the legend's)
    const glm::vec4 untested_outline{0.72f, 0.74f, 0.78f, 1};
    for (std::size_t i = 0; i < v.faces.size(); ++i) {
        const FaceView& f = v.faces[i];
        const std::vector<Vec3>& vs = *f.vertices;
        const bool current = int(i) == v.current;
        const bool kept = f.facing == algo::Facing::front;
        const glm::vec4 fill = !f.facing ? glm::vec4(0.55f, 0.58f, 0.64f, 0.18f)
                               : kept    ? glm::vec4(opaque(backface_colours::kept).x, opaque(backface_colours::kept).y, opaque(backface_colours::kept).z, 0.75f)
                                         : glm::vec4(0.12f, 0.12f, 0.14f, 0.45f);
        for (std::size_t k = 1; k + 1 < vs.size(); ++k)
            out.faint.triangle(glm::vec3(vs[0]), glm::vec3(vs[k]), glm::vec3(vs[k + 1]), fill);
        // against the ray cast: a culled face the eye sees is drawn in its own colour, bold
        const bool culled_but_seen = f.facing && !kept && f.seen && *f.seen > 0;
        const glm::vec4 edge = current             ? opaque(backface_colours::under_test)
                               : culled_but_seen   ? opaque(backface_colours::culled_seen)
                               : f.facing && !kept ? opaque(backface_colours::culled)
                                                   : untested_outline;
        for (std::size_t k = 0; k < vs.size(); ++k)
            (current || culled_but_seen ? out.bold : out.faint).line(glm::vec3(vs[k]), glm::vec3(vs[(k + 1) % vs.size()]), edge);
        // every face numbered as the table and the questions name it, just off its outer side; dim when this view
        // (the window's camera, not the eye under test) sees it from behind. Not in brackets: a class read brackets
        // as "culled", which only the eye's test decides
        const Vec3 c = algo::centroid(vs);
        const bool from_behind = glm::dot(camera_eye - glm::vec3(c), glm::vec3(f.plane.n)) < 0;
        const std::string number = std::to_string(f.id);
        const float alpha = from_behind ? 0.5f : f.facing && !kept ? 0.7f : 1.0f;
        labels.push_back({glm::vec3(c + f.plane.n * 0.04), number,
                          current ? palette::current_edge : glm::vec4(0.85f, 0.86f, 0.9f, alpha)});
        if (!current) continue;
        // the test's vectors: the outward normal at the centroid, and the view vector from the eye to vertex 0
        const double size = glm::length(vs[0] - c) + 0.2;
        out.bold.line(glm::vec3(c), glm::vec3(c + f.plane.n * size), palette::parameter);
        labels.push_back({glm::vec3(c + f.plane.n * size), "n", palette::parameter});
        if (v.test != algo::BackfaceTest::screen_winding) {
            out.faint.line(glm::vec3(v.eye), glm::vec3(vs[0]), palette::working);
            out.bold.point(glm::vec3(vs[0]), palette::working);
            char buf[64];
            std::snprintf(buf, sizeof buf, "%s = %.3g", v.test == algo::BackfaceTest::view_vector ? "v·n" : "N·eye+D",
                          f.value);
            labels.push_back({glm::vec3(vs[0]), buf, palette::working});
        }
    }
    out.bold.point(glm::vec3(v.eye), palette::eye);
    labels.push_back({glm::vec3(v.eye), tr("view.eye"), palette::eye});
}

}  // namespace hsr::viz
