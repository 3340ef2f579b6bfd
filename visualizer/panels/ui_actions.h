// What the user asked for this frame. Panels and keys fill it in; the app carries it out in its update step,
// so panels never change state themselves.
#pragma once

#include <cstddef>
#include <optional>

#include <glm/vec3.hpp>

#include "zbuffer/depth_format.h"

namespace hsr::viz {

struct UiActions {
    bool toggle_play = false;
    bool step = false, step_back = false;              // to the next / previous major event
    bool micro_step = false, micro_step_back = false;  // one event
    bool to_start = false, to_end = false;
    std::optional<std::size_t> seek;
    std::optional<float> speed;  // steps per second while playing
    bool reload = false;
    std::optional<glm::dvec3> move_eye;  // the eye dragged to here (world space)
    std::optional<algo::DepthFormat> depth_format;  // z-buffer lessons: rerun with this format
    std::optional<algo::DepthRange> depth_range;    // z-buffer lessons: rerun with this near and far
    bool toggle_3d = false;                         // z-buffer lessons: the fat pixels, or the scene in 3D
};

struct PlaybackState {
    bool playing = false;
    float speed = 2.0f;        // steps per second
    double since_step = 0.0;   // seconds since the last automatic step
};

}  // namespace hsr::viz
