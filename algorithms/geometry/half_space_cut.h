// SPDX-License-Identifier: MIT
// One stage of Sutherland–Hodgman: the part of a convex polygon on one side of a line (2D) or a plane (3D).
//
//   for each edge p → q of the polygon:
//       if p is inside: keep p
//       if the edge crosses the boundary: keep the crossing p + (q − p)·v(p) / (v(p) − v(q))
//
// "Inside" is value(p) ≥ 0, where value is the signed distance to the boundary at any scale (a plane's n·p + d, a
// line's cross product, a tolerance added for a conservative test). The clipping machines (clipping/) are the
// stepped form of the same loop, against the six or seven planes of the view volume; this is the plain one the
// other families cut with.
#pragma once

#include <cstddef>
#include <vector>

namespace hsr::algo {

// When an edge gets a crossing point.
enum class Crossing {
    strict,       // only when one end is strictly inside and the other strictly outside: a vertex on the boundary
                  // is kept once and is itself the cut
    sign_change,  // the textbook's test, one end inside (≥ 0) and the other not: an edge leaving from a vertex on
                  // the boundary adds that point again, and one arriving at it adds a point next to it; a conservative
                  // test keeps such slivers rather than judge them
};

template <class Point>
struct CutOptions {
    Crossing crossing = Crossing::strict;
    std::vector<Point>* on_boundary = nullptr;  // if set, receives the crossings made and the vertices lying on the
                                                // boundary (value exactly 0), in order: the cap the cut leaves
};

// The part of `polygon` where value(p) ≥ 0, in the polygon's order. It may have fewer than 3 points (nothing left,
// or only a vertex or an edge on the boundary); the caller decides what that means.
template <class Point, class Value>
std::vector<Point> cut_polygon(const std::vector<Point>& polygon, Value value, CutOptions<Point> options = {}) {
    std::vector<Point> kept;
    const std::size_t n = polygon.size();
    if (n == 0) return kept;
    double vq = value(polygon[0]);
    for (std::size_t i = 0; i < n; ++i) {
        const Point& p = polygon[i];
        const Point& q = polygon[(i + 1) % n];
        const double vp = vq;
        vq = value(q);
        if (vp >= 0) kept.push_back(p);
        const bool crosses = options.crossing == Crossing::strict ? (vp < 0 && vq > 0) || (vp > 0 && vq < 0)
                                                                  : (vp >= 0) != (vq >= 0);
        if (crosses) {
            const Point x = p + (q - p) * (vp / (vp - vq));
            kept.push_back(x);
            if (options.on_boundary) options.on_boundary->push_back(x);
        } else if (vp == 0 && options.on_boundary) {
            options.on_boundary->push_back(p);
        }
    }
    return kept;
}

}  // namespace hsr::algo
