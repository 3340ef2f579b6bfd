// SPDX-License-Identifier: MIT
#include "panels/backface_panels.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/state_legend.h"
#include "panels/view_side_box.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {
// the verdicts in the view's colours (its legend says what they are)
const ImVec4 wrong = colour_of(backface_colours::culled_seen);  // culled, yet seen
const ImVec4 culled = colour_of(backface_colours::culled);
const ImVec4 kept_word(0.35f, 0.8f, 0.55f, 1);  // the kept fill's bluish green, lighter: a word on the dark table
int scrolled_to = -1;                        // the row the table last scrolled to

// Every face: its id, the test's value, what the ray cast saw of it, and the verdict.
void faces_table(const BackfaceView& v) {
    const bool cast = !v.faces.empty() && v.faces.front().seen.has_value();
    const std::string face = tr("backface.face"), verdict = tr("backface.verdict"), seen = tr("backface.seen");
    const std::string quantity = v.test == algo::BackfaceTest::view_vector      ? "v·n"
                                 : v.test == algo::BackfaceTest::plane_equation ? "N·eye + D"
                                                                                : tr("machine.backface.screen_area");
    if (ImGui::BeginTable("faces", cast ? 4 : 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        const float pad = 2 * ImGui::GetStyle().CellPadding.x;  // columns sized to their words, in any language and type size
        const auto fixed_width = [&](const std::string& title, const char* widest) {
            return std::max(ImGui::CalcTextSize(title.c_str()).x, ImGui::CalcTextSize(widest).x) + pad;
        };
        ImGui::TableSetupColumn(face.c_str(), ImGuiTableColumnFlags_WidthFixed, fixed_width(face, "000"));
        ImGui::TableSetupColumn(quantity.c_str(), ImGuiTableColumnFlags_WidthFixed, fixed_width(quantity, "-0.00000"));  // %.4g: "-0.1234", rarely "1.2e-05"
        if (cast) ImGui::TableSetupColumn(seen.c_str(), ImGuiTableColumnFlags_WidthFixed, fixed_width(seen, "00000"));
        ImGui::TableSetupColumn(verdict.c_str());
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < v.faces.size(); ++i) {
            const FaceView& f = v.faces[i];
            ImGui::TableNextRow();
            if (int(i) == v.current) {
                ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
                // the face under test is brought into the box once, when it becomes current (then the box scrolls freely)
                if (scrolled_to != v.current) ImGui::SetScrollHereY(0.5f), scrolled_to = v.current;
            }
            ImGui::TableNextColumn();
            ImGui::Text("%d", f.id);
            ImGui::TableNextColumn();
            if (f.facing) {
                char value[32];
                std::snprintf(value, sizeof value, "%.4g", f.value);
                ImGui::TextUnformatted(number_in_language(value).c_str());
            }
            if (cast) {  // shown once the face is tested: before, it would answer "kept or culled?"
                ImGui::TableNextColumn();
                if (f.facing) ImGui::Text("%zu", *f.seen);
            }
            ImGui::TableNextColumn();
            if (!f.facing) {
                wrapped_text(tr("backface.not_tested"), dim_text);  // wrapped at spaces in a narrow column
                continue;
            }
            const bool kept = *f.facing == algo::Facing::front;
            std::string says = tr(kept ? "backface.kept" : "backface.culled");  // the column's title says what is judged
            if (f.seen && kept && *f.seen == 0) says += " · " + tr("backface.kept_hidden");
            if (f.seen && !kept && *f.seen > 0) says += " · " + tr("backface.culled_seen");
            // wrapped in its cell at spaces only ("behalten · verdeckt!" is wider than the column)
            wrapped_text(says, !kept && f.seen && *f.seen > 0 ? wrong : kept ? kept_word : culled);
        }
        ImGui::EndTable();
    }
}

}  // namespace


void backface_state_panel(const BackfaceSession& s, bool table_in_view, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("backface.title") + "###state").c_str());
    const BackfaceView& v = s.view();
    const Strings& words = window_strings();
    wrapped_text(tr("backface.counts", {{"kept", std::to_string(v.kept)}, {"culled", std::to_string(v.culled)},
                                        {"left", std::to_string(int(v.faces.size()) - v.kept - v.culled)}, {"test", words.say(algo::term(v.test))}}),
                 dim_text);
    const bool cast = !v.faces.empty() && v.faces.front().seen.has_value();
    if (cast && (v.kept_hidden > 0 || v.culled_seen > 0))
        wrapped_text(tr("backface.against_ray_cast", {{"hidden", std::to_string(v.kept_hidden)}, {"seen", std::to_string(v.culled_seen)}}),
                     v.culled_seen > 0 ? wrong : dim_text);
    if (!table_in_view) faces_table(v);
    end_column_box(l, Box::state);
}

void backface_faces_box(const BackfaceSession& s, float view_w, float view_h) {
    begin_view_side_box(tr("backface.title") + "###faces in the view", view_w, view_h, 0, faces_box_share);
    faces_table(s.view());
    end_view_side_box();
}


}  // namespace hsr::viz
