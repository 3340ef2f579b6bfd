// SPDX-License-Identifier: MIT
// The generic panels of a lesson (any algorithm). Each reads the session and fills in UiActions; none changes state.
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "panels/ui_actions.h"
#include "render/label.h"
#include "state/column_fit.h"
#include "state/label_placement.h"
#include "state/session.h"

namespace hsr::viz {

struct PanelLayout {
    float width, height;  // of the window, in pixels
    float side = 500;     // width of the right-hand column
    float bottom = 96;    // height of the timeline
    ColumnFit* fit = nullptr;  // the column's boxes sized to their content (arranged for this frame)

    // A box of the right-hand column: where the fit put it, or its default share (1280×800: 150, 262, 170, 122)
    // when there is no fit.
    BoxSlot slot(Box b) const {
        if (fit) return fit->slot(b);
        static constexpr float share[] = {150.f / 704, 262.f / 704, 170.f / 704, 122.f / 704, 0};
        const float column = height - bottom;
        float y = 0;
        for (int i = 0; i < int(b); ++i) y += share[i] * column;
        return {y, b == Box::narration ? column - y : share[int(b)] * column};
    }
};

// `detail`: a line about the setting (the clip volume, the splitter rule, …)
void lesson_panel(const Session& s, const std::string& detail, const PanelLayout& layout);
void pseudocode_panel(const Session& s, const PanelLayout& layout);
void narration_panel(const Session& s, const PanelLayout& layout);
// A chapter's start on the timeline (yellow when it asks a question); a click seeks there.
struct TimelineMark {
    std::size_t step;
    bool question;
    std::string title;
};
// `question_choices`: while a question waits for an answer, its number of choices (the player holds), else 0.
// `language`: for a lesson with chapters, the language as the keys' hint names it (its PgUp/PgDn and L), else "".
void timeline_panel(const Session& s, const PlaybackState& playback, std::size_t question_choices, const std::string& language,
                    const std::vector<TimelineMark>& marks, const PanelLayout& layout, UiActions& out);
// `stopped`: the opening was stopped (Esc), the file is not at fault.
void error_panel(const std::string& message, bool stopped, const PanelLayout& layout, UiActions& out);

// Labels of the 3D view, projected with the viewer's camera into the viewport (x, y, w, h in pixels, top-left).
void draw_labels(const std::vector<Label>& labels, const glm::mat4& view_projection, float x, float y, float w, float h,
                 const std::vector<ViewRect>& covered = {});

}  // namespace hsr::viz
