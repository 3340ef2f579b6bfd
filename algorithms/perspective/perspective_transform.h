// SPDX-License-Identifier: MIT
// The perspective transform and occluding pairs, as the Greek notes give them (chapter 5, "Hidden Surface
// Elimination") and the Brown notes draw them ("Perspective Transformation"):
//
//   two points p1, p2 form an occluding pair when they lie on one projection ray; the nearer occludes the other
//   orthographic projection (rays parallel to z):  x1 = x2 and y1 = y2
//   perspective projection:                         x1/z1 = x2/z2 and y1/z1 = y2/z2   (divisions for every pair)
//   the perspective transform turns the view volume into a box and sends the eye to infinity: after it, every
//   projector is parallel to z, and x′1 = x′2 and y′1 = y′2 decides again, with the divide done once per point
//   (it is done anyway on the way to the screen); it keeps "in front of", straight lines and planes.
//
//   for each point p: transform p to clip space, divide by w            (3 divisions per point)
//   for each pair (a, b): on one projector when x′a = x′b and y′a = y′b   (no division)
//     then the one with the smaller z′ occludes the other
//
// The machine compares every pair both ways, so a student sees the same answer come out of both, and counts what
// each way divides.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "core/plane.h"
#include "core/steps.h"
#include "perspective/transform_events.h"
#include "scene/scene.h"

namespace hsr::algo {

// The maps the warp is drawn with. The picture is eye space scaled by 1/far at the start (so the volume fits the
// unit cube); stage 1 moves it linearly to the canonical volume (perspective: the sides x = ±z and y = ±z, the far
// plane at z = −1; orthographic: already the box); stage 2 is the homogeneous map `transform` of the canonical
// frustum into the box, shown part way as the projective map (1 − s)·I + s·transform. Every map on the way is
// projective, so lines stay lines and planes stay planes at every s. The picture keeps eye space's handedness: its
// z is −z′ (near at +1, far at −1), so the warp turns nothing inside out.
struct ViewVolumeMaps {
    bool perspective = true;
    glm::dmat4 view{1};       // world → eye space (the camera's look-at)
    glm::dmat4 start{1};      // eye space → the picture at the start
    glm::dmat4 normalize{1};  // eye space → the canonical volume (the end of stage 1)
    glm::dmat4 transform{1};  // the canonical volume → the box, homogeneous (the end of stage 2)
};
ViewVolumeMaps view_volume_maps(const Camera& camera);

// Where the picture draws an eye-space point at `stage` (0: the start, 1, 2), `s` of the way through it. Nothing
// where the point's w is not positive there (the eye itself at the end of stage 2: it has gone to infinity).
std::optional<Vec3> warp(const ViewVolumeMaps& maps, std::uint32_t stage, double s, Vec3 eye_point);

// The view volume's eight corners in eye space: near (left bottom, right bottom, right top, left top), then far.
std::vector<Vec3> view_volume_corners(const Camera& camera);

// Equal to within `tolerance` of the larger of 1 and the numbers compared.
bool same_coordinate(double u, double v, double tolerance);
// The numbers the notes compare for an eye-space point: (x/z, y/z) in perspective (two divisions), (x, y) in
// orthographic projection.
glm::dvec2 projector_ratios(Vec3 eye, bool perspective);
// Two points on one projector: their ratios (before the transform) or their x′, y′ (after it) equal.
bool same_projector(glm::dvec2 a, glm::dvec2 b, double tolerance);

struct TransformOptions {
    std::uint64_t max_comparisons = std::uint64_t(1) << 32;  // pairs compared before it stops (step bound)
    double tolerance = 1e-12;
};

struct TransformResult {
    std::vector<std::optional<Vec3>> ndc;  // per scene point: x′, y′, z′ (nothing: left out)
    std::vector<Vec3> eye;                 // per scene point, eye space
    std::vector<std::pair<std::uint32_t, std::uint32_t>> occluding;  // pairs on one projector: (nearer, farther)
    std::uint64_t comparisons = 0;
    bool bounded = false;
};

// The scene's points (world space) through the transform, then every pair compared. The scene is copied into the
// machine: a coroutine outlives the caller's references. InvalidInput when the scene has no points.
Steps<TransformEvent, TransformResult> perspective_transform(Scene scene, TransformOptions options = {});

}  // namespace hsr::algo
