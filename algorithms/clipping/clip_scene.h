// SPDX-License-Identifier: MIT
// Clips every primitive of a scene with one algorithm, one after another, as one machine: the machine a clipping
// lesson plays. Points go through point clipping; segments through Cohen–Sutherland or Liang–Barsky; polygons
// through Sutherland–Hodgman. Primitives the chosen algorithm does not clip are left as they are.
#pragma once

#include <vector>

#include "clipping/clip_types.h"
#include "core/steps.h"
#include "scene/scene.h"

namespace hsr::algo {

enum class ClipAlgorithm : std::uint8_t { cohen_sutherland, liang_barsky, sutherland_hodgman };

struct ClipJob {
    ClipSpace space = ClipSpace::homogeneous;
    std::vector<ClipPoint> points;
    std::vector<ClipSegment> segments;
    std::vector<ClipPolygon> polygons;
};

struct PrimitiveClip {
    PrimitiveId id;
    ClipOutcome outcome;
    std::vector<Vec4> vertices;  // the visible part: 1 for a point, 2 for a segment, the polygon's otherwise
    bool bounded = false;
    bool operator==(const PrimitiveClip&) const = default;
};

// The scene in clip space: orthographic cameras give the cube setting, perspective the homogeneous one.
ClipJob clip_job(const Scene& scene);

Steps<ClipEvent, std::vector<PrimitiveClip>> clip_scene(ClipJob job, ClipAlgorithm algorithm, ClipOptions options = {});

}  // namespace hsr::algo
