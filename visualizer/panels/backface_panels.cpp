// SPDX-License-Identifier: MIT
#include "panels/backface_panels.h"

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

void backface_state_panel(const BackfaceSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("backface.title") + "###state").c_str());
    const BackfaceView& v = s.view();
    const Strings& words = window_strings();
    wrapped_text(tr("backface.counts", {{"kept", std::to_string(v.kept)}, {"culled", std::to_string(v.culled)},
                                        {"left", std::to_string(int(v.faces.size()) - v.kept - v.culled)}, {"test", words.say(algo::term(v.test))}}),
                 dim_text);
    const std::string face = tr("backface.face"), verdict = tr("backface.verdict");
    const std::string quantity = v.test == algo::BackfaceTest::view_vector      ? "v·n"
                                 : v.test == algo::BackfaceTest::plane_equation ? "N·eye + D"
                                                                                : tr("machine.backface.screen_area");
    if (ImGui::BeginTable("faces", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        const float pad = 2 * ImGui::GetStyle().CellPadding.x;  // columns sized to their words, in any language and type size
        ImGui::TableSetupColumn(face.c_str(), ImGuiTableColumnFlags_WidthFixed, std::max(ImGui::CalcTextSize(face.c_str()).x, ImGui::CalcTextSize("000").x) + pad);
        ImGui::TableSetupColumn(quantity.c_str(), ImGuiTableColumnFlags_WidthFixed,
                                std::max(ImGui::CalcTextSize(quantity.c_str()).x, ImGui::CalcTextSize("-0.0000e+00").x) + pad);
        ImGui::TableSetupColumn(verdict.c_str());
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
                                   words.say(algo::term(*f.facing)).c_str());
            else
                ImGui::TextColored(dim_text, "%s", tr("backface.not_tested").c_str());
        }
        ImGui::EndTable();
    }
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
