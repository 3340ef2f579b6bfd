// SPDX-License-Identifier: MIT
#include "panels/scanline_panels.h"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "panels/fat_pixels.h"
#include "panels/panel_style.h"

namespace hsr::viz {

void scanline_canvas(const ScanLineSession& s, float x, float y, float w, float h) {
    const ScanView& v = s.view();
    ImDrawList* d = begin_canvas("##scanline canvas", x, y, w, h);
    const float margin = 24;
    const float cell = std::max(2.0f, std::min((w - 2 * margin) / float(v.viewport.width), (h - 2 * margin - 24) / float(v.viewport.height)));
    const ImVec2 o(x + margin, y + margin + 20);
    d->AddText(ImVec2(o.x, y + margin - 2), IM_COL32(220, 220, 220, 255), "image, line by line (the active edges bold)");
    pixel_grid(d, o, cell, v.viewport, [&](int px, int py) {
        const std::int32_t k = v.owner[std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px)];
        return k >= 0 ? rgb((*v.polygons)[std::size_t(k)].color) : rgb({40, 43, 50});
    });
    for (const auto& p : *v.polygons) outline(d, o, cell, p, ImGui::GetColorU32(ImVec4(1, 1, 1, 0.3f)), 1);
    for (std::uint32_t e : v.active) {
        const algo::EdgeEntry& edge = (*v.edges)[e];
        d->AddLine(on_grid(o, cell, edge.a), on_grid(o, cell, edge.b), IM_COL32(255, 255, 255, 255), canvas_px(3));
    }
    if (v.line >= 0) {
        const float ly = o.y + (float(v.line) + 0.5f) * cell;
        d->AddLine(ImVec2(o.x - 8, ly), ImVec2(o.x + cell * float(v.viewport.width) + 8, ly), IM_COL32(255, 230, 90, 255), canvas_px(2));
        for (const Crossing& c : v.crossings) {
            const float cx = o.x + float(c.x) * cell;
            const ImU32 colour = c.entering ? IM_COL32(90, 220, 130, 255) : IM_COL32(240, 80, 60, 255);
            d->AddCircleFilled(ImVec2(cx, ly), 6, colour);
            d->AddText(ImVec2(cx - 8, ly - 26), colour, c.entering ? "in" : "out");
        }
    }
    ImGui::End();
}

void scanline_state_panel(const ScanLineSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "Edge table");
    const ScanView& v = s.view();
    ImGui::TextColored(dim_text, "line %d · %zu active edges · %llu spans output", v.line, v.active.size(),
                       (unsigned long long)v.spans);
    if (ImGui::BeginTable("edges", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("edge", ImGuiTableColumnFlags_WidthFixed, 44);
        ImGui::TableSetupColumn("polygon", ImGuiTableColumnFlags_WidthFixed, 64);
        ImGui::TableSetupColumn("lines", ImGuiTableColumnFlags_WidthFixed, 70);
        ImGui::TableSetupColumn("side", ImGuiTableColumnFlags_WidthFixed, 44);
        ImGui::TableSetupColumn("in/out");
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < v.edges->size(); ++i) {
            const algo::EdgeEntry& e = (*v.edges)[i];
            ImGui::TableNextRow();
            if (std::find(v.active.begin(), v.active.end(), std::uint32_t(i)) != v.active.end())
                ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
            ImGui::TableNextColumn();
            ImGui::Text("%zu", i);
            ImGui::TableNextColumn();
            ImGui::Text("%d", (*v.polygons)[e.polygon].id);
            ImGui::TableNextColumn();
            ImGui::Text("%d–%d", e.first_row, e.end_row - 1);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(e.left ? "left" : "right");
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(v.in[e.polygon] ? "in" : "");
        }
        ImGui::EndTable();
    }
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
