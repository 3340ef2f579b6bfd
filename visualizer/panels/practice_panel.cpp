// SPDX-License-Identifier: MIT
#include "panels/practice_panel.h"

#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

const ImVec4 practice_title(0.47f, 0.77f, 0.93f, 1);  // sky blue: practice, not the lesson's yellow question
const ImVec4 right_colour(0.35f, 0.8f, 0.55f, 1);

// Topic, level and series: a change starts the series from its first exercise.
void chooser(const practice::PracticeMode& mode, UiActions& out) {
    const auto& all = practice::topics();
    std::size_t topic = mode.topic();
    int level = int(mode.level());
    std::uint64_t series = mode.series();
    bool changed = false;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
    const Strings& words = window_strings();
    if (ImGui::BeginCombo("##topic", words.name(all[topic].title).c_str())) {
        for (std::size_t k = 0; k < all.size(); ++k)
            if (ImGui::Selectable(words.name(all[k].title).c_str(), k == topic)) topic = k, changed = true;
        ImGui::EndCombo();
    }
    ImGui::TextUnformatted(tr("practice.level").c_str());
    for (int l = 1; l <= 3; ++l) {
        ImGui::SameLine();
        if (ImGui::RadioButton(std::to_string(l).c_str(), level == l)) level = l, changed = true;
    }
    ImGui::SameLine();
    ImGui::TextUnformatted(("  " + tr("practice.series")).c_str());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("000000000000").x);
    if (ImGui::InputScalar("##series", ImGuiDataType_U64, &series, nullptr, nullptr, "%llu", ImGuiInputTextFlags_EnterReturnsTrue))
        changed = true;
    if (changed) out.practice_choice = UiActions::PracticeChoice{topic, level, series};
    if (mode.current) {
        ImGui::SameLine();
        ImGui::TextColored(dim_text, "%s", tr("practice.exercise", {{"number", std::to_string(mode.current->index + 1)}}).c_str());
    }
}

// A practice wording in the student's language (the catalogue's [exercise]; English where it has none).
std::string in_words(const practice::Wording& w) {
    const Strings& words = window_strings();
    return practice::said(w, [&](const algo::Saying& s) { return words.pattern("exercise", s); });
}
// A reply or an answer: a choice in the student's language, a number as typed.
std::string reply_text(const practice::Exercise& e, const std::string& english) {
    const practice::Wording* w = e.choice(english);
    return w ? in_words(*w) : english;
}

void choices(const practice::Exercise& e, UiActions& out) {
    const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (std::size_t i = 0; i < e.choices.size(); ++i) {
        // shown in the student's language, answered in the exercise's English
        const std::string label = std::to_string(i + 1) + "  " + in_words(e.offered[i]) + "##practice" + std::to_string(i);
        const float width = ImGui::CalcTextSize(label.c_str(), nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
        if (i > 0) {
            ImGui::SameLine();
            if (ImGui::GetCursorScreenPos().x + width > right_edge) ImGui::NewLine();
        }
        if (ImGui::Button(label.c_str())) out.answer = e.choices[i];
    }
}

}  // namespace

void practice_panel(const practice::PracticeMode& mode, const PanelLayout& l, UiActions& out) {
    ImGui::PushStyleColor(ImGuiCol_TitleBg, practice_title);
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, practice_title);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.08f, 0.08f, 0.1f, 1));
    begin_column_box(l, Box::question, tr("box.practice").c_str());
    ImGui::PopStyleColor(3);
    chooser(mode, out);
    ImGui::Separator();
    if (const auto& e = mode.current) {
        wrapped_text(in_words(e->asked));
        if (mode.waiting()) {
            if (!e->choices.empty()) {
                choices(*e, out);
            } else {
                wrapped_text(tr("practice.typed", {{"typed", mode.typed}}));
                if (ImGui::Button((tr("practice.answer") + "###answer").c_str()) && !mode.typed.empty()) out.answer = mode.typed;
            }
        } else {
            // the deciding event's sentence is the narration's now: the player stands on it
            wrapped_text(tr(*mode.right ? "practice.right" : "practice.not_quite", {{"given", reply_text(*e, mode.given)}}),
                         *mode.right ? right_colour : bit_set);
            if (!*mode.right)
                wrapped_text(tr("practice.machine", {{"answer", reply_text(*e, e->answer)}, {"step", std::to_string(e->deciding_step + 1)}}));
            if (ImGui::Button((tr("practice.next") + "###next exercise").c_str())) out.practice_next = true;
        }
    }
    const practice::TopicScore& s = mode.score();
    wrapped_text(tr("practice.score", {{"right", std::to_string(s.right)},
                                       {"answered", std::to_string(s.answered)},
                                       {"streak", std::to_string(s.streak)},
                                       {"best", std::to_string(s.best_streak)}}),
                 dim_text);
    end_column_box(l, Box::question);
}

}  // namespace hsr::viz
