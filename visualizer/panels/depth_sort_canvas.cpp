// SPDX-License-Identifier: MIT
// Over the 3D view of a depth-sort lesson: the display list as a row of chips that slide when a polygon moves to
// the head or is cut into parts, the screen (x, y) with the projections of R and Q and their extents, and the
// image painted so far, translucent polygons composited "over" what lies behind them.
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <imgui.h>

#include "raster/image.h"
#include "panels/depth_sort_panels.h"
#include "panels/fat_pixels.h"
#include "panels/name_placement.h"
#include "panels/panel_style.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::SortPolygon;

const ImU32 r_colour = IM_COL32(240, 227, 66, 255);   // palette::current_edge, as R is in the 3D view
const ImU32 q_colour = IM_COL32(87, 181, 232, 255);   // palette::parameter, as Q is
const ImU32 cut_colour = IM_COL32(214, 94, 0, 255);   // vermillion
const ImU32 text_colour = IM_COL32(220, 220, 220, 255);
const ImU32 dim_colour = IM_COL32(150, 153, 160, 255);

float ease(float from, float to, bool animate) {
    if (!animate) return to;
    const float k = 1 - std::exp(-ImGui::GetIO().DeltaTime * 9);
    return from + (to - from) * std::clamp(k, 0.0f, 1.0f);
}

// Chips ease towards their place in the list, so that a move to the head or the parts of a cut slide into place
// instead of jumping.
void display_list(const DepthSortSession& s, ChipPlaces& anim, ImDrawList* d, ImVec2 at, float w, bool animate) {
    const DepthSortView& v = s.view();
    anim.x.resize(v.polygons.size(), NAN);
    const std::size_t n = v.drawn.size() + v.list.size();
    const float gap = 26, chip = std::clamp((w - gap) / float(std::max<std::size_t>(n, 1)) - 4, 8.0f, 46.0f);
    const std::string heading = tr(v.front_to_back ? "depth_sort.heading_front" : "depth_sort.heading", {{"moves", std::to_string(v.moves)}, {"splits", std::to_string(v.splits)}});
    d->AddText(at, dim_colour, heading.c_str());
    const float list_x0 = at.x + float(v.drawn.size()) * (chip + 4) + (v.drawn.empty() ? 0 : gap);
    // over the list's head, while there is a list: kept inside the canvas (12 chips pushed it past the view's edge)
    if (!v.list.empty()) {
        const std::string list_words = tr("depth_sort.display_list");
        const float words = ImGui::CalcTextSize(list_words.c_str()).x;
        const float x = std::min(std::max(list_x0, at.x + ImGui::CalcTextSize(heading.c_str()).x + 18), at.x + w - words);
        d->AddText(ImVec2(x, at.y), dim_colour, list_words.c_str());
    }
    const float y = at.y + 22;
    struct Note {
        float x;
        std::string text;
        ImU32 colour;
    };
    std::vector<Note> notes;  // under the chips; drawn after them, a note wider than its chip never over the next one
    const auto place_chip = [&](std::uint32_t i, float target) {
        float& x = anim.x[i];
        if (std::isnan(x)) x = v.cut >= 0 && std::size_t(v.cut) < anim.x.size() && !std::isnan(anim.x[std::size_t(v.cut)])
                                   ? anim.x[std::size_t(v.cut)] : target;  // parts start where the cut polygon was
        x = ease(x, target, animate);
        const SortPolygon& p = v.polygons[i];
        const bool drawn = std::find(v.drawn.begin(), v.drawn.end(), i) != v.drawn.end();
        const float lift = int(i) == v.moved ? -6.0f : 0.0f;
        const ImVec2 a(x, y + lift), b(x + chip, y + lift + 28);
        const float alpha = drawn ? 0.35f + 0.65f * float(p.opacity) : 0.3f;
        d->AddRectFilled(a, b, rgb(p.color, alpha), 3);
        ImU32 edge = IM_COL32(90, 94, 102, 255);
        float thickness = canvas_px(1);
        if (int(i) == v.r) edge = r_colour, thickness = canvas_px(3);
        if (int(i) == v.q) edge = q_colour, thickness = canvas_px(3);
        d->AddRect(a, b, edge, 3, 0, thickness);
        if (chip >= 26) d->AddText(ImVec2(a.x + 4, a.y + 5), text_on(p.color, alpha), ("#" + std::to_string(i)).c_str());
        const std::string note = int(i) == v.moved ? tr("depth_sort.moved_note") : int(i) == v.cycle ? tr("depth_sort.cycle_note")
                                 : int(i) == v.r   ? "R" : int(i) == v.q ? "Q" : "";
        if (!note.empty()) notes.push_back({a.x + 2, note, int(i) == v.cycle ? cut_colour : text_colour});
    };
    for (std::size_t k = 0; k < v.drawn.size(); ++k) place_chip(v.drawn[k], at.x + float(k) * (chip + 4));
    for (std::size_t k = 0; k < v.list.size(); ++k) place_chip(v.list[k], list_x0 + float(k) * (chip + 4));
    // each note on the first line under the chips where it clears the note before it ("verschoben" is wider than a chip)
    std::sort(notes.begin(), notes.end(), [](const Note& p, const Note& q) { return p.x < q.x; });
    const float line = ImGui::GetTextLineHeight();
    std::vector<float> line_ends;  // the right end of the last note on each line
    for (const Note& note : notes) {
        std::size_t row = 0;
        while (row < line_ends.size() && note.x < line_ends[row] + 4) ++row;
        if (row == line_ends.size()) line_ends.push_back(0);
        line_ends[row] = note.x + ImGui::CalcTextSize(note.text.c_str()).x;
        d->AddText(ImVec2(note.x, y + 30 + float(row) * line), note.colour, note.text.c_str());
    }
    if (v.cut >= 0) {
        const std::string cut = tr("depth_sort.was_cut", {{"polygon", std::to_string(v.cut)}, {"front", std::to_string(v.polygons.size() - 2)},
                                                          {"back", std::to_string(v.polygons.size() - 1)}});
        d->AddText(ImVec2(at.x, y + 32 + float(std::max<std::size_t>(line_ends.size(), 1)) * line), cut_colour, cut.c_str());
    }
}

// The screen, x and y in [−1, 1] (y up), as a square of `size` points from `o`.
struct Screen {
    ImVec2 o;
    float size;
    ImVec2 operator()(double x, double y) const {
        return {o.x + float((x + 1) / 2) * size, o.y + float((1 - y) / 2) * size};
    }
};

void projection(ImDrawList* d, const Screen& screen, const SortPolygon& p, ImU32 fill, ImU32 edge, float thickness) {
    std::vector<ImVec2> points;
    for (const auto& v : p.vertices) points.push_back(screen(v.x, v.y));
    if (points.size() >= 3) d->AddConvexPolyFilled(points.data(), int(points.size()), fill);
    d->AddPolyline(points.data(), int(points.size()), edge, ImDrawFlags_Closed, thickness);
}

// An extent [lo, hi] of x (below the screen) or y (left of it), in the colour of its polygon.
void extent_bar(ImDrawList* d, const Screen& screen, const SortPolygon& p, bool along_x, float offset, ImU32 colour) {
    double lo = 1e300, hi = -1e300;
    for (const auto& v : p.vertices) lo = std::min(lo, along_x ? v.x : v.y), hi = std::max(hi, along_x ? v.x : v.y);
    if (along_x) {
        const float y = screen.o.y + screen.size + offset;
        d->AddLine(ImVec2(screen(lo, 0).x, y), ImVec2(screen(hi, 0).x, y), colour, canvas_px(4));
    } else {
        const float x = screen.o.x - offset;
        d->AddLine(ImVec2(x, screen(0, lo).y), ImVec2(x, screen(0, hi).y), colour, canvas_px(4));
    }
}

// "#i" on a dark backing inside polygon i's projection: the parts of a cut, which the questions name, are found in
// the picture by the numbers the chips carry. At the middle, or part way to a corner where an earlier number sits.
void number_label(ImDrawList* d, const Screen& screen, const SortPolygon& p, std::uint32_t i, std::vector<ImVec4>& taken) {
    if (p.vertices.empty()) return;
    std::vector<ImVec2> corners;
    for (const auto& v : p.vertices) corners.push_back(screen(v.x, v.y));
    // a translucent pane's α beside its number: C = αF + (1 − α)B is worked with it
    char alpha[24] = "";
    if (p.opacity < 1) std::snprintf(alpha, sizeof alpha, "  α = %.2g", p.opacity);
    const std::string text = "#" + std::to_string(i) + alpha;
    const ImVec4 b = place_name(corners, ImGui::CalcTextSize(text.c_str()), 2, {0.45f, 0.7f}, true, taken);
    d->AddRectFilled(ImVec2(b.x, b.y), ImVec2(b.z, b.w), IM_COL32(26, 28, 33, 215), 2);
    d->AddText(ImVec2(b.x + 2, b.y + 1), text_colour, text.c_str());
}

void screen_inset(const DepthSortSession& s, ImDrawList* d, Screen screen) {
    const DepthSortView& v = s.view();
    d->AddRectFilled(screen.o, ImVec2(screen.o.x + screen.size, screen.o.y + screen.size), IM_COL32(26, 28, 33, 255));
    d->AddRect(screen.o, ImVec2(screen.o.x + screen.size, screen.o.y + screen.size), IM_COL32(110, 114, 122, 255));
    d->AddText(ImVec2(screen.o.x, screen.o.y - 20), text_colour, tr("depth_sort.screen_inset").c_str());
    // those already drawn faintly in their colours (the inset keeps every polygon's number to the end), those still
    // in the list as grey outlines, the pair under examination in the roles' colours
    for (std::uint32_t i : v.drawn) projection(d, screen, v.polygons[i], rgb(v.polygons[i].color, 0.18f), IM_COL32(110, 114, 122, 120), 1);
    for (std::uint32_t i : v.list)
        if (int(i) != v.r && int(i) != v.q) projection(d, screen, v.polygons[i], 0, IM_COL32(110, 114, 122, 200), 1);
    if (v.r >= 0 && v.q >= 0) {
        const SortPolygon &r = v.polygons[std::size_t(v.r)], &q = v.polygons[std::size_t(v.q)];
        projection(d, screen, r, rgb(r.color, 0.35f), r_colour, 2.5f);
        projection(d, screen, q, rgb(q.color, 0.35f), q_colour, 2.5f);
    }
    std::vector<ImVec4> taken;
    for (std::uint32_t i : v.list) number_label(d, screen, v.polygons[i], i, taken);
    for (std::uint32_t i : v.drawn) number_label(d, screen, v.polygons[i], i, taken);
    if (v.r < 0 || v.q < 0) return;
    const SortPolygon &r = v.polygons[std::size_t(v.r)], &q = v.polygons[std::size_t(v.q)];
    extent_bar(d, screen, r, true, 6, r_colour);
    extent_bar(d, screen, q, true, 12, q_colour);
    extent_bar(d, screen, r, false, 6, r_colour);
    extent_bar(d, screen, q, false, 12, q_colour);
    for (const algo::TestTried& t : v.tests)
        if (t.test == algo::OrderTest::projections)
            d->AddText(ImVec2(screen.o.x + 4, screen.o.y + 4), t.passed ? IM_COL32(90, 205, 140, 255) : cut_colour,
                       tr(t.passed ? "depth_sort.inset_apart" : "depth_sort.inset_overlap").c_str());
}

}  // namespace

DepthSortInsets depth_sort_insets(float x, float y, float w, float h) {
    // the two insets share the view's lower part: as large as leaves the canvas in the middle its room
    const float size = std::clamp(std::min(w * 0.34f, h * 0.40f), 110.0f, 420.0f);
    return {size, ImVec2(x + 34, y + h - size - 34), ImVec2(x + w - size - 16, y + h - size - 34)};
}

std::vector<ViewRect> DepthSortInsets::covered() const {
    const float title = 22;  // the line above each square
    return {{screen.x, screen.y - title, screen.x + size, screen.y + size}, {painted.x, painted.y - title, painted.x + size, painted.y + size}};
}

void depth_sort_canvas(const DepthSortSession& s, ChipPlaces& chips, const algo::Image& painted, float x, float y, float w,
                       float h, bool animate) {
    ImDrawList* d = begin_canvas("##depth sort canvas", x, y, w, h);
    display_list(s, chips, d, ImVec2(x + 16, y + 10), w - 32, animate);
    const DepthSortInsets insets = depth_sort_insets(x, y, w, h);
    screen_inset(s, d, {insets.screen, insets.size});
    const ImVec2 at = insets.painted;
    d->AddText(ImVec2(at.x, at.y - 20), text_colour,
               tr(s.view().front_to_back ? "depth_sort.drawn_so_far" : "depth_sort.painted_so_far").c_str());
    draw_image(d, painted, at, ImVec2(insets.size, insets.size));
    ImGui::End();
}

}  // namespace hsr::viz
