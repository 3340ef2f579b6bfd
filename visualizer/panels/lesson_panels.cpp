// SPDX-License-Identifier: MIT
// [SECTION] helpers
// [SECTION] lesson, pseudocode, narration
// [SECTION] timeline
// [SECTION] error, labels
#include "panels/lesson_panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "state/chapters.h"
#include "state/label_placement.h"
#include "state/strings.h"

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"

namespace hsr::viz {
namespace {

std::string step_text(const Session& s) {
    const std::string steps = std::to_string(s.known()) + (s.complete() ? "" : "+");
    const bool capped = s.capped() && s.cursor() >= s.known();
    return tr(capped ? "timeline.step_of_capped" : "timeline.step_of", {{"step", std::to_string(s.cursor())}, {"steps", steps}});
}

}  // namespace

// ── [SECTION] lesson, pseudocode, narration ─────────────────────────────────────────────────────────────────
void lesson_panel(const Session& s, const std::string& detail, const PanelLayout& l) {
    begin_column_box(l, Box::lesson, tr("box.lesson").c_str());
    const Lesson& lesson = s.lesson();
    const std::string& language = window_strings().language();
    wrapped_text(lesson.titles.empty() ? lesson.title : in_language(lesson.titles, language, lesson.languages));
    wrapped_text(tr("box.lesson_line", {{"algorithm", std::string(s.lesson().algorithm.id)}, {"difficulty", std::to_string(s.lesson().difficulty)}, {"detail", detail}}),
                 dim_text);
    ImGui::Separator();
    wrapped_text(reflow(lesson.summaries.empty() ? lesson.summary : in_language(lesson.summaries, language, lesson.languages)), dim_text);
    end_column_box(l, Box::lesson);
}

void pseudocode_panel(const Session& s, const PanelLayout& l) {
    // a slot too low for its title and one row (the lesson's end gives the room to its result): no box at all, rather
    // than a title over nothing (and a box of no height is one ImGui would size to its content)
    const float one_row = ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().WindowPadding.y + ImGui::GetTextLineHeightWithSpacing();
    if (l.fit && l.slot(Box::pseudocode).h < one_row) {
        l.fit->keep(Box::pseudocode);
        return;
    }
    begin_column_box(l, Box::pseudocode, tr("box.pseudocode").c_str(), fixed | ImGuiWindowFlags_NoScrollbar);
    if (ImFont* mono = monospace_font()) ImGui::PushFont(mono);
    // A line wider than the box wraps at a space onto rows indented under it, so nothing is cut on the right.
    struct Row {
        std::string text;
        int line;
    };
    std::vector<Row> rows;
    const float width = std::max(ImGui::GetContentRegionAvail().x, 1.0f);
    const auto measure = [](std::string_view t) { return ImGui::CalcTextSize(t.data(), t.data() + t.size()).x; };
    const auto lines = s.pseudocode();
    for (int i = 0; i < int(lines.size()); ++i) {
        const std::string_view line = lines[std::size_t(i)];
        const std::string indent(line.substr(0, std::min(line.find_first_not_of(' '), line.size())));
        const std::string hanging = indent + "    ";
        const auto pieces = wrap_at_spaces(line.substr(indent.size()), width - measure(hanging), measure);
        for (std::size_t k = 0; k < pieces.size(); ++k) rows.push_back({(k == 0 ? indent : hanging) + pieces[k], i});
    }
    // When the rows do not all fit, a window of whole rows around the running line (a third of the way down), and a
    // row at either end saying how many more there are: no row is cut at the top or the bottom.
    const int current = s.current_line();
    const float row_height = ImGui::GetTextLineHeightWithSpacing();
    const ImGuiStyle& style = ImGui::GetStyle();
    const float room = ImGui::GetWindowHeight() - ImGui::GetCursorStartPos().y - style.WindowPadding.y + style.ItemSpacing.y;
    const int fit = std::max(0, int(room / row_height));  // none in a box squeezed to its title: never half a row
    const bool marks = fit >= 3;  // room for a row saying what is above or below, besides the running line
    int first = 0, last = int(rows.size());
    if (last > fit) {
        const auto at = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.line == current; });
        const int running = at == rows.end() ? 0 : int(at - rows.begin());
        first = std::clamp(running - fit / 3, 0, last - fit);
        last = first + fit;
    }
    for (int r = first; r < last; ++r) {
        if (marks && ((r == first && first > 0) || (r == last - 1 && last < int(rows.size())))) {
            const int hidden = r == first ? first + 1 : int(rows.size()) - r;
            ImGui::TextColored(dim_text, "%s", tr(r == first ? "box.more_above" : "box.more_below", {{"lines", std::to_string(hidden)}}).c_str());
            continue;
        }
        const Row& row = rows[std::size_t(r)];
        if (row.line == current) {
            const ImVec2 at = ImGui::GetCursorScreenPos();
            ImGui::GetWindowDrawList()->AddRectFilled(at, ImVec2(at.x + width, at.y + row_height), ImGui::GetColorU32(highlight_bg));
        }
        ImGui::TextUnformatted(row.text.c_str());
    }
    // all rows when there is room; must be seen: the title and five rows (the running one among them), while a
    // question is open three (the running one between the two saying how many more there are)
    auto height_of = [&](std::size_t n) {
        return ImGui::GetCursorStartPos().y + float(n) * row_height - style.ItemSpacing.y + style.WindowPadding.y + 2;
    };
    if (monospace_font()) ImGui::PopFont();
    if (l.fit) l.fit->asked(Box::pseudocode, {height_of(std::min<std::size_t>(rows.size(), 5)), height_of(rows.size()),
                                                   height_of(std::min<std::size_t>(rows.size(), 3))});
    audit_current_window();
    ImGui::End();
}

void narration_panel(const Session& s, const PanelLayout& l) {
    begin_column_box(l, Box::narration, tr("box.narration").c_str());
    ImGui::TextColored(dim_text, "%s", step_text(s).c_str());
    const std::string now = s.narration();
    wrapped_text(now.empty() ? tr("narration.start") : now);
    const float need = column_box_height_so_far();
    // the few events before, faint, newest first: those that fit whole (no line cut at the box's foot, no scrollbar
    // for them); the fit is told how tall all of them are, to give them room when the column has it
    const float bottom = ImGui::GetWindowHeight() - ImGui::GetStyle().WindowPadding.y;
    float full = need;
    bool fits = true;
    for (std::size_t back = 2; back <= 4 && back <= s.cursor(); ++back) {
        const std::string before = s.spoken(s.cursor() - back);
        const float h = wrapped_height(before);
        full += h;
        fits = fits && ImGui::GetCursorPosY() + h - ImGui::GetStyle().ItemSpacing.y <= bottom;
        if (fits) wrapped_text(before, dim_text);
    }
    end_column_box(l, Box::narration, need, full);
}

// ── [SECTION] timeline ──────────────────────────────────────────────────────────────────────────────────────
void timeline_panel(const Session& s, const PlaybackState& playback, std::size_t question_choices, const std::string& language,
                    const std::vector<TimelineMark>& marks, const PanelLayout& l, UiActions& out) {
    place(0, l.height - l.bottom, l.width, l.bottom);
    ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoTitleBar);
    // each button's ImGui id stays the English one, so that a language switch keeps the widgets' state
    const auto button = [](std::string_view key, const char* id) { return ImGui::Button((tr(key) + "###" + id).c_str()); };
    out.to_start |= button("timeline.home", "home");
    ImGui::SameLine();
    out.step_back |= button("timeline.step_back", "step back");
    ImGui::SameLine();
    out.micro_step_back |= button("timeline.micro_back", "micro back");
    ImGui::SameLine();
    out.toggle_play |= button(playback.playing ? "timeline.pause" : "timeline.play", "play");
    ImGui::SameLine();
    out.micro_step |= button("timeline.micro", "micro");
    ImGui::SameLine();
    out.step |= button("timeline.step", "step");
    ImGui::SameLine();
    out.to_end |= button("timeline.end", "end");
    ImGui::SameLine();
    out.toggle_menu |= button("timeline.lessons", "lessons");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(10 * ImGui::GetFontSize());
    float speed = playback.speed;
    if (ImGui::SliderFloat((tr("timeline.speed") + "###speed").c_str(), &speed, 0.25f, 30.0f, "%.2f", ImGuiSliderFlags_Logarithmic)) out.speed = speed;
    ImGui::SameLine();
    // the keys' hint as far as it fits beside the step: whole, shorter, or not at all; while a question waits, why
    // the player does not move on
    const std::string step = step_text(s);
    const float room = ImGui::GetContentRegionAvail().x;
    const std::string keys = question_choices ? "1–" + std::to_string(question_choices) : "";
    std::string line = question_choices   ? tr("timeline.question_waits", {{"step", step}, {"keys", keys}})
                       : !language.empty() ? tr("timeline.keys_chapters", {{"step", step}, {"language", language}})
                                           : tr("timeline.keys", {{"step", step}});
    if (ImGui::CalcTextSize(line.c_str()).x > room && !question_choices && !language.empty())
        line = tr("timeline.keys_chapters_short", {{"step", step}, {"language", language}});
    if (ImGui::CalcTextSize(line.c_str()).x > room)
        line = question_choices ? tr("timeline.question_short", {{"step", step}, {"keys", keys}}) : tr("timeline.keys_short", {{"step", step}});
    if (ImGui::CalcTextSize(line.c_str()).x > room) line = step;
    ImGui::TextColored(question_choices ? ImVec4(0.94f, 0.89f, 0.26f, 1) : dim_text, "%s", line.c_str());

    int cursor = int(s.cursor());
    const int last = int(std::max<std::size_t>(s.known(), 1));
    ImGui::SetNextItemWidth(-1);
    // the slider's printf format: the catalogue's words with any % doubled, then the one %d (a translation can
    // never smuggle in a directive)
    std::string scrub_words = window_strings().text("timeline.scrub");
    for (std::size_t at = scrub_words.find('%'); at != std::string::npos; at = scrub_words.find('%', at + 2)) scrub_words.insert(at, "%");
    const std::string scrub_format = fill(scrub_words, {{"step", "%d"}});
    if (ImGui::SliderInt("##scrub", &cursor, 0, last, scrub_format.c_str())) out.seek = std::size_t(cursor);
    // the chapters' starts under the scrub bar, where ImGui's slider puts those steps' grab (a click seeks there)
    const ImVec2 bar_min = ImGui::GetItemRectMin(), bar_max = ImGui::GetItemRectMax();
    const float pad = 2, width = bar_max.x - bar_min.x - 2 * pad;
    const float grab = std::max(width / float(last + 1), ImGui::GetStyle().GrabMinSize);
    const float tick = 0.35f * ImGui::GetFontSize();
    for (std::size_t k = 0; k < marks.size(); ++k) {
        const TimelineMark& m = marks[k];
        const float x = bar_min.x + pad + grab / 2 + (width - grab) * float(std::min<std::size_t>(m.step, std::size_t(last))) / float(last);
        ImGui::SetCursorScreenPos(ImVec2(x - tick, bar_max.y + 1));
        ImGui::PushID(int(k));
        if (ImGui::InvisibleButton("mark", ImVec2(2 * tick, 2 * tick))) out.seek = m.step;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s", tr(m.question ? "timeline.mark_question" : "timeline.mark",
                                       {{"title", m.title}, {"step", std::to_string(m.step)}}).c_str());
        ImGui::PopID();
        const ImU32 colour = ImGui::GetColorU32(m.question ? ImVec4(0.94f, 0.89f, 0.26f, 1) : ImVec4(0.85f, 0.85f, 0.9f, 1));
        ImGui::GetWindowDrawList()->AddTriangleFilled(ImVec2(x, bar_max.y + 1), ImVec2(x - tick, bar_max.y + 1 + 2 * tick),
                                                      ImVec2(x + tick, bar_max.y + 1 + 2 * tick), colour);
    }
    ImGui::End();
}

// ── [SECTION] error, labels ─────────────────────────────────────────────────────────────────────────────────
void error_panel(const std::string& message, bool stopped, const PanelLayout& l, UiActions& out) {
    place(40, 40, l.width - 80, 220);
    ImGui::Begin((tr(stopped ? "error.stopped" : "error.broken") + "###error").c_str(), nullptr, fixed);
    ImGui::PushStyleColor(ImGuiCol_Text, bit_set);
    wrapped_text(message);
    ImGui::PopStyleColor();
    ImGui::Separator();
    wrapped_text(tr(stopped ? "error.how_stopped" : "error.how_broken"));
    out.reload |= ImGui::Button((tr(stopped ? "error.open_again" : "error.reload") + "###reload").c_str());
    ImGui::End();
}

void draw_labels(const std::vector<Label>& labels, const glm::mat4& vp, float x, float y, float w, float h, const std::vector<ViewRect>& covered) {
    ImDrawList* d = ImGui::GetBackgroundDrawList();
    // on the screen, in the view; placed from the last given (the element under study is given last) so that
    // no label covers another
    // At most max_labels_shown of them: more cannot be read anyway, and placing each against all placed before is
    // quadratic (a 65,535-polygon scene spent minutes a frame here).
    constexpr std::size_t max_labels_shown = 256;
    std::vector<const Label*> shown;
    std::vector<LabelBox> boxes;
    for (auto it = labels.rbegin(); it != labels.rend() && shown.size() < max_labels_shown; ++it) {
        const glm::vec4 c = vp * glm::vec4(it->world, 1.0f);
        if (c.w <= 1e-6f) continue;
        const float sx = x + (c.x / c.w * 0.5f + 0.5f) * w, sy = y + (0.5f - c.y / c.w * 0.5f) * h;
        if (sx < x || sx > x + w || sy < y || sy > y + h) continue;
        const ImVec2 size = ImGui::CalcTextSize(it->text.c_str());
        shown.push_back(&*it);
        boxes.push_back({sx, sy, size.x, size.y});
    }
    const std::vector<Placed> at = place_labels(boxes, 12, covered);
    for (std::size_t k = 0; k < shown.size(); ++k) {
        if (!at[k].shown) continue;  // no free spot in a crowd of labels
        const Label& label = *shown[k];
        const ImU32 color = ImGui::GetColorU32(ImVec4(label.color.x, label.color.y, label.color.z, 1));
        // on a dark backing of its own, never on the colour of the face under it ("3f" orange on an orange face)
        const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
        const float pad = canvas_px(2);
        // kept inside the view: a label at its right edge would run under the panel column ("p2 000010" cut)
        const float left = std::clamp(at[k].left, x + pad, std::max(x + pad, x + w - size.x - pad));
        // a label moved off its point (a crowd around it) is joined to it by a thin line of its colour
        const float px = boxes[k].x, py = boxes[k].y;
        const float nx = std::clamp(px, left, left + size.x), ny = std::clamp(py, at[k].top, at[k].top + size.y);
        if (std::hypot(nx - px, ny - py) > 1.5f * size.y)
            d->AddLine(ImVec2(px, py), ImVec2(nx, ny), ImGui::GetColorU32(ImVec4(label.color.x, label.color.y, label.color.z, 0.8f)), canvas_px(1));
        d->AddRectFilled(ImVec2(left - pad, at[k].top - pad / 2), ImVec2(left + size.x + pad, at[k].top + size.y + pad / 2),
                         IM_COL32(14, 15, 18, 215), pad);
        d->AddText(ImVec2(left, at[k].top), color, label.text.c_str());
    }
}

}  // namespace hsr::viz
