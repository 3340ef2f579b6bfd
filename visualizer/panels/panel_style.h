// SPDX-License-Identifier: MIT
// Colours and placement shared by the panels.
#pragma once

#include <algorithm>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>

#include "panels/layout_audit.h"
#include "panels/lesson_panels.h"
#include "core/okabe_ito.h"

namespace hsr::viz {

// An Okabe–Ito colour (core/okabe_ito.h) for ImGui's draw lists.
inline ImU32 okabe_ito_u32(algo::okabe_ito::Rgb8 c, unsigned alpha = 255) { return IM_COL32(c.r, c.g, c.b, alpha); }

constexpr ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings;

inline const ImVec4 highlight_bg(0.20f, 0.34f, 0.52f, 1.0f);
inline const ImVec4 bit_set(0.84f, 0.37f, 0.0f, 1.0f);  // vermillion: outside this plane, back side, …
inline const ImVec4 bit_clear(0.18f, 0.20f, 0.24f, 1.0f);
inline const ImVec4 dim_text(0.62f, 0.64f, 0.68f, 1.0f);

// The type's scale (--projector, --scale, Ctrl+=; set where the fonts are built). The canvases draw their lines and
// marks canvas_px(n) wide, n pixels at scale 1, so that they grow with the type as the views' lines do and the back
// row sees a wall as well as it reads its label.
inline float& type_scale() {
    static float scale = 1;
    return scale;
}
inline float canvas_px(float n) { return n * type_scale(); }

// Numbers along an axis (a grid's pixels, the horizon's columns, the projectors): small type, and every 1st, 2nd,
// 5th, 10th … of them, the first step at which two-digit numbers `spacing` points apart do not touch.
inline float axis_number_size() { return ImGui::GetFontSize() * 0.75f; }
inline int axis_number_step(float spacing) {
    const float two_digits = ImGui::GetFont()->CalcTextSizeA(axis_number_size(), 1e9f, 0, "00").x + 3;
    for (int step : {1, 2, 5, 10, 20, 50})
        if (spacing * float(step) >= two_digits) return step;
    return 100;
}

// The second font loaded by the app, if any: monospace, for pseudocode.
inline ImFont* monospace_font() {
    ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    return atlas->Fonts.Size > 1 ? atlas->Fonts[1] : nullptr;
}

inline void place(float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
}

// A window without decoration over the view area, for a canvas drawn with ImGui's draw list.
inline ImDrawList* begin_canvas(const char* name, float x, float y, float w, float h) {
    place(x, y, w, h);
    ImGui::Begin(name, nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoBackground |
                                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoInputs);
    return ImGui::GetWindowDrawList();
}

// A box of the right-hand column: placed where the column's fit puts it, begun as a window with `flags`. End it
// with end_column_box, which tells the fit how tall its content was.
inline void begin_column_box(const PanelLayout& l, Box b, const char* title, ImGuiWindowFlags flags = fixed) {
    const auto slot = l.slot(b);
    // a box the column has no room for yet (a question that opened this frame, after the column was arranged) is
    // drawn once out of sight, to be measured: the next frame gives it its room. Drawn in place, it hung below the
    // column, over the timeline, with its choices cut off.
    const bool unplaced = l.fit && slot.h <= 0;
    place(l.width - l.side, unplaced ? l.height + 100 : slot.y, l.side, slot.h);
    ImGui::Begin(title, nullptr, l.fit && l.fit->holds(b) ? flags | ImGuiWindowFlags_NoScrollbar : flags);
}

// The height of the box's content down to the cursor: the content's bottom (the cursor stands one item spacing below
// it) and the padding under it.
inline float column_box_height_so_far() {
    const ImGuiStyle& style = ImGui::GetStyle();
    return ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y + 2;
}

// `need`: how much of the box must be seen (column_box_height_so_far() at that point), all of it by default;
// `full`: how tall it would be with all it has to show (when it left out what did not fit whole), else as drawn.
inline void end_column_box(const PanelLayout& l, Box b, float need = -1, float full_height = -1) {
    audit_current_window();
    if (b == Box::state && ImGui::GetCurrentWindow()->ScrollbarY) result_scrolls() = true;
    if (need >= 0 && need <= ImGui::GetWindowHeight() && ImGui::GetScrollY() == 0) {  // what must be seen is: only the rest scrolls
        auto& boxes = scrolling_boxes();
        const std::string name = std::string(ImGui::GetCurrentWindow()->Name);
        boxes.erase(std::remove(boxes.begin(), boxes.end(), name.substr(0, name.find("###"))), boxes.end());
    }
    if (l.fit) {
        float full = std::max(full_height, column_box_height_so_far());
        if (ImGui::GetCurrentWindow()->ScrollbarX) full += ImGui::GetStyle().ScrollbarSize;
        l.fit->asked(b, {need < 0 ? full : need, full});
    }
    // a box that scrolls fades out at its foot while more lies below: its last visible line reads as going on under
    // the edge (beside the scrollbar), not as a line cut in half
    if (ImGuiWindow* w = ImGui::GetCurrentWindow(); w->ScrollbarY && ImGui::GetScrollY() < ImGui::GetScrollMaxY()) {
        const ImRect inner = w->InnerClipRect;
        const float fade = std::min(ImGui::GetTextLineHeight() * 1.3f, inner.GetHeight() / 3);
        const ImU32 bg = ImGui::GetColorU32(ImGuiCol_WindowBg) | IM_COL32_A_MASK, clear = bg & ~IM_COL32_A_MASK;
        w->DrawList->AddRectFilledMultiColor(ImVec2(inner.Min.x, inner.Max.y - fade), inner.Max, clear, clear, bg, bg);
    }
    ImGui::End();
}

}  // namespace hsr::viz
