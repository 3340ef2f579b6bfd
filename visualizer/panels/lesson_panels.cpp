// [SECTION] helpers
// [SECTION] lesson, pseudocode, narration
// [SECTION] timeline
// [SECTION] error, labels
#include "panels/lesson_panels.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "panels/panel_style.h"

namespace hsr::viz {
namespace {

std::string step_text(const Session& s) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "step %zu of %zu%s", s.cursor(), s.known(), s.complete() ? "" : "+");
    return buf;
}

}  // namespace

// ── [SECTION] lesson, pseudocode, narration ─────────────────────────────────────────────────────────────────
void lesson_panel(const Session& s, const std::string& detail, const PanelLayout& l) {
    place_in_column(l, 0);
    ImGui::Begin("Lesson", nullptr, fixed);
    ImGui::TextWrapped("%s", s.lesson().title.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    ImGui::TextWrapped("%s  ·  difficulty %d  ·  %s", std::string(s.lesson().algorithm.id).c_str(),
                       s.lesson().difficulty, detail.c_str());
    ImGui::PopStyleColor();
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    ImGui::TextWrapped("%s", s.lesson().summary.c_str());
    ImGui::PopStyleColor();
    ImGui::End();
}

void pseudocode_panel(const Session& s, const PanelLayout& l) {
    place_in_column(l, 1);
    ImGui::Begin("Pseudocode", nullptr, fixed | ImGuiWindowFlags_HorizontalScrollbar);
    const auto lines = s.pseudocode();
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

void narration_panel(const Session& s, const PanelLayout& l) {
    place_in_column(l, 3);
    ImGui::Begin("Narration", nullptr, fixed);
    ImGui::TextColored(dim_text, "%s", step_text(s).c_str());
    const std::string now = s.narration();
    ImGui::TextWrapped("%s", now.empty() ? "Press Space to play, or → to take one step." : now.c_str());
    // the few events before, faint, newest first
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    for (std::size_t back = 2; back <= 4 && back <= s.cursor(); ++back)
        ImGui::TextWrapped("%s", s.sentence(s.cursor() - back).c_str());
    ImGui::PopStyleColor();
    ImGui::End();
}

// ── [SECTION] timeline ──────────────────────────────────────────────────────────────────────────────────────
void timeline_panel(const Session& s, const PlaybackState& playback, std::size_t question_choices, const PanelLayout& l, UiActions& out) {
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
    // the keys' hint as far as it fits beside the step: whole, shorter, or not at all; while a question waits, why
    // the player does not move on
    const std::string step = step_text(s);
    const float room = ImGui::GetContentRegionAvail().x;
    const std::string keys = question_choices ? "1–" + std::to_string(question_choices) : "";
    std::string line = question_choices ? step + "   a question waits: answer it (" + keys + ") and the machine tells"
                                        : step + "   Space play · ←/→ step · Shift micro-step · Home/End";
    if (ImGui::CalcTextSize(line.c_str()).x > room)
        line = question_choices ? step + "   answer the question: " + keys : step + "   Space · ←/→ · F1 keys";
    if (ImGui::CalcTextSize(line.c_str()).x > room) line = step;
    ImGui::TextColored(question_choices ? ImVec4(0.94f, 0.89f, 0.26f, 1) : dim_text, "%s", line.c_str());

    int cursor = int(s.cursor());
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderInt("##scrub", &cursor, 0, int(std::max<std::size_t>(s.known(), 1)), "step %d"))
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
