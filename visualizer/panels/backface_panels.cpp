// SPDX-License-Identifier: MIT
#include "panels/backface_panels.h"

#include <imgui.h>

#include "panels/panel_style.h"

namespace hsr::viz {

void backface_state_panel(const BackfaceSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "Faces");
    const BackfaceView& v = s.view();
    ImGui::TextColored(dim_text, "%d kept · %d culled · %d to test (%s)", v.kept, v.culled,
                       int(v.faces.size()) - v.kept - v.culled, std::string(algo::to_string(v.test)).c_str());
    if (ImGui::BeginTable("faces", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("face", ImGuiTableColumnFlags_WidthFixed, 50);
        ImGui::TableSetupColumn(v.test == algo::BackfaceTest::view_vector      ? "v·n"
                                : v.test == algo::BackfaceTest::plane_equation ? "N·eye + D"
                                                                               : "screen area",
                                ImGuiTableColumnFlags_WidthFixed, 110);
        ImGui::TableSetupColumn("verdict");
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < v.faces.size(); ++i) {
            const FaceView& f = v.faces[i];
            ImGui::TableNextRow();
            if (int(i) == v.current) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
            ImGui::TableNextColumn();
            ImGui::Text("%d", f.id);
            ImGui::TableNextColumn();
            if (f.facing) ImGui::Text("%.4g", f.value);
            ImGui::TableNextColumn();
            if (f.facing)
                ImGui::TextColored(*f.facing == algo::Facing::front ? ImVec4(0.35f, 0.8f, 0.55f, 1) : bit_set, "%s",
                                   std::string(algo::to_string(*f.facing)).c_str());
            else
                ImGui::TextColored(dim_text, "not tested yet");
        }
        ImGui::EndTable();
    }
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
