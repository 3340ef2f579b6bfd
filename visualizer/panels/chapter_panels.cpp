// SPDX-License-Identifier: MIT
#include "panels/chapter_panels.h"

#include <cctype>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

const ImVec4 chapter_colour(0.94f, 0.89f, 0.26f, 1);
const ImVec4 question_title(0.94f, 0.89f, 0.26f, 1);

// The lesson's end: the score and the next lesson to open (kept short: the column gives the room to what it built).
void end_card(const Classroom& room, const CourseLesson* next, UiActions& out) {
    if (room.questions() > 0)
        wrapped_text(tr("chapters.end_score", {{"right", std::to_string(room.right())},
                                               {"answered", std::to_string(room.answered())},
                                               {"questions", std::to_string(room.questions())}}));
    else
        wrapped_text(tr("chapters.no_questions"));
    if (next) wrapped_text(tr("chapters.next", {{"title", in_language(next->titles, room.window_language(), next->languages)}}), dim_text);
    if (next && ImGui::Button((tr("chapters.next_lesson") + "###next lesson").c_str())) out.next_lesson = 1;
    if (next) ImGui::SameLine();
    if (ImGui::Button((tr("chapters.all_lessons") + "###all lessons").c_str())) out.toggle_menu = true;
}

}  // namespace

void chapter_lesson_panel(const Session& s, const Classroom& room, const std::string& detail, const PanelLayout& l) {
    const Lesson& lesson = s.lesson();
    begin_column_box(l, Box::lesson, tr("box.lesson").c_str());
    wrapped_text(in_language(lesson.titles, room.language(), lesson.languages));
    // the algorithm, the difficulty and the view's caption: not while a question is open, when the column is fullest
    // and the chapter's words above the question must be read whole (two or three lines back for them)
    if (!room.open_question(s))
        wrapped_text(tr("box.lesson_line", {{"algorithm", std::string(lesson.algorithm.id)}, {"difficulty", std::to_string(lesson.difficulty)}, {"detail", detail}}),
                     dim_text);
    ImGui::Separator();
    if (const auto c = room.chapter(s)) {
        const Chapter& ch = lesson.chapters[*c];
        wrapped_text(std::to_string(*c + 1) + "/" + std::to_string(lesson.chapters.size()) + "  " + in_language(ch.titles, room.language(), lesson.languages), chapter_colour);
        wrapped_text(reflow(in_language(ch.narration, room.language(), lesson.languages)));
    } else {
        wrapped_text(reflow(in_language(lesson.summaries, room.language(), lesson.languages)), dim_text);
    }
    end_column_box(l, Box::lesson);
}

std::string language_hint(const Classroom& room) {
    // the student's choice; when the lesson is not narrated in it, which language it is narrated in
    const std::string& chosen = room.window_language();
    return chosen == room.language() ? chosen : tr("chapters.narrated_in", {{"chosen", chosen}, {"narration", room.language()}});
}

void question_panel(const Session& s, const Classroom& room, const CourseLesson* next, const PanelLayout& l, UiActions& out) {
    const Lesson& lesson = s.lesson();
    const Question* q = room.open_question(s);
    const auto verdict = room.verdict(s);
    const bool finished = !q && s.complete() && s.cursor() >= s.known();
    if (!q && !verdict && !finished) return;
    // a title bar in the chapter colour: the box the class is asked to look at
    ImGui::PushStyleColor(ImGuiCol_TitleBg, question_title);
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, question_title);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.08f, 0.08f, 0.1f, 1));
    // the title says the score so far (the lesson box keeps its room for the chapter's words)
    const StringValues score = {{"right", std::to_string(room.right())},
                                {"answered", std::to_string(room.answered())},
                                {"questions", std::to_string(room.questions())}};
    const std::string title = tr(q ? "box.question" : finished ? "box.end" : "box.answer") +
                              (finished ? std::string() : tr(room.answered() ? "chapters.title_score" : "chapters.title_questions", score));
    begin_column_box(l, Box::question, (title + "###question").c_str());
    ImGui::PopStyleColor(3);
    if (q) {
        wrapped_text(in_language(q->ask, room.language(), lesson.languages));
        // one button per choice, as many to a row as fit (none cut); a choice that already starts with its own
        // number ("3. R wholly behind Q's plane") is not numbered twice
        const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
        for (std::size_t i = 0; i < q->choices.size(); ++i) {
            const std::string number = std::to_string(i + 1);
            const std::string& choice = q->choices[i];
            const std::string shown = window_strings().word(choice);  // "entering" in the student's language
            const bool numbered = choice.rfind(number + ". ", 0) == 0;  // "1. x extents apart", not "1.0"
            // a choice numbered otherwise by the notes ("3'. Q wholly behind R's plane", the seventh choice) keeps its
            // own number in front and its key after it, in brackets: not two numbers side by side
            const std::size_t dot = choice.find(". ");
            const bool own_number = !numbered && dot != std::string::npos && dot <= 3 && std::isdigit(static_cast<unsigned char>(choice[0]));
            // a choice that is itself a number ("0", "4") gets its key in brackets, so that "1  0" does not read as 10
            const bool number_choice = !choice.empty() && (std::isdigit(static_cast<unsigned char>(choice[0])) || choice[0] == '-');
            const std::string label = numbered     ? shown
                                      : own_number ? shown + "  [" + number + "]"
                                      : number_choice ? "[" + number + "]  " + shown
                                                      : number + "  " + shown;
            const float button_width = ImGui::CalcTextSize(label.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x;
            if (i > 0) {
                ImGui::SameLine();
                if (ImGui::GetCursorScreenPos().x + button_width > right_edge) ImGui::NewLine();
            }
            if (ImGui::Button((label + "##choice" + number).c_str())) out.answer = choice;
        }
    } else if (verdict) {
        if (verdict->revealed)
            wrapped_text(tr("chapters.shown_before"), dim_text);
        else
            wrapped_text(tr(verdict->right ? "chapters.right" : "chapters.not_quite"), verdict->right ? ImVec4(0.35f, 0.8f, 0.55f, 1) : bit_set);
        // the deciding event's sentence in the language the window speaks (the verdict keeps the English)
        std::string because = verdict->because;
        if (const auto c = room.chapter(s); c && room.script() && room.script()->places()[*c].answered)
            because = s.spoken(*room.script()->places()[*c].answered - 1);
        wrapped_text(tr("chapters.machine", {{"answer", window_strings().word(verdict->answer)}, {"because", because}}));
    }
    if (finished) end_card(room, next, out);
    end_column_box(l, Box::question);
}

}  // namespace hsr::viz
