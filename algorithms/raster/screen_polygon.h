// SPDX-License-Identifier: MIT
// The rasterisers' common ground (z-buffer fill and scan-line): polygons on the screen, with the fill rule.
//
// Screen space: x to the right, y down, in pixels; pixel (i, j) is sampled at its centre (i + ½, j + ½).
// Vertices are snapped to 1/256 of a pixel (8 sub-pixel bits, as GL rasterisers do) so that coverage is decided
// by exact integer arithmetic: two polygons sharing an edge see the same edge, bit for bit.
//
// Fill rule: OpenGL's top-left rule. Vertices are put in clockwise order on the screen (y down), so that the
// inside of every edge a→b is where E(p) = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x) > 0. A pixel centre
// exactly on an edge (E = 0) belongs to the polygon only if the edge is a *left* edge (going up: b.y < a.y) or a
// horizontal edge with the inside *above* it (b.y = a.y, b.x < a.x). Rasterisers apply "top-left" in the order
// their framebuffer rows are stored, and OpenGL's rows run bottom to top, so in our top-down image the rule that
// matches OpenGL (checked against Mesa in tests/gui/gl_raster_check) takes the pixels on a horizontal edge for the
// polygon above it. A shared edge is walked in opposite directions by its two polygons, so exactly one of them owns
// the pixels on it.
//
// Depth. After the divide by w the window depth d ∈ [0, 1] is an affine function of the screen position, so every
// polygon has a depth plane d = c0 + (−a/c)·x + (−b/c)·y (the lecture's F′(x, y)), and stepping one pixel along x
// adds the constant forward difference −a/c.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace hsr::algo {

inline constexpr std::int64_t subpixels = 256;  // per pixel, along x and along y

struct DepthPlane {
    double c0 = 0;   // d at the screen origin
    double per_x = 0;  // −a/c: change of d per pixel to the right
    double per_y = 0;  // −b/c: change of d per pixel down
    double at(double x, double y) const { return c0 + per_x * x + per_y * y; }
    bool operator==(const DepthPlane&) const = default;
};

struct ScreenVertex {
    std::int64_t x, y;  // pixels × 256 (sub-pixel fixed point)
    double depth;       // window depth d ∈ [0, 1]
    bool operator==(const ScreenVertex&) const = default;
};

enum class ScreenStatus : std::uint8_t { drawn, outside_view, zero_area };

struct ScreenPolygon {
    SceneId id = 0;
    Color color;
    ScreenStatus status = ScreenStatus::drawn;
    std::vector<ScreenVertex> vertices;  // clockwise on screen, after clipping to the view volume
    DepthPlane plane;
    int row_begin = 0, row_end = 0;      // the rows whose centres it may cover: [row_begin, row_end)
};

// Viewport of the rasterisers: width × height pixels.
struct Viewport {
    int width = 64, height = 48;
};

// The scene's polygons (world space, convex) clipped in homogeneous clip space (near plane first: never discarded
// whole because a vertex is behind the eye), divided by w, mapped to the viewport and snapped.
// InvalidInput names a polygon that is not convex or has NaN coordinates.
std::vector<ScreenPolygon> project_polygons(const Scene& scene, Viewport viewport);

// Throws InvalidInput naming the polygon unless it is convex (world space; a polygon with no area passes).
void require_convex(const ScenePolygon& p);
void require_convex(std::span<const glm::dvec3> polygon, SceneId id);
// Every polygon of a world scene that the hidden-surface algorithms refuse (not convex, or crossing itself), as
// "FILE:LINE: polygon N is not convex; …": what `check` warns of and `render` refuses before it starts.
std::vector<std::string> polygons_not_convex(const Scene& scene);

// One polygon given in clip space (x, y, z, w), as above.
ScreenPolygon project_polygon(SceneId id, Color color, std::span<const glm::dvec4> clip_vertices, Viewport viewport);
ScreenPolygon project_polygon(SceneId id, Color color, const std::vector<glm::dvec4>& clip_vertices, Viewport viewport);

// Many polygons given in clip space, each as project_polygon, on every core; the answers in their order.
// InvalidInput names the first polygon (in that order) refused.
struct ClipSpacePolygon {
    SceneId id = 0;
    Color color;
    std::vector<glm::dvec4> vertices;
};
std::vector<ScreenPolygon> project_polygons(std::span<const ClipSpacePolygon> polygons, Viewport viewport);

// The pixels [begin, end) of row j whose centres the polygon covers under the top-left rule (the intersection of
// every edge's half-plane), clamped to the viewport. Empty when end ≤ begin.
struct Span {
    int begin = 0, end = 0;
};
Span span_on_row(const ScreenPolygon& p, int row, Viewport viewport);

// The same bound for one edge a→b alone: the first pixel of row j whose centre is inside (a left edge, going up),
// or one past the last (a right edge, going down). Horizontal edges bound no pixel and are not asked.
int edge_bound_on_row(const ScreenVertex& a, const ScreenVertex& b, int row);

// Where the edge a→b crosses the centre line of row j, in pixels (for narration and the edge table's x).
double edge_x_at_row(const ScreenVertex& a, const ScreenVertex& b, int row);

// Pixel centres, in pixels.
inline double pixel_centre(int i) { return i + 0.5; }

// The centre line of row j, in sub-pixels.
inline std::int64_t row_centre(int row) { return std::int64_t(row) * subpixels + subpixels / 2; }

// The fill rule as a threshold on the edge function E of edge (dx, dy): a pixel centre is inside when E ≥ it, so on
// the edge (E = 0) counts only for left edges and bottom edges (going −x).
inline std::int64_t fill_rule_threshold(std::int64_t dx, std::int64_t dy) { return (dy < 0 || (dy == 0 && dx < 0)) ? 0 : 1; }

}  // namespace hsr::algo
