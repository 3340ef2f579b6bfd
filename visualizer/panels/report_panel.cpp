// SPDX-License-Identifier: MIT
#include "panels/report_panel.h"

#include <cstdio>

#include <imgui.h>

namespace hsr::viz {

void report_panel(const std::vector<analysis::Measurement>& rows, std::optional<float> measuring, const PanelLayout& l,
                  UiActions& out) {
    const float w = l.width - l.side - 24, h = l.height - l.bottom - 24;
    ImGui::SetNextWindowPos(ImVec2(12, 12), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
    ImGui::Begin("Error against run time (R)", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize);
    if (measuring) {  // measured on a thread of its own: the window goes on drawing, and the student may stop it
        ImGui::PushTextWrapPos(w - 16);
        ImGui::TextUnformatted("Measuring this algorithm's family on small scenes (hsrviz report --quick): each setting is run "
                               "three times and its median time kept, and its answer is compared with the reference.");
        ImGui::PopTextWrapPos();
        char done[32];
        std::snprintf(done, sizeof done, "%.0f %%", double(*measuring) * 100);
        ImGui::ProgressBar(*measuring, ImVec2(-1, 0), done);
        if (ImGui::Button("Cancel (R or Esc)")) out.cancel_measurement = true;
        ImGui::End();
        return;
    }
    if (rows.empty()) {
        ImGui::TextDisabled("Nothing to measure for this algorithm.");
        ImGui::End();
        return;
    }
    ImGui::PushTextWrapPos(w - 16);
    ImGui::TextDisabled("Measured just now on small scenes (hsrviz report --quick); the error: %s; the count: %s.",
                        rows.front().error_name.c_str(), rows.front().wrong_name.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::BeginTable("report", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("method", ImGuiTableColumnFlags_WidthStretch, 3);
        ImGui::TableSetupColumn("setting", ImGuiTableColumnFlags_WidthStretch, 3);
        ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthStretch, 1);
        ImGui::TableSetupColumn("error", ImGuiTableColumnFlags_WidthStretch, 1.2f);
        ImGui::TableSetupColumn("count", ImGuiTableColumnFlags_WidthStretch, 1.4f);  // named above: a header is not wrapped
        ImGui::TableHeadersRow();
        for (const analysis::Measurement& m : rows) {
            ImGui::TableNextColumn();  // names wrap in their column rather than run under the next one
            ImGui::TextWrapped("%s", m.method.c_str());
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", m.setting.c_str());
            if (!m.extra.empty()) {  // what else it says: splits, slack, what each culling stage left out
                ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
                ImGui::TextWrapped("%s", m.extra.c_str());
                ImGui::PopStyleColor();
            }
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
