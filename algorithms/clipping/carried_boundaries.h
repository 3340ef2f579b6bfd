// SPDX-License-Identifier: MIT
// Clipped points that remember which side of every plane they are on.
//
// Cohen–Sutherland and Sutherland–Hodgman clip what an earlier cut left. Testing the next plane on an already
// rounded point re-clips rounding: a segment running within an ulp of x = −w, cut first at z = w, gets its new end
// rounded exactly onto x = −w, and the cut at x = −w then finds t = 0 and keeps a single point where a tenth of the
// segment is visible (a polygon's edge the same). A point made by a cut therefore carries its boundary values,
// interpolated from those of the two points it was cut between, as a GPU interpolates clip distances: the inside
// tests and the next cut read them, and the rounded coordinates only say where the point is drawn. Every boundary
// value then stays within a few roundings of the exact point's, however many planes cut before.
//
// The machines and the straight-line clippers (straight_clip.h) share these helpers, so both give the same answers
// bit for bit.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec4.hpp>

namespace hsr::algo {

// The boundary value at parameter t between two points whose values are b1 and b2: from the nearer end, so that
// t = 0 and t = 1 give b1 and b2 exactly (1 − t is exact for t ≥ ½).
template <class T>
T boundary_at(T b1, T b2, T t) {
    return t <= T(0.5) ? b1 + t * (b2 - b1) : b2 + (1 - t) * (b1 - b2);
}

// Where a plane cuts the input segment (boundary values b1, b2 at its ends), kept between the current ends t1 < t2.
// Exactly, the cut lies between them; a t beyond them (or b1 == b2, which gives ±inf or NaN) means rounding alone
// put the current end outside the plane, and that end is where the cut is.
template <class T>
T cut_parameter(T b1, T b2, T t1, T t2, bool p1_outside) {
    const T t = b1 / (b1 - b2);
    if (std::isnan(t)) return p1_outside ? t1 : t2;
    return std::clamp(t, t1, t2);
}

// A vertex of a Sutherland–Hodgman stage: where it is drawn, and its boundary value for each of the 7 planes (in
// clipping's order, ClipPlane), exact for an input vertex and interpolated for a cut one.
template <class T>
struct CarriedVertex {
    glm::vec<4, T> p;
    std::array<T, 7> b;
};

// The vertex where plane r cuts the edge in → out (in.b[r] ≥ 0 > out.b[r]), computed from the inside end, so that an
// edge two polygons share, walked in opposite directions, gives bit-identical points. `intersect(from, to, t)` is
// intersect_plane_line for r: it snaps the point onto r, where its carried value is 0.
template <class T, class Intersect>
CarriedVertex<T> cut_edge(int r, const CarriedVertex<T>& in, const CarriedVertex<T>& out, Intersect&& intersect) {
    const T t = in.b[std::size_t(r)] / (in.b[std::size_t(r)] - out.b[std::size_t(r)]);
    CarriedVertex<T> x{intersect(in.p, out.p, t), {}};
    for (std::size_t k = 0; k < x.b.size(); ++k) x.b[k] = boundary_at(in.b[k], out.b[k], t);
    x.b[std::size_t(r)] = 0;
    return x;
}

}  // namespace hsr::algo
