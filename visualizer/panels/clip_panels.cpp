// [SECTION] helpers
// [SECTION] lesson, pseudocode, narration
// [SECTION] state: outcodes (Cohen–Sutherland), parameters (Liang–Barsky), pipeline (Sutherland–Hodgman)
// [SECTION] timeline
// [SECTION] error, labels
#include "panels/clip_panels.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "state/clip_pseudocode.h"

namespace hsr::viz {
namespace {

using algo::ClipAlgorithm;
using algo::ClipPlane;

// ── [SECTION] helpers ───────────────────────────────────────────────────────────────────────────────────────
constexpr ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings;

const ImVec4 highlight_bg(0.20f, 0.34f, 0.52f, 1.0f);
const ImVec4 bit_set(0.84f, 0.37f, 0.0f, 1.0f);    // vermillion: outside this plane
const ImVec4 bit_clear(0.18f, 0.20f, 0.24f, 1.0f);
const ImVec4 dim_text(0.62f, 0.64f, 0.68f, 1.0f);

// The second font loaded by the app, if any: monospace, for pseudocode.
ImFont* monospace_font() {
    ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    return atlas->Fonts.Size > 1 ? atlas->Fonts[1] : nullptr;
}

void place(float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
}

void place_in_column(const PanelLayout& l, int panel) {
    const auto slot = l.slot(panel);
    place(l.width - l.side, slot.y, l.side, slot.h);
}

std::string step_text(const ClipSession& s) {
    const auto& p = s.player();
    char buf[96];
    std::snprintf(buf, sizeof buf, "step %zu of %zu%s", p.cursor(), p.known(), p.complete() ? "" : "+");
    return buf;
}

// ── [SECTION] lesson, pseudocode, narration ─────────────────────────────────────────────────────────────────
}  // namespace

void lesson_panel(const ClipSession& s, const PanelLayout& l) {
    place_in_column(l, 0);
    ImGui::Begin("Lesson", nullptr, fixed);
    ImGui::TextWrapped("%s", s.lesson().title.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    ImGui::TextWrapped("%s  ·  difficulty %d  ·  %s", std::string(s.lesson().algorithm.id).c_str(),
                       s.lesson().difficulty,
                       s.space() == algo::ClipSpace::homogeneous ? "clip space −w ≤ x, y, z ≤ w and w ≥ ε = 1e-9"
                                                                 : "the canonical cube −1 ≤ x, y, z ≤ 1");
    ImGui::PopStyleColor();
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    ImGui::TextWrapped("%s", s.lesson().summary.c_str());
    ImGui::PopStyleColor();
    ImGui::End();
}

void pseudocode_panel(const ClipSession& s, const PanelLayout& l) {
    place_in_column(l, 1);
    ImGui::Begin("Pseudocode", nullptr, fixed | ImGuiWindowFlags_HorizontalScrollbar);
    const auto lines = pseudocode(s.algorithm());
    const int current = s.current_line();
    if (ImFont* mono = monospace_font()) ImGui::PushFont(mono);
    for (int i = 0; i < int(lines.size()); ++i) {
        const std::string text(lines[std::size_t(i)]);
        if (i == current) {
            const ImVec2 at = ImGui::GetCursorScreenPos();
            const float w = std::max(ImGui::GetContentRegionAvail().x, ImGui::CalcTextSize(text.c_str()).x);
            ImGui::GetWindowDrawList()->AddRectFilled(
                at, ImVec2(at.x + w, at.y + ImGui::GetTextLineHeightWithSpacing()), ImGui::GetColorU32(highlight_bg));
            ImGui::TextUnformatted(text.c_str());
            ImGui::SetScrollHereY(0.5f);
        } else {
            ImGui::TextUnformatted(text.c_str());
        }
    }
    if (monospace_font()) ImGui::PopFont();
    ImGui::End();
}

void narration_panel(const ClipSession& s, const PanelLayout& l) {
    place_in_column(l, 3);
    ImGui::Begin("Narration", nullptr, fixed);
    ImGui::TextColored(dim_text, "%s", step_text(s).c_str());
    const std::string now = s.narration();
    ImGui::TextWrapped("%s", now.empty() ? "Press Space to play, or → to take one step." : now.c_str());
    // the few events before, faint, newest first
    const auto& p = s.player();
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    for (std::size_t back = 2; back <= 4 && back <= p.cursor(); ++back)
        ImGui::TextWrapped("%s", algo::describe(p.event(p.cursor() - back), s.space()).c_str());
    ImGui::PopStyleColor();
    ImGui::End();
}

// ── [SECTION] state ─────────────────────────────────────────────────────────────────────────────────────────
namespace {

void outcode_table(const ClipView& v) {
    const int columns = algo::plane_count(v.space);
    // the lecture's bit order, bit 1 first; each header names the plane the bit says a point is outside of
    static constexpr const char* headers[] = {"z>", "z<", "y>", "y<", "x>", "x<", "w<ε"};
    if (!ImGui::BeginTable("outcodes", columns + 1, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame))
        return;
    ImGui::TableSetupColumn("bit", ImGuiTableColumnFlags_WidthFixed, 44);
    for (int c = 0; c < columns; ++c) ImGui::TableSetupColumn(headers[c]);
    ImGui::TableHeadersRow();
    const bool both = v.c1_known && v.c2_known;
    const struct {
        const char* name;
        algo::Outcode code;
        bool known;
    } rows[] = {{"p1", v.c1, v.c1_known}, {"p2", v.c2, v.c2_known}, {"OR", v.c1 | v.c2, both}, {"AND", v.c1 & v.c2, both}};
    for (const auto& row : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.name);
        for (int c = 0; c < columns; ++c) {
            ImGui::TableNextColumn();
            const bool set = row.known && row.code.has(algo::all_planes[std::size_t(c)]);
            ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, ImGui::GetColorU32(set ? bit_set : bit_clear));
            ImGui::TextUnformatted(!row.known ? " ·" : set ? " 1" : " 0");
        }
    }
    ImGui::EndTable();
    if (v.plane) ImGui::Text("plane R: %s", std::string(algo::plane_inequality(*v.plane, v.space)).c_str());
}

void parameter_bar(const ClipView& v) {
    ImGui::Text("t_enter = %.4g     t_leave = %.4g", v.t_enter, v.t_leave);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x - 8, h = 22;
    ImDrawList* d = ImGui::GetWindowDrawList();
    d->AddRectFilled(at, ImVec2(at.x + w, at.y + h), ImGui::GetColorU32(bit_clear));
    const float a = at.x + w * float(std::clamp(v.t_enter, 0.0, 1.0)),
                b = at.x + w * float(std::clamp(v.t_leave, 0.0, 1.0));
    if (a <= b) d->AddRectFilled(ImVec2(a, at.y), ImVec2(b, at.y + h), ImGui::GetColorU32(highlight_bg));
    else d->AddRectFilled(ImVec2(b, at.y), ImVec2(a, at.y + h), ImGui::GetColorU32(bit_set));
    d->AddText(ImVec2(at.x + 2, at.y + 2), IM_COL32_WHITE, "0");
    d->AddText(ImVec2(at.x + w - 10, at.y + 2), IM_COL32_WHITE, "1");
    ImGui::Dummy(ImVec2(w, h));
    if (v.plane) ImGui::Text("plane: %s", std::string(algo::plane_inequality(*v.plane, v.space)).c_str());
}

void pipeline(const ClipView& v) {
    for (int k = 0; k < algo::plane_count(v.space); ++k) {
        const ClipPlane r = algo::all_planes[std::size_t(k)];
        const bool current = v.plane == r;
        if (k > 0) ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Button, current ? highlight_bg : bit_clear);
        ImGui::SmallButton(std::string(algo::plane_name(r)).c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Text("stage input: %zu vertices   emitted: %zu", v.stage_input.size(), v.stage_output.size());
    if (v.edge >= 0) ImGui::Text("edge v%d → v%zu", v.edge, (std::size_t(v.edge) + 1) % std::max<std::size_t>(1, v.stage_input.size()));
}

}  // namespace

void state_panel(const ClipSession& s, const PanelLayout& l) {
    place_in_column(l, 2);
    const ClipView& v = s.player().view();
    const char* title = s.algorithm() == ClipAlgorithm::cohen_sutherland ? "Outcodes"
                        : s.algorithm() == ClipAlgorithm::liang_barsky   ? "Parameters"
                                                                         : "Pipeline";
    ImGui::Begin(title, nullptr, fixed);
    switch (s.algorithm()) {
        case ClipAlgorithm::cohen_sutherland: outcode_table(v); break;
        case ClipAlgorithm::liang_barsky: parameter_bar(v); break;
        case ClipAlgorithm::sutherland_hodgman: pipeline(v); break;
    }
    if (v.bound_reached) ImGui::TextColored(bit_set, "a step bound was reached");
    ImGui::End();
}

// ── [SECTION] timeline ──────────────────────────────────────────────────────────────────────────────────────
void timeline_panel(const ClipSession& s, const PlaybackState& playback, const PanelLayout& l, UiActions& out) {
    place(0, l.height - l.bottom, l.width, l.bottom);
    ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoTitleBar);
    out.to_start |= ImGui::Button("|< Home");
    ImGui::SameLine();
    out.step_back |= ImGui::Button("<< Step");
    ImGui::SameLine();
    out.micro_step_back |= ImGui::Button("< micro");
    ImGui::SameLine();
    out.toggle_play |= ImGui::Button(playback.playing ? "  Pause  " : "  Play  ");
    ImGui::SameLine();
    out.micro_step |= ImGui::Button("micro >");
    ImGui::SameLine();
    out.step |= ImGui::Button("Step >>");
    ImGui::SameLine();
    out.to_end |= ImGui::Button("End >|");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(180);
    float speed = playback.speed;
    if (ImGui::SliderFloat("steps/s", &speed, 0.25f, 30.0f, "%.2f", ImGuiSliderFlags_Logarithmic)) out.speed = speed;
    ImGui::SameLine();
    ImGui::TextColored(dim_text, "%s   Space play · ←/→ step · Shift micro-step · Home/End", step_text(s).c_str());

    const auto& p = s.player();
    int cursor = int(p.cursor());
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderInt("##scrub", &cursor, 0, int(std::max<std::size_t>(p.known(), 1)), "step %d"))
        out.seek = std::size_t(cursor);
    ImGui::End();
}

// ── [SECTION] error, labels ─────────────────────────────────────────────────────────────────────────────────
void error_panel(const std::string& message, const PanelLayout& l, UiActions& out) {
    place(40, 40, l.width - 80, 220);
    ImGui::Begin("The lesson could not be loaded", nullptr, fixed);
    ImGui::PushStyleColor(ImGuiCol_Text, bit_set);
    ImGui::TextWrapped("%s", message.c_str());
    ImGui::PopStyleColor();
    ImGui::Separator();
    ImGui::TextWrapped("Fix the file and press F5 (or the button) to load it again.");
    out.reload |= ImGui::Button("Reload (F5)");
    ImGui::End();
}

void draw_labels(const std::vector<Label>& labels, const glm::mat4& vp, float x, float y, float w, float h) {
    ImDrawList* d = ImGui::GetBackgroundDrawList();
    for (const Label& label : labels) {
        const glm::vec4 c = vp * glm::vec4(label.world, 1.0f);
        if (c.w <= 1e-6f) continue;
        const float sx = x + (c.x / c.w * 0.5f + 0.5f) * w, sy = y + (0.5f - c.y / c.w * 0.5f) * h;
        if (sx < x || sx > x + w || sy < y || sy > y + h) continue;
        const ImU32 color = ImGui::GetColorU32(ImVec4(label.color.x, label.color.y, label.color.z, label.color.w));
        d->AddText(ImVec2(sx + 7, sy - 9), IM_COL32(0, 0, 0, 200), label.text.c_str());
        d->AddText(ImVec2(sx + 6, sy - 10), color, label.text.c_str());
    }
}

}  // namespace hsr::viz
