// SPDX-License-Identifier: MIT
#include "panels/lesson_menu.h"

#include <filesystem>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "state/strings.h"

namespace hsr::viz {

void lesson_menu(const std::vector<CourseLesson>& course, const std::string& playing, std::size_t cursor, const std::string& language,
                 const PanelLayout& l, UiActions& out) {
    const float view_w = l.width - l.side, view_h = l.height - l.bottom;
    ImGui::SetNextWindowPos(ImVec2(view_w / 2, view_h / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(view_w - 24, 44 * ImGui::GetFontSize()), view_h - 24));
    ImGui::Begin((tr("menu.title") + "###lessons").c_str(), nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize);
    const std::string now = std::filesystem::path(playing).filename().string();
    for (const CourseTopic& topic : topics_of(course)) {
        ImGui::Spacing();
        ImGui::TextColored(ImVec4(0.94f, 0.89f, 0.26f, 1), "%s", window_strings().name(topic.name).c_str());
        for (const CourseLesson* lesson : topic.lessons) {
            const std::size_t index = std::size_t(lesson - course.data());
            const bool here = lesson->file == now;
            std::string label = lesson->file.substr(0, 2) + "  " + in_language(lesson->titles, language, lesson->languages) +
                                (here ? "   " + tr("menu.playing") : std::string());
            ImGui::PushID(int(index));
            if (index == cursor) ImGui::SetScrollHereY(0.5f);
            if (ImGui::Selectable(label.c_str(), index == cursor || here)) out.open_lesson = lesson->path;
            std::string after;
            for (const std::string& p : lesson->prerequisites) after += (after.empty() ? "" : " ") + p.substr(0, 2);
            const std::string about = !lesson->problem.empty() ? tr("menu.broken", {{"problem", lesson->problem}})
                                      : after.empty()          ? tr("menu.difficulty", {{"difficulty", std::to_string(lesson->difficulty)}})
                                                               : tr("menu.difficulty_after", {{"difficulty", std::to_string(lesson->difficulty)}, {"after", after}});
            ImGui::Indent(2.4f * ImGui::GetFontSize());
            ImGui::TextColored(dim_text, "%s", about.c_str());
            ImGui::Unindent(2.4f * ImGui::GetFontSize());
            ImGui::PopID();
        }
    }
    ImGui::Separator();
    ImGui::TextColored(dim_text, "%s", tr("menu.how").c_str());
    ImGui::End();
}

}  // namespace hsr::viz
