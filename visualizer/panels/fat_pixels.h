// SPDX-License-Identifier: MIT
// Drawing a classroom-sized image as a grid of fat pixels (z-buffer and scan-line lessons), with polygon outlines
// in the same pixel coordinates.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <imgui.h>

#include "raster/image.h"
#include "panels/name_placement.h"
#include "panels/panel_style.h"
#include "raster/screen_polygon.h"

namespace hsr::viz {

// Where a canvas draws a grid of fat pixels: its top-left corner and the size of one pixel, in window points (so
// that the window's mouse can be read in pixels of the grid).
struct FatGrid {
    float x0, y0, cell;
};

inline ImU32 rgb(algo::Color c, float alpha = 1) {
    return ImGui::GetColorU32(ImVec4(c.r / 255.f, c.g / 255.f, c.b / 255.f, alpha));
}

// Text that reads on colour c laid with `alpha` over the dark canvas: near-black on a light fill (a yellow chip),
// near-white on a dark one (relative luminance, WCAG's weights, of what the eye sees).
inline ImU32 text_on(algo::Color c, float alpha = 1) {
    const float background = 0.1f;  // the canvases' background, about (26, 28, 33)
    const auto seen = [&](std::uint8_t v) { return background * (1 - alpha) + v / 255.f * alpha; };
    const float luminance = 0.2126f * seen(c.r) + 0.7152f * seen(c.g) + 0.0722f * seen(c.b);
    return luminance > 0.5f ? IM_COL32(20, 20, 24, 255) : IM_COL32(235, 235, 235, 255);
}

// One buffer as width × height cells of `cell` points from `origin`; `fill(x, y)` gives each pixel's colour.
template <class Fill>
void pixel_grid(ImDrawList* d, ImVec2 origin, float cell, algo::Viewport vp, Fill fill) {
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x)
            d->AddRectFilled(ImVec2(origin.x + float(x) * cell, origin.y + float(y) * cell),
                             ImVec2(origin.x + float(x + 1) * cell - 1, origin.y + float(y + 1) * cell - 1), fill(x, y));
}

// The pixels' numbers along a grid, x under it and y left of it, in small dim type: the questions and the narration
// name pixels by them ("pixel (15, 13)"). Every pixel's when the cells are wide enough for two digits, else every
// 2nd, 5th or 10th. They take the line under the grid and the canvas's margin left of it.
// The room grid_numbers takes left of a grid: its widest row number and the gap before the grid.
inline float grid_number_room(algo::Viewport vp) {
    return ImGui::GetFont()->CalcTextSizeA(axis_number_size(), 1e9f, 0, std::to_string(std::max(vp.height - 1, 0)).c_str()).x + 3;
}

inline void grid_numbers(ImDrawList* d, ImVec2 origin, float cell, algo::Viewport vp) {
    ImFont* font = ImGui::GetFont();
    const float size = axis_number_size();
    const ImU32 dim = IM_COL32(170, 170, 170, 255);
    const auto width = [&](const std::string& t) { return font->CalcTextSizeA(size, 1e9f, 0, t.c_str()).x; };
    const int step = axis_number_step(cell);
    const float bottom = origin.y + cell * float(vp.height) + 1;
    for (int x = 0; x < vp.width; x += step) {
        const std::string t = std::to_string(x);
        d->AddText(font, size, ImVec2(origin.x + (float(x) + 0.5f) * cell - width(t) / 2, bottom), dim, t.c_str());
    }
    for (int y = 0; y < vp.height; y += step) {
        const std::string t = std::to_string(y);
        d->AddText(font, size, ImVec2(origin.x - 3 - width(t), origin.y + (float(y) + 0.5f) * cell - size / 2), dim, t.c_str());
    }
}

inline ImVec2 on_grid(ImVec2 origin, float cell, const algo::ScreenVertex& v) {
    return {origin.x + float(v.x) / float(algo::subpixels) * cell, origin.y + float(v.y) / float(algo::subpixels) * cell};
}

inline void outline(ImDrawList* d, ImVec2 origin, float cell, const algo::ScreenPolygon& p, ImU32 colour, float thickness) {
    if (p.status != algo::ScreenStatus::drawn) return;
    std::vector<ImVec2> points;
    for (const auto& q : p.vertices) points.push_back(on_grid(origin, cell, q));
    d->AddPolyline(points.data(), int(points.size()), colour, ImDrawFlags_Closed, thickness);
}

// A polygon's name on a dark backing inside it, in the polygon's colour: the name the tables, the narration and the
// questions use, found in the picture. At the middle of its outline, or, where an earlier name sits there (two
// crossing triangles share a middle), part way towards one of its corners, or beside it on the grid. `taken`: the
// names placed so far, and what else they keep off.
inline void polygon_name(ImDrawList* d, ImVec2 origin, float cell, algo::Viewport viewport, const algo::ScreenPolygon& p,
                         const std::string& text, std::vector<ImVec4>& taken) {
    if (p.status != algo::ScreenStatus::drawn || p.vertices.empty()) return;
    std::vector<ImVec2> corners;
    for (const auto& q : p.vertices) corners.push_back(on_grid(origin, cell, q));
    const ImVec4 grid(origin.x, origin.y, origin.x + cell * float(viewport.width), origin.y + cell * float(viewport.height));
    const ImVec4 b = place_name(corners, ImGui::CalcTextSize(text.c_str()), 3, {0.4f, 0.6f}, true, taken, &grid);
    // a light backing, so that the pixels under a name still show their colour (a fill-rule lesson is about single
    // pixels); white words, never the colour of the pixels under them, and the polygon's colour in a bar beside them
    d->AddRectFilled(ImVec2(b.x - 4, b.y), ImVec2(b.z, b.w), IM_COL32(20, 22, 26, 165), 3);
    d->AddRectFilled(ImVec2(b.x - 4, b.y + 1), ImVec2(b.x - 1, b.w - 1), rgb(p.color));
    d->AddText(ImVec2(b.x + 3, b.y + 1), IM_COL32(245, 245, 245, 255), text.c_str());
}

// The pixels along each edge the polygon being filled shares with another (the same line, overlapping): where a fill-rule lesson looks (which polygon writes a pixel whose centre is on the edge), so the
// polygons' names keep off them.
inline std::vector<ImVec4> shared_edge_strips(const std::vector<algo::ScreenPolygon>& polygons, int filled, ImVec2 origin, float cell) {
    using V = algo::ScreenVertex;
    const auto turn = [](const V& a, const V& b, const V& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); };
    std::vector<ImVec4> strips;
    if (filled < 0 || filled >= int(polygons.size())) return strips;
    const auto& p = polygons[std::size_t(filled)].vertices;
    for (std::size_t j = 0; j < polygons.size(); ++j) {
        const auto& q = polygons[j].vertices;
        if (int(j) == filled || polygons[j].status != algo::ScreenStatus::drawn) continue;
        for (std::size_t e = 0; e < p.size(); ++e)
            for (std::size_t f = 0; f < q.size(); ++f) {
                const V &a = p[e], &b = p[(e + 1) % p.size()], &c = q[f], &d = q[(f + 1) % q.size()];
                if (a == b || turn(a, b, c) != 0 || turn(a, b, d) != 0) continue;  // not on one line (exact: integers)
                // the overlap, along the edge's longer axis
                const bool along_x = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
                const auto key = [&](const V& v) { return along_x ? v.x : v.y; };
                const auto [p0, p1] = std::minmax({a, b}, [&](const V& u, const V& v) { return key(u) < key(v); });
                const auto [q0, q1] = std::minmax({c, d}, [&](const V& u, const V& v) { return key(u) < key(v); });
                const V& from = key(p0) > key(q0) ? p0 : q0;
                const V& to = key(p1) < key(q1) ? p1 : q1;
                if (key(from) >= key(to)) continue;  // they touch at a point, or not at all
                // each pixel the shared part runs through (sampled at half a pixel)
                const ImVec2 s = on_grid(origin, cell, from), t = on_grid(origin, cell, to);
                const int samples = 2 * int(std::max(std::abs(t.x - s.x), std::abs(t.y - s.y)) / cell) + 1;
                for (int k = 0; k <= samples; ++k) {
                    const float u = float(k) / float(samples);
                    const float px = std::floor((s.x + (t.x - s.x) * u - origin.x) / cell), py = std::floor((s.y + (t.y - s.y) * u - origin.y) / cell);
                    strips.push_back(ImVec4(origin.x + px * cell, origin.y + py * cell, origin.x + (px + 1) * cell, origin.y + (py + 1) * cell));
                }
            }
    }
    return strips;
}

// An image (painted so far, say) stretched over the box from `o` of `size` points, with a frame: runs of one colour
// along a row as one rectangle each, so a 96 × 96 image costs a few hundred rectangles, not nine thousand.
inline void draw_image(ImDrawList* d, const algo::Image& image, ImVec2 o, ImVec2 size) {
    const float cw = size.x / float(std::max(image.width, 1)), ch = size.y / float(std::max(image.height, 1));
    for (int y = 0; y < image.height; ++y)
        for (int x0 = 0; x0 < image.width;) {
            const auto px = [&](int x) { return &image.rgb[3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x))]; };
            int x1 = x0 + 1;
            while (x1 < image.width && std::equal(px(x1), px(x1) + 3, px(x0))) ++x1;
            d->AddRectFilled(ImVec2(o.x + float(x0) * cw, o.y + float(y) * ch), ImVec2(o.x + float(x1) * cw, o.y + float(y + 1) * ch),
                             IM_COL32(px(x0)[0], px(x0)[1], px(x0)[2], 255));
            x0 = x1;
        }
    d->AddRect(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(110, 114, 122, 255));
}

}  // namespace hsr::viz
