// SPDX-License-Identifier: MIT
#include "analysis/exact_horizon.h"

#include <algorithm>
#include <cmath>

#include <gmpxx.h>

#include "horizon/floating_horizon.h"

namespace hsr::analysis {

namespace {

// Under one screen column the world is the plane x = const. There the ray from a point (z_p, h_p) of the section
// towards the eye runs to smaller z and larger h, along (−cos e, sin e) in (z, h): the view's direction reversed. A
// point (z, h) lies on the ray's line when h·cos + z·sin = h_p·cos + z_p·sin, on its upper side when that is more.
// Along the piece of the section from row k to row k + 1 this signed height is linear, so the ray meets the piece
// where it changes sign or is zero; the pieces in front of the point are those of rows nearer than its own.
template <class Number>
struct Walk {
    Number cos_e, sin_e;
    // The section's height over the ray's line at row k (the line's own height subtracted).
    Number over(const Number& height, const Number& z, const Number& line) const { return height * cos_e + z * sin_e - line; }
};

template <class Number>
HorizonReference walk_all(const algo::Terrain& t, int columns, auto to_double) {
    const algo::HorizonProjection view(t.elevation);
    const Walk<Number> walk{Number(view.cos_e), Number(view.sin_e)};
    HorizonReference out{.columns = columns, .rows = t.rows};
    out.visible.resize(std::size_t(columns) * std::size_t(t.rows));
    out.margin.resize(out.visible.size());
    std::vector<Number> section(std::size_t(t.rows)), zs(std::size_t(t.rows));
    for (int c = 0; c < columns; ++c) {
        const double x = algo::column_x(t, columns, c);
        for (int k = 0; k < t.rows; ++k) section[std::size_t(k)] = Number(algo::curve_height(t, k, x)), zs[std::size_t(k)] = Number(double(k * t.dz));
        for (int j = 0; j < t.rows; ++j) {
            const Number line = walk.over(section[std::size_t(j)], zs[std::size_t(j)], Number(0));
            // March from the point's row towards the eye, piece by piece
            bool hit = false;
            Number highest = 0, lowest = 0;  // of the signed heights at the rows in front
            for (int k = j - 1; k >= 0; --k) {
                const Number a = walk.over(section[std::size_t(k)], zs[std::size_t(k)], line);          // the piece's near end
                const Number b = walk.over(section[std::size_t(k + 1)], zs[std::size_t(k + 1)], line);  // its far end
                // the far end of the piece next to the point is the point itself (b = 0): only its near end can touch
                const bool meets = k + 1 == j ? a == 0 : (a <= 0 && b >= 0) || (a >= 0 && b <= 0);
                hit = hit || meets;
                if (k == j - 1 || a > highest) highest = a;
                if (k == j - 1 || a < lowest) lowest = a;
            }
            // How far from the other answer: a visible point's distance to the nearest row in front on its side;
            // a hidden one's to the nearer end of the range the rows in front span
            const std::size_t at = std::size_t(j) * std::size_t(columns) + std::size_t(c);
            out.visible[at] = !hit;
            if (j == 0) out.margin[at] = INFINITY;
            else if (!hit) out.margin[at] = lowest > 0 ? to_double(lowest) : to_double(Number(-highest));
            else out.margin[at] = std::min(to_double(highest), to_double(Number(-lowest)));
        }
    }
    return out;
}

}  // namespace

HorizonReference exact_horizon(const algo::Terrain& terrain, int columns) {
    return walk_all<mpq_class>(terrain, columns, [](const mpq_class& q) { return q.get_d(); });
}

HorizonReference sampled_horizon(const algo::Terrain& terrain, int columns) {
    return walk_all<double>(terrain, columns, [](double v) { return v; });
}

}  // namespace hsr::analysis
