#include "panels/chapter_panels.h"

#include <string>

#include <imgui.h>

#include "panels/panel_style.h"

namespace hsr::viz {

void chapter_lesson_panel(const Session& s, const Classroom& room, const std::string& detail, const PanelLayout& l) {
    const Lesson& lesson = s.lesson();
    place_in_column(l, 0);
    ImGui::Begin("Lesson", nullptr, fixed);
    ImGui::TextWrapped("%s", lesson.title.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    ImGui::TextWrapped("%s  ·  difficulty %d  ·  %s", std::string(lesson.algorithm.id).c_str(), lesson.difficulty, detail.c_str());
    ImGui::PopStyleColor();
    ImGui::Separator();
    if (const auto c = room.chapter(s)) {
        const Chapter& ch = lesson.chapters[*c];
        ImGui::TextColored(ImVec4(0.94f, 0.89f, 0.26f, 1), "%zu/%zu  %s", *c + 1, lesson.chapters.size(), ch.title.c_str());
        ImGui::TextWrapped("%s", in_language(ch.narration, room.language(), lesson.languages).c_str());
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
        ImGui::TextWrapped("%s", lesson.summary.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::PushStyleColor(ImGuiCol_Text, dim_text);
    ImGui::TextWrapped("PgUp/PgDn chapters · L language (%s)%s", room.language().c_str(),
                       room.questions() ? (" · score " + std::to_string(room.right()) + " of " + std::to_string(room.answered()) +
                                           " answered, " + std::to_string(room.questions()) + " questions")
                                              .c_str()
                                        : "");
    ImGui::PopStyleColor();
    ImGui::End();
}

void question_panel(const Session& s, const Classroom& room, float x, float y, float w, float h, UiActions& out) {
    const Lesson& lesson = s.lesson();
    const Question* q = room.open_question(s);
    const auto verdict = room.verdict(s);
    if (!q && !verdict) return;
    const float width = std::min(w - 24, 520.0f);
    ImGui::SetNextWindowPos(ImVec2(x + 12, y + h - 12), ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(width, 0));
    ImGui::Begin("Question", nullptr, fixed | ImGuiWindowFlags_AlwaysAutoResize);
    if (q) {
        ImGui::TextWrapped("%s", in_language(q->ask, room.language(), lesson.languages).c_str());
        for (std::size_t i = 0; i < q->choices.size(); ++i) {
            if (i % 3) ImGui::SameLine();
            if (ImGui::Button((std::to_string(i + 1) + "  " + q->choices[i]).c_str())) out.answer = q->choices[i];
        }
        ImGui::TextColored(dim_text, "keys 1 to %zu; the machine's next event will tell", q->choices.size());
    } else {
        if (verdict->revealed)
            ImGui::TextColored(dim_text, "Shown before it was answered: no score.");
        else
            ImGui::TextColored(verdict->right ? ImVec4(0.35f, 0.8f, 0.55f, 1) : bit_set, "%s", verdict->right ? "Right." : "Not quite.");
        ImGui::TextWrapped("The machine: %s (%s)", verdict->answer.c_str(), verdict->because.c_str());
    }
    ImGui::End();
}

}  // namespace hsr::viz
