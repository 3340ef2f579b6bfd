// The ImGui panels of a clipping lesson. Each reads the session and fills in UiActions; none changes state.
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "panels/ui_actions.h"
#include "render/clip_renderer.h"
#include "state/clip_session.h"

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

void lesson_panel(const ClipSession& s, const PanelLayout& layout);
void pseudocode_panel(const ClipSession& s, const PanelLayout& layout);
void state_panel(const ClipSession& s, const PanelLayout& layout);  // outcodes, t values or pipeline stage
void narration_panel(const ClipSession& s, const PanelLayout& layout);
void timeline_panel(const ClipSession& s, const PlaybackState& playback, const PanelLayout& layout, UiActions& out);
void error_panel(const std::string& message, const PanelLayout& layout, UiActions& out);

// Labels of the 3D view, projected with the viewer's camera into the viewport (x, y, w, h in pixels, top-left).
void draw_labels(const std::vector<Label>& labels, const glm::mat4& view_projection, float x, float y, float w, float h);

}  // namespace hsr::viz
