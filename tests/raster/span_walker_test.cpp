// SPDX-License-Identifier: MIT
// The span walker steps span_on_row's divisions by additions: its spans must be span_on_row's, row for row.
#include "catch.h"

#include <cmath>
#include <random>

#include "raster/span_walker.h"

using namespace hsr::algo;

namespace {

// Every row from `first` on (before, inside and after the polygon's rows), walked, against span_on_row.
// Returns how many of those rows were not empty.
int require_same_spans(const ScreenPolygon& p, Viewport vp, int first, int last) {
    SpanWalker walk(p, first, vp);
    int filled = 0;
    for (int row = first; row < last; ++row, walk.next_row()) {
        const Span expected = span_on_row(p, row, vp), got = walk.span();
        INFO("row " << row << " of rows [" << p.row_begin << ", " << p.row_end << "), " << p.vertices.size() << " vertices");
        REQUIRE(walk.row() == row);
        REQUIRE(got.begin == expected.begin);
        REQUIRE(got.end == expected.end);
        filled += got.end > got.begin;
    }
    return filled;
}

// A polygon given straight in sub-pixels (no projection), clockwise and with rows as project_polygon makes them.
ScreenPolygon in_subpixels(std::vector<ScreenVertex> v, Viewport vp) {
    std::int64_t twice_area = 0;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) twice_area += v[j].x * v[i].y - v[i].x * v[j].y;
    if (twice_area < 0) std::reverse(v.begin(), v.end());
    ScreenPolygon p{.id = 1, .vertices = std::move(v)};
    std::int64_t y0 = p.vertices[0].y, y1 = y0;
    for (const auto& q : p.vertices) y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    p.row_begin = int(std::clamp<std::int64_t>((y0 - 128 + 255) / 256, 0, vp.height));
    p.row_end = int(std::clamp<std::int64_t>((y1 - 128) / 256 + 1, 0, vp.height));
    return p;
}

}  // namespace

TEST_CASE("The span walker gives span_on_row's spans on random projected polygons, clipped ones included") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(-1.6, 1.6), depth(-0.9, 0.9), w(-0.2, 2);
    std::uniform_int_distribution<int> sides(3, 8);
    int walked = 0;
    for (const Viewport vp : {Viewport{64, 48}, Viewport{1024, 1024}, Viewport{7, 300}}) {
        for (int n = 0; n < 400; ++n) {
            // a convex polygon: points on an ellipse in clip space, some behind the eye (clipped at w = ε)
            const int k = sides(rng);
            const double cx = coord(rng), cy = coord(rng), rx = std::abs(coord(rng)), ry = std::abs(coord(rng)), ww = w(rng);
            std::vector<glm::dvec4> clip;
            for (int i = 0; i < k; ++i) {
                const double a = 2 * M_PI * i / k;
                clip.push_back({cx + rx * std::cos(a), cy + ry * std::sin(a), depth(rng), ww + 0.3 * std::cos(a)});
            }
            const ScreenPolygon p = project_polygon(1, {}, clip, vp);
            if (p.status != ScreenStatus::drawn) continue;
            ++walked;
            require_same_spans(p, vp, p.row_begin - 2, p.row_end + 2);
            require_same_spans(p, vp, (p.row_begin + p.row_end) / 2, p.row_end);  // started midway, as a band does
        }
    }
    CHECK(walked > 600);
}

TEST_CASE("The span walker agrees where edges pass exactly through pixel centres (the fill rule's ties)") {
    // vertices on a grid of half pixels: many edges run through pixel centres, and the remainders land exactly on
    // the divisor, where the carry decides the tie
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::int64_t> half_pixel(0, 40);
    const Viewport vp{24, 24};
    int filled = 0;
    for (int n = 0; n < 3000; ++n) {
        std::vector<ScreenVertex> v;
        for (int i = 0; i < 3; ++i) v.push_back({128 * half_pixel(rng), 128 * half_pixel(rng), 0});
        std::int64_t twice_area = 0;
        for (std::size_t i = 0, j = 2; i < 3; j = i++) twice_area += v[j].x * v[i].y - v[i].x * v[j].y;
        if (twice_area == 0) continue;
        filled += require_same_spans(in_subpixels(v, vp), vp, 0, 24);
    }
    CHECK(filled > 10000);
}

TEST_CASE("The span walker agrees on horizontal edges, huge coordinates, tiny slopes and many vertices") {
    const Viewport vp{200, 120};
    // horizontal top and bottom edges (the rule takes their pixels for the polygon above) on pixel centres
    CHECK(require_same_spans(in_subpixels({{256 * 10 + 128, 256 * 5 + 128, 0}, {256 * 90 + 128, 256 * 5 + 128, 0},
                                     {256 * 90 + 128, 256 * 50 + 128, 0}, {256 * 10 + 128, 256 * 50 + 128, 0}}, vp),
                             vp, 0, 120) == 45);  // rows 6…50: row 5's centres are on the top edge
    // far outside the viewport on both sides: bounds beyond the clamp of span_on_row
    CHECK(require_same_spans(in_subpixels({{-(std::int64_t(1) << 40), 100, 0}, {std::int64_t(1) << 40, 2000, 0}, {0, 256 * 119, 0}}, vp), vp, 0, 120) > 100);
    // a slope of one sub-pixel in 2^30 rows, and its mirror
    CHECK(require_same_spans(in_subpixels({{300, 0, 0}, {301, 256 * 120, 0}, {256 * 150, 256 * 100, 0}}, vp), vp, 0, 120) > 90);
    CHECK(require_same_spans(in_subpixels({{256 * 150, 0, 0}, {256 * 150 - 1, 256 * 120, 0}, {300, 256 * 60, 0}}, vp), vp, 0, 120) > 90);
    // a zero-length edge (which no projection makes) empties every row in span_on_row: so in the walker
    CHECK(require_same_spans(in_subpixels({{1000, 1000, 0}, {1000, 1000, 0}, {9000, 9000, 0}, {1000, 9000, 0}}, vp), vp, 0, 120) == 0);
    // more vertices than the walker keeps: it asks span_on_row row by row
    std::vector<ScreenVertex> circle;
    for (int i = 0; i < 40; ++i)
        circle.push_back({std::int64_t(256 * (100 + 80 * std::cos(-2 * M_PI * i / 40))), std::int64_t(256 * (60 + 50 * std::sin(-2 * M_PI * i / 40))), 0});
    CHECK(require_same_spans(in_subpixels(circle, vp), vp, 0, 120) == 100);
}
