// SPDX-License-Identifier: MIT
#include "panels/depth_sort_panels.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

// The tests tried on the pair under examination, one row each (the swapped retries of 3 and 4 after the five),
// scrolled so that the latest is in sight.
namespace {

std::string extent(double lo, double hi) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.2f,%.2f", lo, hi);
    return buffer;
}

std::string numbers_of(const algo::TestTried& t) {
    switch (t.test) {
        case algo::OrderTest::x_extents:
        case algo::OrderTest::y_extents: return tr("depth_sort.extents", {{"r", extent(t.a, t.b)}, {"q", extent(t.c, t.d)}});
        case algo::OrderTest::projections: return tr(t.a != 0 ? "depth_sort.overlap" : "depth_sort.separated");
        default: {
            const auto count = [](double x) { return std::to_string(static_cast<long long>(x)); };
            return tr("depth_sort.sides", {{"far", count(t.a)}, {"near", count(t.b)}, {"on", count(t.c)}});
        }
    }
}

}  // namespace

// The tests tried on the pair under examination, one row each (the swapped retries of 3 and 4 after the five),
// scrolled so that the latest is in sight. The names and the numbers side by side when the box is wide enough for
// them whole, else the latest test's numbers under its name: nothing is cut at any scale.
void depth_sort_state_panel(const DepthSortSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("depth_sort.table") + "###decision table").c_str());
    const DepthSortView& v = s.view();
    if (v.r < 0) {
        const StringValues counts = {{"drawn", std::to_string(v.drawn.size())}, {"moves", std::to_string(v.moves)},
                                     {"splits", std::to_string(v.splits)}, {"front", std::to_string(v.front.size())},
                                     {"never", std::to_string(v.left)}};
        // front to back, the sorted list is drawn from its near end and may stop early: say how many were drawn
        wrapped_text(!v.done ? tr("depth_sort.no_pair") : tr(v.front_to_back ? "depth_sort.all_sorted_front" : "depth_sort.all_drawn", counts),
                     dim_text);
    } else if (v.tests.empty()) {
        wrapped_text(tr("depth_sort.pair", {{"r", std::to_string(v.r)}, {"q", std::to_string(v.q)}}));
    }
    ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(4, 1));
    const auto width_of = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
    float names = 0, verdict = std::max(width_of(tr("depth_sort.yes")), width_of(tr("depth_sort.no"))), numbers = 0;
    for (const algo::OrderTest t : {algo::OrderTest::x_extents, algo::OrderTest::y_extents, algo::OrderTest::r_behind_q,
                                    algo::OrderTest::q_in_front_of_r, algo::OrderTest::projections,
                                    algo::OrderTest::q_behind_r, algo::OrderTest::r_in_front_of_q})
        names = std::max(names, width_of(window_strings().say(algo::term(t))));
    std::vector<std::string> row_numbers;
    for (const algo::TestTried& t : v.tests) row_numbers.push_back(numbers_of(t)), numbers = std::max(numbers, width_of(row_numbers.back()));
    // the numbers beside the verdict where the row's fit, else under the test's name; only two columns when even the
    // shortest numbers do not fit beside the names
    float shortest = numbers;
    for (const std::string& n : row_numbers) shortest = std::min(shortest, width_of(n));
    const float pad = 3 * 2 * 4 + 2 * ImGui::GetStyle().ItemSpacing.x;
    const float room = ImGui::GetContentRegionAvail().x - names - verdict - pad;
    const bool three = shortest <= room;
    if (!v.tests.empty() && ImGui::BeginTable("tests", three ? 3 : 2, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("test", ImGuiTableColumnFlags_WidthFixed, names);
        ImGui::TableSetupColumn("verdict", ImGuiTableColumnFlags_WidthFixed, verdict);
        if (three) ImGui::TableSetupColumn("numbers", ImGuiTableColumnFlags_WidthStretch);
        for (std::size_t k = 0; k < v.tests.size(); ++k) {
            const algo::TestTried& t = v.tests[k];
            const std::string& n = row_numbers[k];
            const bool beside = three && width_of(n) <= room;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            wrapped_text(window_strings().say(algo::term(t.test)));
            // numbers that do not fit beside go under the name of the test just tried only: the rows above keep one
            // line each, so that the pair's whole table fits its box (the extents are also the inset's bars)
            if (!beside && k + 1 == v.tests.size()) wrapped_text("    " + n, dim_text);
            ImGui::TableNextColumn();
            ImGui::TextColored(t.passed ? ImVec4(0.35f, 0.8f, 0.55f, 1) : bit_set, "%s", tr(t.passed ? "depth_sort.yes" : "depth_sort.no").c_str());
            if (three) {
                ImGui::TableNextColumn();
                if (beside) ImGui::TextUnformatted(n.c_str());
            }
        }
        ImGui::SetScrollHereY(1.0f);
        ImGui::EndTable();
    }
    ImGui::PopStyleVar();
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
