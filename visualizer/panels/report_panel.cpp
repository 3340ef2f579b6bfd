#include "panels/report_panel.h"

#include <imgui.h>

namespace hsr::viz {

void report_panel(const std::vector<analysis::Measurement>& rows, const PanelLayout& l) {
    const float w = l.width - l.side - 24, h = l.height - l.bottom - 24;
    ImGui::SetNextWindowPos(ImVec2(12, 12), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
    ImGui::Begin("Error against run time (R)", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize);
    if (rows.empty()) {
        ImGui::TextDisabled("Nothing to measure for this algorithm.");
        ImGui::End();
        return;
    }
    ImGui::PushTextWrapPos(w - 16);
    ImGui::TextDisabled("Measured just now on small scenes (hsrviz report --quick); the error: %s.", rows.front().error_name.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::BeginTable("report", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("method", ImGuiTableColumnFlags_WidthStretch, 3);
        ImGui::TableSetupColumn("setting", ImGuiTableColumnFlags_WidthStretch, 3);
        ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthStretch, 1);
        ImGui::TableSetupColumn("error", ImGuiTableColumnFlags_WidthStretch, 1.2f);
        ImGui::TableSetupColumn(rows.front().wrong_name.c_str(), ImGuiTableColumnFlags_WidthStretch, 1.4f);
        ImGui::TableHeadersRow();
        for (const analysis::Measurement& m : rows) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(m.method.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(m.setting.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3g", m.median_ms);
            ImGui::TableNextColumn();
            ImGui::Text("%.3g", m.error);
            ImGui::TableNextColumn();
            if (m.wrong_must_be_zero && m.wrong != 0) ImGui::TextColored(ImVec4(0.84f, 0.37f, 0, 1), "%llu (must be 0)", (unsigned long long)m.wrong);
            else ImGui::Text("%llu", (unsigned long long)m.wrong);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace hsr::viz
