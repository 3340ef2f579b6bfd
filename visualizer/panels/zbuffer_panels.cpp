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

// What the fill has under way: the polygon, its span and the pixel under test.
void under_way(ImDrawList* d, ImVec2 origin, float cell, const ZView& v) {
    for (const auto& p : *v.polygons) outline(d, origin, cell, p, ImGui::GetColorU32(ImVec4(1, 1, 1, 0.25f)), 1);
    if (v.polygon >= 0) outline(d, origin, cell, (*v.polygons)[std::size_t(v.polygon)], IM_COL32(255, 255, 255, 255), 2.5f);
    if (v.span_y >= 0)
        d->AddRect(ImVec2(origin.x + float(v.span_begin) * cell - 1, origin.y + float(v.span_y) * cell - 1),
                   ImVec2(origin.x + float(v.span_end) * cell, origin.y + float(v.span_y + 1) * cell), IM_COL32(255, 230, 90, 255), 0, 0, canvas_px(2));
    if (v.pixel_x >= 0) {
        const ImU32 c = v.outcome == PixelOutcome::written  ? IM_COL32(90, 220, 130, 255)
                        : v.outcome == PixelOutcome::failed ? IM_COL32(240, 80, 60, 255)
                                                            : IM_COL32(255, 230, 90, 255);
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
    under_way(d, frame, cell, v);
    under_way(d, depth, cell, v);
    precision_diagram(d, ImVec2(x + margin, frame.y + cell * float(v.viewport.height) + 16), w - 2 * margin, v);
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
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
