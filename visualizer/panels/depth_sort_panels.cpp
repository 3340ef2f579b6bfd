#include "panels/depth_sort_panels.h"

#include <string>

#include <imgui.h>

#include "panels/panel_style.h"

namespace hsr::viz {

void depth_sort_state_panel(const DepthSortSession& s, const PanelLayout& l) {
    place_in_column(l, 2);
    const DepthSortView& v = s.view();
    ImGui::Begin("Decision table", nullptr, fixed);
    std::string list = "list:";
    for (std::uint32_t i : v.list) list += " #" + std::to_string(i);
    ImGui::TextColored(dim_text, "%zu drawn · %u moves · %u splits · %s", v.drawn.size(), v.moves, v.splits, list.c_str());
    if (v.r >= 0 && ImGui::BeginTable("tests", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY)) {
        ImGui::TableSetupColumn("test", ImGuiTableColumnFlags_WidthFixed, 250);
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 36);
        ImGui::TableSetupColumn("numbers");
        ImGui::TableHeadersRow();
        for (const algo::TestTried& t : v.tests) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(algo::to_string(t.test)).c_str());
            ImGui::TableNextColumn();
            ImGui::TextColored(t.passed ? ImVec4(0.35f, 0.8f, 0.55f, 1) : bit_set, "%s", t.passed ? "yes" : "no");
            ImGui::TableNextColumn();
            switch (t.test) {
                case algo::OrderTest::x_extents:
                case algo::OrderTest::y_extents: ImGui::Text("R [%.3g, %.3g]  Q [%.3g, %.3g]", t.a, t.b, t.c, t.d); break;
                case algo::OrderTest::projections: ImGui::TextUnformatted(t.a != 0 ? "overlap" : "separated"); break;
                default: ImGui::Text("far %g · near %g · on %g", t.a, t.b, t.c);
            }
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace hsr::viz
