// SPDX-License-Identifier: MIT
#include "panels/perspective_panels.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "core/events.h"
#include "panels/panel_style.h"
#include "panels/state_legend.h"
#include "panels/view_side_box.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

std::string f(double value) { return algo::format_number(value + 0.0); }  // + 0: no "−0"
std::string n(std::uint64_t value) { return std::to_string(value); }

// Three significant digits: the table is narrow, the narration gives six.
std::string short_number(double value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", value + 0.0);
    return buf;
}

void point_table(const PerspectiveView& v) {
    const auto width = [](const char* t) { return ImGui::CalcTextSize(t).x; };
    const std::string eye = tr("transform.eye_space");
    if (!ImGui::BeginTable("points", 6, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) return;
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, width("P00"));
    ImGui::TableSetupColumn(eye.c_str());
    for (const char* name : {"w", "x′", "y′", "z′"}) ImGui::TableSetupColumn(name, ImGuiTableColumnFlags_WidthFixed, width("-0.000"));
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < v.input->points.size(); ++i) {
        const algo::Vec3 p = v.input->points[i];
        ImGui::TableNextRow();
        if (v.pair && (v.pair->a == i || v.pair->b == i)) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
        ImGui::TableNextColumn();
        ImGui::Text("P%zu", i);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("(%s, %s, %s)", short_number(p.x).c_str(), short_number(p.y).c_str(), short_number(p.z).c_str());
        if (const auto& t = v.transformed[i]) {
            for (const double value : {t->w, t->nx, t->ny, t->nz}) {
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(short_number(value).c_str());
            }
        } else if (v.left_out[i]) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted("—");
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(tr("transform.left_out").c_str());
        }
    }
    ImGui::EndTable();
}

void rule_and_legend(const PerspectiveView& v) {
    wrapped_text(tr(v.input->maps.perspective ? "transform.rule" : "transform.rule_orthographic"), dim_text);
    state_legend(transform_colours::all);
}

}  // namespace

void perspective_state_panel(const PerspectiveSession& s, bool table_in_view, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("transform.title") + "###state").c_str());
    const PerspectiveView& v = s.view();
    const bool perspective = v.input->maps.perspective;
    const std::string stage = v.stage == 0 ? tr("transform.stage_eye")
                              : v.stage == 1 ? tr("transform.stage_normalize", {{"percent", n(std::uint64_t(100 * v.s + 0.5))}})
                                             : tr(perspective ? "transform.stage_transform" : "transform.stage_none",
                                                  {{"percent", n(std::uint64_t(100 * v.s + 0.5))}});
    wrapped_text(stage);
    if (v.pair) {
        const algo::PairCompared& p = *v.pair;
        const auto& ta = v.transformed[p.a];
        const auto& tb = v.transformed[p.b];
        const char* before_key = perspective ? "transform.before" : "transform.before_orthographic";
        wrapped_text(tr("transform.pair", {{"a", n(p.a)}, {"b", n(p.b)}}));
        wrapped_text(tr(before_key, {{"rax", f(p.ratio_ax)}, {"ray", f(p.ratio_ay)}, {"rbx", f(p.ratio_bx)}, {"rby", f(p.ratio_by)},
                                     {"same", tr(p.same_before ? "transform.same" : "transform.apart")}}));
        if (ta && tb)
            wrapped_text(tr("transform.after", {{"ax", f(ta->nx)}, {"ay", f(ta->ny)}, {"bx", f(tb->nx)}, {"by", f(tb->ny)},
                                                {"same", tr(p.same_after ? "transform.same" : "transform.apart")}}));
        if (p.same_after && p.nearer >= 0) wrapped_text(tr("transform.nearer", {{"nearer", n(std::uint64_t(p.nearer))}}));
    }
    const std::uint64_t kept = std::uint64_t(std::count_if(v.transformed.begin(), v.transformed.end(), [](const auto& t) { return t.has_value(); }));
    wrapped_text(tr("transform.counts", {{"pairs", n(v.comparisons)}, {"occluding", n(v.occluding.size())},
                                         {"before", n(perspective ? 4 * v.comparisons : 0)}, {"after", n(3 * kept)}}));
    if (!table_in_view) {  // else both are in the view, the rule under the table
        point_table(v);
        rule_and_legend(v);
    }
    end_column_box(l, Box::state);
}

void perspective_points_box(const PerspectiveSession& s, float view_w, float view_h) {
    begin_view_foot_box(tr("transform.points_title") + "###points in the view", view_w, view_h, points_box_share);
    point_table(s.view());
    rule_and_legend(s.view());
    end_view_side_box();
}

}  // namespace hsr::viz
