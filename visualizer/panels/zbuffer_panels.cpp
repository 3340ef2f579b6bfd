// SPDX-License-Identifier: MIT
#include "panels/zbuffer_panels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "core/events.h"
#include "panels/fat_pixels.h"
#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::DepthFormat;

constexpr std::array formats = {DepthFormat::int16, DepthFormat::int24, DepthFormat::int32,
                                DepthFormat::float32, DepthFormat::float32_reversed, DepthFormat::linear24};

std::string g4(double v) {  // four significant digits: what a student compares
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

// The eye distance a window depth d stands for (perspective: d = a + b/z).
double eye_distance(double d, algo::DepthRange r) {
    const double a = r.far / (r.far - r.near), b = r.far * r.near / (r.near - r.far);
    return b / (d - a);
}

// The eye distance whose code is `target`, by bisection (codes grow with distance in every format).
double distance_of_code(DepthFormat f, std::uint64_t target, algo::DepthRange r) {
    double lo = r.near, hi = r.far;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (algo::code(f, mid, r) < target ? lo : hi) = mid;
    }
    return hi;
}

// The outline of the pixel under test: being tested, written (nearer), or failed the depth test (kept what was there).
ImU32 outcome_colour(PixelOutcome o) {
    return o == PixelOutcome::written ? IM_COL32(90, 220, 130, 255) : o == PixelOutcome::failed ? IM_COL32(240, 80, 60, 255) : IM_COL32(255, 230, 90, 255);
}

// What the fill has under way: the polygon, its span and the pixel under test.
void under_way(ImDrawList* d, ImVec2 origin, float cell, const ZView& v) {
    for (const auto& p : *v.polygons) outline(d, origin, cell, p, ImGui::GetColorU32(ImVec4(1, 1, 1, 0.25f)), 1);
    if (v.polygon >= 0) outline(d, origin, cell, (*v.polygons)[std::size_t(v.polygon)], IM_COL32(255, 255, 255, 255), 2.5f);
    if (v.span_y >= 0)
        d->AddRect(ImVec2(origin.x + float(v.span_begin) * cell - 1, origin.y + float(v.span_y) * cell - 1),
                   ImVec2(origin.x + float(v.span_end) * cell, origin.y + float(v.span_y + 1) * cell), IM_COL32(255, 230, 90, 255), 0, 0, canvas_px(2));
    if (v.pixel_x >= 0) {
        const ImU32 c = outcome_colour(v.outcome);
        d->AddRect(ImVec2(origin.x + float(v.pixel_x) * cell - 2, origin.y + float(v.pixel_y) * cell - 2),
                   ImVec2(origin.x + float(v.pixel_x + 1) * cell + 1, origin.y + float(v.pixel_y + 1) * cell + 1), c, 0, 0, canvas_px(3));
    }
}

// Stored codes against eye distance: a tick at every 1/64 of the codes between near and far.
void precision_diagram(ImDrawList* d, ImVec2 at, float width, const ZView& v) {
    const algo::DepthRange r = v.range;
    const float x0 = at.x + 10, x1 = at.x + width - 10, y = at.y + 26;
    const auto x_of = [&](double z) { return x0 + float((z - r.near) / (r.far - r.near)) * (x1 - x0); };
    d->AddLine(ImVec2(x0, y), ImVec2(x1, y), IM_COL32(200, 200, 200, 255), canvas_px(1.5f));
    const std::uint64_t c0 = algo::code(v.format, r.near, r), c1 = algo::code(v.format, r.far, r);
    constexpr int ticks = 64;
    for (int i = 0; i <= ticks; ++i) {
        const std::uint64_t c = c0 + (c1 - c0) * std::uint64_t(i) / ticks;
        const float x = x_of(distance_of_code(v.format, c, r));
        d->AddLine(ImVec2(x, y - 8), ImVec2(x, y + 8), IM_COL32(120, 190, 255, 255), canvas_px(1));
    }
    d->AddText(ImVec2(x0, y + 10), IM_COL32(200, 200, 200, 255), tr("zbuffer.near_at", {{"near", algo::format_number(r.near)}}).c_str());
    const std::string far_text = tr("zbuffer.far_at", {{"far", algo::format_number(r.far)}});
    d->AddText(ImVec2(x1 - ImGui::CalcTextSize(far_text.c_str()).x, y + 10), IM_COL32(200, 200, 200, 255), far_text.c_str());
    d->AddText(ImVec2(x0, at.y), IM_COL32(200, 200, 200, 255), tr("zbuffer.axis").c_str());
    if (v.pixel_x >= 0) {  // the pixel under test on the same axis
        const float x = x_of(std::clamp(eye_distance(v.pixel_depth, r), r.near, r.far));
        d->AddTriangleFilled(ImVec2(x, y - 10), ImVec2(x - 6, y - 20), ImVec2(x + 6, y - 20), IM_COL32(255, 230, 90, 255));
    }
}


// The pixel under test and its neighbours close up: each one's stored code on its polygon's colour (blank: the far
// code, never written), the pixels' x above and y beside; the pixel under test outlined by its outcome, with the
// incoming code it is compared against, and a legend of the outline's colours.
void close_up(ImDrawList* d, ImVec2 at, float width, float height, const ZView& v) {
    const ImU32 text = IM_COL32(220, 220, 220, 255), dim = IM_COL32(150, 150, 150, 255);
    const float line = ImGui::GetTextLineHeight();
    // the pixel under test; else the first pixel of the span under way (a step fills a span, a micro step a pixel)
    const bool testing = v.pixel_x >= 0;
    const int fx = testing ? v.pixel_x : v.span_begin, fy = testing ? v.pixel_y : v.span_y;
    if (fy < 0) {
        if (height > 3 * line) {  // wrapped to the box: a longer language's sentence ran off its right edge
            const std::string idle = tr("zbuffer.close_up_idle");
            d->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, dim, idle.c_str(), nullptr, width);
        }
        return;
    }
    const std::string widest = std::to_string(v.far_code);
    const float cw = ImGui::CalcTextSize(widest.c_str()).x + canvas_px(12), ch = line + canvas_px(8);
    const float header = ImGui::CalcTextSize("000").x + canvas_px(6);
    int cols = std::min(9, int((width - header) / cw)), rows = std::min(5, int((height - 5 * line) / ch));
    cols -= 1 - cols % 2, rows -= 1 - rows % 2;  // odd: the pixel under test in the middle
    if (cols < 3 || rows < 1) return;
    const int x0 = std::clamp(fx - cols / 2, 0, std::max(0, v.viewport.width - cols));
    const int y0 = std::clamp(fy - rows / 2, 0, std::max(0, v.viewport.height - rows));
    cols = std::min(cols, v.viewport.width), rows = std::min(rows, v.viewport.height);
    const std::string title = tr(testing ? "zbuffer.close_up" : "zbuffer.close_up_span",
                                 {{"x", std::to_string(fx)}, {"y", std::to_string(fy)}, {"incoming", std::to_string(v.incoming)}});
    d->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, text, title.c_str(), nullptr, width);  // wrapped in the view
    const float title_h = ImGui::CalcTextSize(title.c_str(), nullptr, false, width).y;
    const float top = at.y + title_h + canvas_px(6) + line, left = at.x + header;
    for (int c = 0; c < cols; ++c)
        d->AddText(ImVec2(left + float(c) * cw + canvas_px(4), top - line), dim, std::to_string(x0 + c).c_str());
    for (int r = 0; r < rows; ++r) {
        const int py = y0 + r;
        d->AddText(ImVec2(at.x, top + float(r) * ch + canvas_px(4)), dim, std::to_string(py).c_str());
        for (int c = 0; c < cols; ++c) {
            const int px = x0 + c;
            const std::size_t i = std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px);
            const ImVec2 a(left + float(c) * cw, top + float(r) * ch), b(a.x + cw - 2, a.y + ch - 2);
            const std::int32_t o = v.owner[i];
            const algo::Color fill = o < 0 ? algo::Color{40, 43, 50} : (*v.polygons)[std::size_t(o)].color;
            d->AddRectFilled(a, b, rgb(fill, o < 0 ? 1.0f : 0.55f), 2);
            if (v.depth[i] < v.far_code)
                d->AddText(ImVec2(a.x + canvas_px(5), a.y + canvas_px(4)), text_on(fill, o < 0 ? 1.0f : 0.55f), std::to_string(v.depth[i]).c_str());
            if (py == v.span_y && px >= v.span_begin && px < v.span_end)  // the span under way, as in the grids
                d->AddRect(a, b, IM_COL32(255, 230, 90, 160), 2, 0, canvas_px(1));
            if (testing && px == v.pixel_x && py == v.pixel_y) d->AddRect(ImVec2(a.x - 2, a.y - 2), ImVec2(b.x + 2, b.y + 2), outcome_colour(v.outcome), 0, 0, canvas_px(3));
        }
    }
    // the legend: each outline colour with its word
    float x = at.x;
    const float y = top + float(rows) * ch + canvas_px(6);
    for (const PixelOutcome o : {PixelOutcome::none, PixelOutcome::written, PixelOutcome::failed}) {
        const std::string word = tr(o == PixelOutcome::written ? "zbuffer.outcome_written" : o == PixelOutcome::failed ? "zbuffer.outcome_failed" : "zbuffer.outcome_testing");
        d->AddRect(ImVec2(x, y + 2), ImVec2(x + line - 4, y + line - 2), outcome_colour(o), 0, 0, canvas_px(3));
        d->AddText(ImVec2(x + line + 2, y), text, word.c_str());
        x += line + 2 + ImGui::CalcTextSize(word.c_str()).x + canvas_px(18);
    }
}
}  // namespace

FatGrid zbuffer_frame_grid(const ZBufferSession& s, float x, float y, float w, float h) {
    const ZView& v = s.view();
    const float margin = 24, diagram = 70;
    const float cell = std::max(2.0f, std::min((w - 3 * margin) / (2.0f * float(v.viewport.width)),
                                               (h - 2 * margin - diagram - 24) / float(v.viewport.height)));
    return {x + margin, y + margin + 20, cell};
}

void zbuffer_canvas(const ZBufferSession& s, float x, float y, float w, float h) {
    const ZView& v = s.view();
    ImDrawList* d = begin_canvas("##zbuffer canvas", x, y, w, h);
    const float margin = 24;
    const FatGrid grid = zbuffer_frame_grid(s, x, y, w, h);
    const float cell = grid.cell;
    const ImVec2 frame(grid.x0, grid.y0), depth(frame.x + cell * float(v.viewport.width) + margin, frame.y);
    d->AddText(ImVec2(frame.x, y + margin - 2), IM_COL32(220, 220, 220, 255), tr("zbuffer.frame").c_str());
    d->AddText(ImVec2(depth.x, y + margin - 2), IM_COL32(220, 220, 220, 255), tr("zbuffer.depth").c_str());
    const algo::Color background{26, 28, 33};
    const auto at = [&](int px, int py) { return std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px); };
    pixel_grid(d, frame, cell, v.viewport, [&](int px, int py) {
        const std::int32_t o = v.owner[at(px, py)];
        return o < 0 ? rgb({40, 43, 50}) : rgb((*v.polygons)[std::size_t(o)].color);
    });
    grid_numbers(d, frame, cell, v.viewport);
    // heat: stretched over the codes the buffer holds now (perspective codes bunch up near the far end)
    std::uint64_t lo = v.far_code, hi = 0;
    for (std::uint64_t c : v.depth)
        if (c < v.far_code) lo = std::min(lo, c), hi = std::max(hi, c);
    pixel_grid(d, depth, cell, v.viewport, [&](int px, int py) {
        const std::uint64_t c = v.depth[at(px, py)];
        if (c >= v.far_code) return rgb(background);
        const float g = hi > lo ? 0.25f + 0.75f * float(double(hi - c) / double(hi - lo)) : 1.0f;
        return ImGui::GetColorU32(ImVec4(0.15f + 0.85f * g, 0.12f + 0.6f * g, 0.25f * (1 - g) + 0.1f, 1));
    });
    // each polygon named in the frame buffer as the machine's sentences and the questions name it (its scene id)
    std::vector<ImVec4> taken = shared_edge_strips(*v.polygons, v.polygon, frame, cell);  // not over a shared edge, the span or the pixel under test
    if (v.span_y >= 0)
        taken.push_back(ImVec4(frame.x + float(v.span_begin) * cell - 2, frame.y + float(v.span_y) * cell - 2, frame.x + float(v.span_end) * cell + 2,
                               frame.y + float(v.span_y + 1) * cell + 2));
    if (v.pixel_x >= 0)
        taken.push_back(ImVec4(frame.x + float(v.pixel_x) * cell - 3, frame.y + float(v.pixel_y) * cell - 3, frame.x + float(v.pixel_x + 1) * cell + 3,
                               frame.y + float(v.pixel_y + 1) * cell + 3));
    for (const algo::ScreenPolygon& p : *v.polygons) polygon_name(d, frame, cell, v.viewport, p, tr("zbuffer.polygon_label", {{"id", std::to_string(p.id)}}), taken);
    under_way(d, frame, cell, v);
    under_way(d, depth, cell, v);
    const float diagram_top = frame.y + cell * float(v.viewport.height) + 16 + axis_number_size();  // under the x numbers
    precision_diagram(d, ImVec2(x + margin, diagram_top), w - 2 * margin, v);
    const float close_top = diagram_top + 26 + 10 + ImGui::GetTextLineHeight() + canvas_px(24);  // under the diagram's words
    close_up(d, ImVec2(x + margin, close_top), w - 2 * margin, y + h - margin - close_top, v);
    ImGui::End();
}

void zbuffer_state_panel(const ZBufferSession& s, bool in_3d, const PanelLayout& l, UiActions& out) {
    begin_column_box(l, Box::state, (tr("zbuffer.title") + "###state").c_str());
    const ZView& v = s.view();
    int current = 0;
    for (std::size_t i = 0; i < formats.size(); ++i)
        if (formats[i] == v.format) current = int(i);
    // as wide as the widest format's name in the student's language, at any type size
    const auto name = [](DepthFormat f) { return window_strings().name(algo::to_string(f)); };
    float widest = 0;
    for (const DepthFormat f : formats) widest = std::max(widest, ImGui::CalcTextSize(name(f).c_str()).x);
    ImGui::SetNextItemWidth(widest + ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().FramePadding.x);
    if (ImGui::BeginCombo((tr("zbuffer.format") + "###format").c_str(), name(v.format).c_str())) {
        for (std::size_t i = 0; i < formats.size(); ++i)
            if (ImGui::Selectable(name(formats[i]).c_str(), int(i) == current))
                out.depth_format = formats[i];
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    bool three_d = in_3d;
    if (ImGui::Checkbox((tr("zbuffer.view_3d") + "###3d").c_str(), &three_d)) out.toggle_3d = true;
    float near = float(v.range.near), far = float(v.range.far);
    ImGui::SetNextItemWidth(150);
    const bool near_moved = ImGui::SliderFloat((tr("zbuffer.near") + "###near").c_str(), &near, 1e-3f, 10.0f, "%.4g", ImGuiSliderFlags_Logarithmic);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(150);
    const bool far_moved = ImGui::SliderFloat((tr("zbuffer.far") + "###far").c_str(), &far, 1.0f, 1e5f, "%.4g", ImGuiSliderFlags_Logarithmic);
    if ((near_moved || far_moved) && near < far) out.depth_range = algo::DepthRange{near, far};
    wrapped_text(tr(algo::smaller_is_nearer(v.format) ? "zbuffer.smaller_nearer" : "zbuffer.larger_nearer", {{"far", std::to_string(v.far_code)}}),
                 dim_text);
    // The distance the resolvable step is shown for: the user's choice, kept in ImGui's own widget storage as a
    // slider's value is (the geometric mean of near and far until moved)
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID probe_id = ImGui::GetID("probe distance");
    float probe = storage->GetFloat(probe_id, float(std::sqrt(v.range.near * v.range.far)));
    ImGui::SetNextItemWidth(150);
    if (ImGui::SliderFloat((tr("zbuffer.distance") + "###distance").c_str(), &probe, float(v.range.near), float(v.range.far), "%.4g", ImGuiSliderFlags_Logarithmic))
        storage->SetFloat(probe_id, probe);
    const double z = std::clamp(double(probe), v.range.near, v.range.far);
    // beside the slider when it fits there, else under it
    const std::string step = tr("zbuffer.step", {{"step", g4(algo::resolvable_step(v.format, z, v.range))}});
    ImGui::SameLine();
    if (ImGui::CalcTextSize(step.c_str()).x > ImGui::GetContentRegionAvail().x) ImGui::NewLine();
    wrapped_text(step);
    const auto n = [](auto value) { return std::to_string(value); };
    if (v.pixel_x >= 0) {
        const double zp = eye_distance(v.pixel_depth, v.range);
        wrapped_text(tr("zbuffer.step_at_pixel", {{"z", g4(zp)}, {"step", g4(algo::resolvable_step(v.format, zp, v.range))}}), dim_text);
        wrapped_text(tr("zbuffer.pixel", {{"x", n(v.pixel_x)}, {"y", n(v.pixel_y)}, {"new", n(v.incoming)},
                                          {"relation", v.incoming < v.stored ? "<" : "≥"}, {"stored", n(v.stored)}}));
    }
    wrapped_text(tr("zbuffer.counts", {{"tested", n(v.tested)}, {"written", n(v.written)}, {"unlike", n(s.pixels_unlike_ray_cast())}}),
                 dim_text);
    if (s.unlike_on_edges() > 0)  // ties, not errors: say so, or a class reads them as the fill's mistakes
        wrapped_text(tr("zbuffer.unlike_on_edges", {{"edges", n(s.unlike_on_edges())}}), dim_text);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
