// SPDX-License-Identifier: MIT
#include "render/horizon_renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "horizon/floating_horizon.h"
#include "state/horizon_colours.h"

namespace hsr::viz {

namespace {

// Terrain (x, height, z away from the eye) in the world of the 3D view, which looks down −z.
glm::vec3 world(double x, double height, double z) { return {float(x), float(height), float(-z)}; }

struct HeightRange {
    double lo = 0, hi = 0;
};
HeightRange heights(const algo::Terrain& t) {
    HeightRange r{t.heights.front(), t.heights.front()};
    for (const double h : t.heights) r.lo = std::min(r.lo, h), r.hi = std::max(r.hi, h);
    return r;
}

glm::vec4 row_colour(int row, int rows) {
    const algo::Color c = horizon_curve_colour(row, rows);
    return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1};
}

}  // namespace

std::optional<glm::mat4> horizon_terrain_camera(const HorizonView& v, float view_w, float view_h) {
    const algo::Terrain& t = *v.terrain;
    const HeightRange h = heights(t);
    const double depth = (t.rows - 1) * t.dz, size = std::max({t.width(), depth, 1e-9});
    if (h.hi - h.lo > 1e6 * size) return std::nullopt;
    const glm::vec3 centre = world(t.width() / 2, (h.lo + h.hi) / 2, depth / 2);
    const float radius = 0.5f * float(std::sqrt(t.width() * t.width() + depth * depth + (h.hi - h.lo) * (h.hi - h.lo)));
    // From the lesson's elevation (at least 15°, to see the ground), 35° to the side
    const float elevation = glm::radians(std::clamp(float(t.elevation), 15.0f, 75.0f)), yaw = glm::radians(35.0f);
    const glm::vec3 towards_eye(std::sin(yaw) * std::cos(elevation), std::sin(elevation), std::cos(yaw) * std::cos(elevation));
    const float share = 1 - horizon_canvas_share, aspect = share * view_w / view_h;
    // Far enough that the bounding sphere fits the narrower of the two angles of view
    const float fov = glm::radians(35.0f), half_across = std::atan(std::tan(fov / 2) * std::min(aspect, 1.0f));
    const float distance = radius / std::sin(half_across) * 1.05f;
    const glm::mat4 view = glm::lookAt(centre + towards_eye * distance, centre, glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(fov, aspect, distance * 0.05f, distance * 3);
    // Into the view's right part: x from −1 … 1 to (1 − 2·share) … 1
    const glm::mat4 into_right = glm::translate(glm::mat4(1), glm::vec3(1 - share, 0, 0)) * glm::scale(glm::mat4(1), glm::vec3(share, 1, 1));
    return into_right * projection * view;
}

void draw_horizon_terrain(const HorizonView& v, LineBatches& b, std::vector<Label>& labels, const std::string& nearest,
                          const std::string& farthest) {
    const algo::Terrain& t = *v.terrain;
    labels.push_back({world(0, t.height(0, 0), 0), nearest, row_colour(0, t.rows)});
    if (t.rows > 1) labels.push_back({world(0, t.height(0, t.rows - 1), (t.rows - 1) * t.dz), farthest, row_colour(t.rows - 1, t.rows)});
    const glm::vec4 grid(0.55f, 0.57f, 0.62f, 0.35f), hidden(0.55f, 0.57f, 0.62f, 0.55f);
    // The terrain's samples as a wire grid: along z faintly; the curves still to come a little less faintly
    for (int i = 0; i < t.columns; ++i)
        for (int j = 0; j + 1 < t.rows; ++j) b.faint.line(world(i * t.dx, t.height(i, j), j * t.dz), world(i * t.dx, t.height(i, j + 1), (j + 1) * t.dz), grid);
    for (int j = 0; j < t.rows; ++j) {
        const bool reached = v.tested[v.at(j, 0)] != 0;
        if (!reached)
            for (int i = 0; i + 1 < t.columns; ++i)
                b.faint.line(world(i * t.dx, t.height(i, j), j * t.dz), world((i + 1) * t.dx, t.height(i + 1, j), j * t.dz), grid * 1.6f);
    }
    // The curves tested so far, at the screen's columns: bold in their colour where shown, faint where hidden
    for (int j = 0; j < t.rows; ++j)
        for (int c = 0; c + 1 < v.columns; ++c) {
            const std::size_t a = v.at(j, c), n = v.at(j, c + 1);
            if (!v.tested[a] || !v.tested[n]) continue;
            const double xa = algo::column_x(t, v.columns, c), xn = algo::column_x(t, v.columns, c + 1);
            const glm::vec3 p = world(xa, algo::curve_height(t, j, xa), j * t.dz), q = world(xn, algo::curve_height(t, j, xn), j * t.dz);
            if (v.sight[a] != algo::Sight::hidden && v.sight[n] != algo::Sight::hidden) b.bold.line(p, q, row_colour(j, t.rows));
            else b.faint.line(p, q, hidden);
        }
    // The section under the column being tested: the plane x = const the ray walk lives in, and the point
    if (v.last) {
        const algo::PointTested& e = *v.last;
        const glm::vec4 section(1, 1, 1, 0.5f);
        for (int j = 0; j + 1 < t.rows; ++j)
            b.faint.line(world(e.x, algo::curve_height(t, j, e.x), j * t.dz), world(e.x, algo::curve_height(t, j + 1, e.x), (j + 1) * t.dz), section);
        const bool shown = e.sight != algo::Sight::hidden;
        b.bold.point(world(e.x, e.height, e.row * t.dz), shown ? glm::vec4(0.35f, 0.86f, 0.5f, 1) : glm::vec4(0.94f, 0.31f, 0.24f, 1));
    }
}

}  // namespace hsr::viz
