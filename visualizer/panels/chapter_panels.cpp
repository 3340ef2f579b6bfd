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
        // one button per choice, as many to a row as fit (none cut); a choice that already starts with its own
        // number ("3. R wholly behind Q's plane") is not numbered twice
        const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
        for (std::size_t i = 0; i < q->choices.size(); ++i) {
            const std::string number = std::to_string(i + 1);
            const std::string& choice = q->choices[i];
            const bool numbered = choice.rfind(number + ".", 0) == 0;
            const std::string label = numbered ? choice : number + "  " + choice;
            const float button_width = ImGui::CalcTextSize(label.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x;
            if (i > 0) {
                ImGui::SameLine();
                if (ImGui::GetCursorScreenPos().x + button_width > right_edge) ImGui::NewLine();
            }
            if (ImGui::Button((label + "##choice" + number).c_str())) out.answer = choice;
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
