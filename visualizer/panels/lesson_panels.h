// The generic panels of a lesson (any algorithm). Each reads the session and fills in UiActions; none changes state.
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "panels/ui_actions.h"
#include "render/label.h"
#include "state/session.h"

namespace hsr::viz {

struct PanelLayout {
    float width, height;  // of the window, in pixels
    float side = 500;     // width of the right-hand column
    float bottom = 96;    // height of the timeline

    // The right-hand column, top to bottom: lesson, pseudocode, state, narration; as shares of its height, so that
    // 1280×800 gives 150, 262, 170 and the rest, and smaller windows shrink every panel alike.
    struct Slot {
        float y, h;
    };
    Slot slot(int panel) const {
        static constexpr float share[] = {150.f / 704, 262.f / 704, 170.f / 704, 122.f / 704};
        const float column = height - bottom;
        float y = 0;
        for (int i = 0; i < panel; ++i) y += share[i] * column;
        return {y, panel == 3 ? column - y : share[panel] * column};
    }
};

// `detail`: a line about the setting (the clip volume, the splitter rule, …)
void lesson_panel(const Session& s, const std::string& detail, const PanelLayout& layout);
void pseudocode_panel(const Session& s, const PanelLayout& layout);
void narration_panel(const Session& s, const PanelLayout& layout);
// `question_choices`: while a question waits for an answer, its number of choices (the player holds), else 0.
void timeline_panel(const Session& s, const PlaybackState& playback, std::size_t question_choices, const PanelLayout& layout,
                    UiActions& out);
void error_panel(const std::string& message, const PanelLayout& layout, UiActions& out);

// Labels of the 3D view, projected with the viewer's camera into the viewport (x, y, w, h in pixels, top-left).
void draw_labels(const std::vector<Label>& labels, const glm::mat4& view_projection, float x, float y, float w, float h);

}  // namespace hsr::viz
