// SPDX-License-Identifier: MIT
#include "panels/depth_sort_panels.h"

#include <string>

#include <imgui.h>

#include "panels/panel_style.h"

namespace hsr::viz {

// The tests tried on the pair under examination, one row each (the swapped retries of 3 and 4 after the five),
// scrolled so that the latest is in sight.
void depth_sort_state_panel(const DepthSortSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "Decision table");
    const DepthSortView& v = s.view();
    if (v.r < 0) {
        ImGui::TextColored(dim_text, v.done ? "All drawn: %zu polygons, %u moves, %u splits." : "No pair under examination.",
                           v.drawn.size(), v.moves, v.splits);
    } else if (v.tests.empty()) {
        ImGui::Text("R = #%d and Q = #%d overlap in z: the tests come next.", v.r, v.q);
    }
    ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(4, 1));
    if (!v.tests.empty() && ImGui::BeginTable("tests", 3, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("test", ImGuiTableColumnFlags_WidthFixed, 226);
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 28);
        ImGui::TableSetupColumn("numbers");
        for (const algo::TestTried& t : v.tests) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(algo::to_string(t.test)).c_str());
            ImGui::TableNextColumn();
            ImGui::TextColored(t.passed ? ImVec4(0.35f, 0.8f, 0.55f, 1) : bit_set, "%s", t.passed ? "yes" : "no");
            ImGui::TableNextColumn();
            switch (t.test) {
                case algo::OrderTest::x_extents:
                case algo::OrderTest::y_extents: ImGui::Text("R [%.2f,%.2f]  Q [%.2f,%.2f]", t.a, t.b, t.c, t.d); break;
                case algo::OrderTest::projections: ImGui::TextUnformatted(t.a != 0 ? "overlap" : "separated"); break;
                default: ImGui::Text("far %g · near %g · on %g", t.a, t.b, t.c);
            }
        }
        ImGui::SetScrollHereY(1.0f);
        ImGui::EndTable();
    }
    ImGui::PopStyleVar();
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
