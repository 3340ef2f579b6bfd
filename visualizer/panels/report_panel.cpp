// SPDX-License-Identifier: MIT
#include "panels/report_panel.h"

#include <cstdio>

#include <imgui.h>

#include "state/strings.h"

namespace hsr::viz {

void report_panel(const std::vector<analysis::Measurement>& rows, std::optional<float> measuring, const PanelLayout& l,
                  UiActions& out) {
    const float w = l.width - l.side - 24, h = l.height - l.bottom - 24;
    ImGui::SetNextWindowPos(ImVec2(12, 12), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
    ImGui::Begin((tr("runtime.title") + "###report").c_str(), nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize);
    if (measuring) {  // measured on a thread of its own: the window goes on drawing, and the student may stop it
        ImGui::PushTextWrapPos(w - 16);
        ImGui::TextUnformatted(tr("runtime.measuring").c_str());
        ImGui::PopTextWrapPos();
        char done[32];
        std::snprintf(done, sizeof done, "%.0f %%", double(*measuring) * 100);
        ImGui::ProgressBar(*measuring, ImVec2(-1, 0), done);
        if (ImGui::Button((tr("runtime.cancel") + "###cancel").c_str())) out.cancel_measurement = true;
        ImGui::End();
        return;
    }
    if (rows.empty()) {
        ImGui::TextDisabled("%s", tr("runtime.nothing").c_str());
        ImGui::End();
        return;
    }
    ImGui::PushTextWrapPos(w - 16);
    ImGui::TextDisabled("%s", tr("runtime.measured", {{"error", rows.front().error_name}, {"count", rows.front().wrong_name}}).c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::BeginTable("report", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupScrollFreeze(0, 1);
        const std::string method = tr("runtime.method"), setting = tr("runtime.setting"), error = tr("runtime.error"), count = tr("runtime.count");
        ImGui::TableSetupColumn(method.c_str(), ImGuiTableColumnFlags_WidthStretch, 3);
        ImGui::TableSetupColumn(setting.c_str(), ImGuiTableColumnFlags_WidthStretch, 3);
        ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthStretch, 1);
        ImGui::TableSetupColumn(error.c_str(), ImGuiTableColumnFlags_WidthStretch, 1.2f);
        ImGui::TableSetupColumn(count.c_str(), ImGuiTableColumnFlags_WidthStretch, 1.4f);  // named above: a header is not wrapped
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
            if (m.wrong_must_be_zero && m.wrong != 0) ImGui::TextColored(ImVec4(0.84f, 0.37f, 0, 1), "%s", tr("runtime.must_be_zero", {{"count", std::to_string(m.wrong)}}).c_str());
            else ImGui::Text("%llu", (unsigned long long)m.wrong);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace hsr::viz
