// SPDX-License-Identifier: MIT
// What a clipping lesson shows, as plain data: every primitive with its input and (once clipped) its visible
// part, and the working state of the primitive being clipped. Changed only by reduce(); read by the renderer,
// the panels and the tests.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "clipping/clip_scene.h"
#include "state/cow_vector.h"

namespace hsr::viz {

using algo::ClipEvent;
using algo::Vec4;

enum class PrimitiveKind : unsigned char { point, segment, polygon };
enum class PrimitiveStatus : unsigned char { waiting, clipping, done };

struct PrimitiveState {
    algo::PrimitiveId id;
    PrimitiveKind kind;
    std::vector<Vec4> input;                 // clip space, as the scene gave it
    PrimitiveStatus status = PrimitiveStatus::waiting;
    algo::ClipOutcome outcome = algo::ClipOutcome::rejected;  // valid once done
    std::vector<Vec4> visible;               // clip space, once done
    bool bounded = false;                    // a step bound stopped its machine
};

struct ClipView {
    algo::ClipSpace space = algo::ClipSpace::homogeneous;
    algo::ClipAlgorithm algorithm = algo::ClipAlgorithm::cohen_sutherland;
    CowVector<PrimitiveState> primitives;    // in the order the machine clips them; shared between keyframes
    int active = -1;                         // index of the primitive being clipped

    // The segment being clipped (Cohen–Sutherland, Liang–Barsky): its current ends and their outcodes.
    Vec4 p1{}, p2{};
    algo::Outcode c1{}, c2{};
    bool c1_known = false, c2_known = false;  // computed for the current round
    int round = 0;
    std::optional<algo::ClipPlane> plane;    // the plane in focus
    CowVector<Vec4, 1024> intersections;     // found so far on the active primitive
    double t_enter = 0, t_leave = 1;         // Liang–Barsky, along the input segment

    // Sutherland–Hodgman: the current stage's input and what it has emitted so far.
    CowVector<Vec4, 1024> stage_input, stage_output;  // chunks shared between keyframes, as the primitives are
    int edge = -1;                           // the edge from stage_input[edge] to its successor

    // The intersection just computed, between the ends it was computed on: the panel writes out the notes'
    // equation (3) for it. Cleared by the next step that is not an intersection.
    struct Intersecting {
        algo::ClipPlane plane;
        Vec4 p1, p2;
    };
    std::optional<Intersecting> intersecting;

    bool bound_reached = false;
};

// The view before any event: every primitive of the job waiting, in the order clip_scene visits them.
ClipView initial_view(const algo::ClipJob& job, algo::ClipAlgorithm algorithm);

void reduce(ClipView& view, const ClipEvent& event);
// What copying the view costs (the primitives are shared chunk by chunk between copies).
std::size_t approx_bytes(const ClipView& view);

// The answers the view shows, in the shape the machine returns them (the events are the truth the window shows,
// so a test checks that this equals the machine's own result).
std::vector<algo::PrimitiveClip> answers(const ClipView& view);

}  // namespace hsr::viz
