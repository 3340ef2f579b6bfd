// SPDX-License-Identifier: MIT
// The state panel of a clipping lesson: outcodes (Cohen–Sutherland), parameters (Liang–Barsky) or the pipeline
// stage (Sutherland–Hodgman).
#include "panels/clip_panels.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::ClipAlgorithm;
using algo::ClipPlane;

const ImVec4 equation_colour(0.95f, 0.70f, 0.20f, 1.0f);  // the orange of the intersections in the 3D view


void outcode_table(const ClipView& v) {
    const int columns = algo::plane_count(v.space);
    // the lecture's bit order, bit 1 first; each header names the plane the bit says a point is outside of, as the
    // narration, the pipeline and the questions name it ("x max": outside x ≤ w)
    static constexpr const char* headers[] = {"z max", "z min", "y max", "y min", "x max", "x min", "w<ε"};
    if (!ImGui::BeginTable("outcodes", columns + 1, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame))
        return;
    ImGui::TableSetupColumn("bit", ImGuiTableColumnFlags_WidthFixed, 44);
    for (int c = 0; c < columns; ++c) ImGui::TableSetupColumn(headers[c]);
    ImGui::TableHeadersRow();
    const bool both = v.c1_known && v.c2_known;
    const struct {
        const char* name;
        algo::Outcode code;
        bool known;
    } rows[] = {{"p1", v.c1, v.c1_known}, {"p2", v.c2, v.c2_known}, {"OR", v.c1 | v.c2, both}, {"AND", v.c1 & v.c2, both}};
    for (const auto& row : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.name);
        for (int c = 0; c < columns; ++c) {
            ImGui::TableNextColumn();
            const bool set = row.known && row.code.has(algo::all_planes[std::size_t(c)]);
            ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, ImGui::GetColorU32(set ? bit_set : bit_clear));
            ImGui::TextUnformatted(!row.known ? " ·" : set ? " 1" : " 0");
        }
    }
    ImGui::EndTable();
    // (while an intersection is shown, its equation names R)
    if (v.plane && !v.intersecting)
        wrapped_text(tr("clipping.plane_r", {{"inequality", std::string(algo::plane_inequality(*v.plane, v.space))}}));
}

void parameter_bar(const ClipView& v) {
    ImGui::Text("t_enter = %.4g     t_leave = %.4g", v.t_enter, v.t_leave);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x - 8, h = 22;
    ImDrawList* d = ImGui::GetWindowDrawList();
    d->AddRectFilled(at, ImVec2(at.x + w, at.y + h), ImGui::GetColorU32(bit_clear));
    const float a = at.x + w * float(std::clamp(v.t_enter, 0.0, 1.0)),
                b = at.x + w * float(std::clamp(v.t_leave, 0.0, 1.0));
    if (a <= b) d->AddRectFilled(ImVec2(a, at.y), ImVec2(b, at.y + h), ImGui::GetColorU32(highlight_bg));
    else d->AddRectFilled(ImVec2(b, at.y), ImVec2(a, at.y + h), ImGui::GetColorU32(bit_set));
    d->AddText(ImVec2(at.x + 2, at.y + 2), IM_COL32_WHITE, "0");
    d->AddText(ImVec2(at.x + w - 10, at.y + 2), IM_COL32_WHITE, "1");
    ImGui::Dummy(ImVec2(w, h));
    if (v.plane) wrapped_text(tr("clipping.plane", {{"inequality", std::string(algo::plane_inequality(*v.plane, v.space))}}));
}

void pipeline(const ClipView& v) {
    for (int k = 0; k < algo::plane_count(v.space); ++k) {
        const ClipPlane r = algo::all_planes[std::size_t(k)];
        const bool current = v.plane == r;
        if (k > 0) ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Button, current ? highlight_bg : bit_clear);
        ImGui::SmallButton(std::string(algo::plane_name(r)).c_str());
        ImGui::PopStyleColor();
    }
    wrapped_text(tr("clipping.stage_counts", {{"input", std::to_string(v.stage_input.size())}, {"emitted", std::to_string(v.stage_output.size())}}));
    if (v.edge >= 0)
        wrapped_text(tr("clipping.edge", {{"from", std::to_string(v.edge)},
                                          {"to", std::to_string((std::size_t(v.edge) + 1) % std::max<std::size_t>(1, v.stage_input.size()))}}));
}

// The notes' equation (3) for the intersection just computed, with its numbers: where the homogeneous
// intersections come from (the notes print the six planes' forms; this is the one in use).
void equation_three(const ClipView& v) {
    if (!v.intersecting) return;
    const auto& [plane, p1, p2] = *v.intersecting;
    const algo::EquationThree e = algo::equation_three(plane, v.space, p1, p2);
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, " = %.4g / %.4g = %.4g", e.numerator, e.denominator, e.t());
    wrapped_text(tr("clipping.equation_three", {{"inequality", std::string(algo::plane_inequality(plane, v.space))}}));
    wrapped_text("t = " + std::string(e.formula) + numbers, equation_colour);
}

}  // namespace

void clip_state_panel(const ClipSession& s, const PanelLayout& l) {
    const ClipView& v = s.view();
    const std::string title = tr(s.algorithm() == ClipAlgorithm::cohen_sutherland ? "clipping.outcodes"
                                 : s.algorithm() == ClipAlgorithm::liang_barsky   ? "clipping.parameters"
                                                                                  : "clipping.pipeline");
    begin_column_box(l, Box::state, (title + "###clip state").c_str());
    switch (s.algorithm()) {
        case ClipAlgorithm::cohen_sutherland: outcode_table(v); break;
        case ClipAlgorithm::liang_barsky: parameter_bar(v); break;
        case ClipAlgorithm::sutherland_hodgman: pipeline(v); break;
    }
    equation_three(v);
    if (v.bound_reached) wrapped_text(tr("clipping.bound_reached"), bit_set);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
