// SPDX-License-Identifier: MIT
#include "page_queries.h"

#include <imgui.h>

#include <cmath>
#include <sstream>

#include "panels/layout_audit.h"
#include "state/trace.h"

namespace hsr::viz {

std::string player_state(const LessonPlay& lp) {
    const Session* s = lp.session();
    if (!s) return {};
    return "step " + std::to_string(s->cursor()) + " of " + std::to_string(s->known()) + (s->complete() ? "" : "+") + ", " +
           (lp.playback.playing ? "playing" : "paused") + (lp.classroom.open_question(*s) ? ", question open" : "") +
           (lp.show_menu ? ", lesson menu open" : s->complete() && s->cursor() >= s->known() ? ", end of the lesson" : "");
}

std::string page_answer(LessonPlay& lp, const Renderer& r, const std::string& question) {
    if (question == "lesson") return lp.path;
    if (question == "error") return lp.error;
    if (question == "language") return lp.classroom.language();
    if (question == "practice") {
        int answered = 0, right = 0;
        for (const auto& [topic, record] : lp.practice.records()) answered += record.answered, right += record.right;
        return "answered " + std::to_string(answered) + ", right " + std::to_string(right);
    }
    if (question == "trace" && lp.session()) return played_trace_text(*lp.session());
    if (question == "type_size") return std::to_string(std::lround(ImGui::GetFontSize()));  // in points
    if (question == "layout") {  // what the last frame's layout audit found (a text cut, a box too small); "" if nothing
        std::string found;
        for (const std::string& problem : layout_problems()) found += (found.empty() ? "" : "; ") + problem;
        return found;
    }
    std::istringstream asked(question);
    std::string word;
    glm::dvec2 p;
    if (asked >> word >> p.x >> p.y && word == "window_point" && std::isfinite(p.x) && std::isfinite(p.y)) {
        const glm::vec2 w = gesture_window_point(lp, r, p);
        return std::to_string(std::lround(w.x)) + " " + std::to_string(std::lround(w.y));
    }
    return "";
}

}  // namespace hsr::viz
