// SPDX-License-Identifier: MIT
#include "panels/report_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "analysis/report_files.h"
#include "state/strings.h"
#include "core/okabe_ito.h"

namespace hsr::viz {

namespace {

// A sweep's rows (run time against P or p) as a log–log chart at the cursor, `w` × `h` points, with its legend under
// it: one line per method, the measured slope beside the notes' claim. The report's SVG draws the same lines.
void growth_chart(const std::vector<analysis::Measurement>& rows, const std::string& family, const std::string& title, float w, float h) {
    const analysis::GrowthLines g = analysis::growth_lines(rows, family);
    const auto colour = [](std::size_t k) {  // the report's chart colours, the first six (its yellow and black are thin on the dark panel)
        const algo::okabe_ito::Rgb8 c = algo::okabe_ito::chart[k % 6];
        return IM_COL32(c.r, c.g, c.b, 255);
    };
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + w);  // the title wraps inside its chart's width
    ImGui::TextUnformatted(title.c_str());
    ImGui::PopTextWrapPos();
    ImDrawList* d = ImGui::GetWindowDrawList();
    const ImVec2 o = ImGui::GetCursorScreenPos();
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const float left = ImGui::CalcTextSize("1e-3").x + 8, bottom = line + 4, top = line / 2;
    const ImU32 grid = IM_COL32(90, 94, 102, 255), dim = IM_COL32(160, 164, 172, 255);
    const auto x_of = [&](double x) { return o.x + left + float((x - g.x_lo) / (g.x_hi - g.x_lo)) * (w - left - 8); };
    const auto y_of = [&](double y) { return o.y + top + float((g.y_hi - y) / (g.y_hi - g.y_lo)) * (h - top - bottom); };
    for (double x = g.x_lo; x <= g.x_hi + 1e-9; x += 1) {
        d->AddLine(ImVec2(x_of(x), y_of(g.y_lo)), ImVec2(x_of(x), y_of(g.y_hi)), grid);
        const std::string label = "1e" + std::to_string(int(x));
        d->AddText(ImVec2(x_of(x) - ImGui::CalcTextSize(label.c_str()).x / 2, y_of(g.y_lo) + 2), dim, label.c_str());
    }
    for (double y = g.y_lo; y <= g.y_hi + 1e-9; y += 1) {
        d->AddLine(ImVec2(x_of(g.x_lo), y_of(y)), ImVec2(x_of(g.x_hi), y_of(y)), grid);
        const std::string label = "1e" + std::to_string(int(y));
        d->AddText(ImVec2(o.x, y_of(y) - line / 2), dim, label.c_str());
    }
    for (std::size_t k = 0; k < g.lines.size(); ++k) {
        std::vector<ImVec2> points;
        for (const analysis::Measurement* m : g.lines[k].rows) points.emplace_back(x_of(std::log10(m->size)), y_of(std::log10(std::max(m->median_ms, 1e-6))));
        d->AddPolyline(points.data(), int(points.size()), colour(k), 0, 2.5f);
        for (const ImVec2 p : points) d->AddCircleFilled(p, 3.5f, colour(k));
    }
    ImGui::Dummy(ImVec2(w, h));
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + w);
    for (std::size_t k = 0; k < g.lines.size(); ++k) {
        const analysis::GrowthLine& l = g.lines[k];
        char slope[16];
        std::snprintf(slope, sizeof slope, "%.2f", l.rows.front()->error);
        const std::size_t colon = l.claimed.find(": ");
        const std::string claim = colon == std::string::npos ? l.claimed : l.claimed.substr(colon + 2);
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colour(k)), "%s",
                           tr("runtime.chart_legend", {{"method", l.method}, {"slope", slope}, {"claim", claim}}).c_str());
    }
    // why a slope measured here may not be the notes' exponent: the sizes a class waits for are small
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(dim), "%s", tr("runtime.chart_caveat").c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace

void report_panel(const std::vector<analysis::Measurement>& rows, std::optional<float> measuring, const PanelLayout& l,
                  UiActions& out) {
    const float w = l.width - l.side - 24, h = l.height - l.bottom - 24;
    ImGui::SetNextWindowPos(ImVec2(12, 12), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1);  // opaque: a canvas under it must not show through the table
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
    if (rows.front().wrong_name.empty())  // a sweep counts nothing that must be 0
        ImGui::TextDisabled("%s", tr("runtime.measured_no_count", {{"error", rows.front().error_name}}).c_str());
    else
        ImGui::TextDisabled("%s", tr("runtime.measured", {{"error", rows.front().error_name}, {"count", rows.front().wrong_name}}).c_str());
    ImGui::PopTextWrapPos();
    const bool sweep = std::any_of(rows.begin(), rows.end(), [](const analysis::Measurement& m) { return m.size > 0; });
    if (sweep) {  // a sweep (the complexity table): each family's run time against its size, charts side by side
        std::vector<std::string> families;
        for (const std::string& f : analysis::families_of(rows))
            if (std::any_of(rows.begin(), rows.end(), [&](const analysis::Measurement& m) { return m.family == f && m.size > 0; })) families.push_back(f);
        const float gap = 16, chart_w = (ImGui::GetContentRegionAvail().x - gap) / 2, chart_h = std::min(h * 0.36f, 320.0f);
        for (std::size_t k = 0; k < families.size(); ++k) {
            if (k % 2 == 1) ImGui::SameLine(0, gap);
            ImGui::BeginGroup();
            growth_chart(rows, families[k], tr("runtime.sweep_chart", {{"family", families[k]}}), chart_w, chart_h);
            ImGui::EndGroup();
        }
    }
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
