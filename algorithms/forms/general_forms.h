// SPDX-License-Identifier: MIT
// The two general forms of hidden-surface elimination, as the Greek notes give them ("Introduction (4)"):
//
//   object space                                      image space
//   for each primitive                                for each pixel
//   {                                                 {
//       find visible part                                 find closest primitive
//         // compare against all other primitives         render pixel with color of closest primitive
//       render visible part                           }
//   }                                                 complexity O(pP)
//   complexity O(P²)
//
// in a floor plan (flatland): the primitives are the scene's segments in the plane z = 0, the camera stands in that
// plane, and the image is one row of pixels. A segment's image is an interval of the image line u ∈ [−1, 1]; its
// visible part is that interval less what every other segment hides, exactly (along a line 1/z is linear in u, so
// "nearer" changes at most once between two segments). The image-space form casts one projector per pixel and
// intersects it with every segment on its own (no interval is shared), so the two images are two answers to compare.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "core/steps.h"
#include "forms/forms_events.h"
#include "scene/scene.h"

namespace hsr::algo {

// The camera in the plan: the eye, the view direction and the image line's direction (to the right).
struct PlanCamera {
    bool perspective = true;
    glm::dvec2 eye{0}, forward{0, 1}, right{1, 0};
    double tan_half = 1;       // perspective: tan(fov / 2), the image line's half width at depth 1
    double left = -1, right_edge = 1;  // orthographic: the image line's ends, eye-space units
    double near = 0.1, far = 100;

    glm::dvec2 to_camera(glm::dvec2 world) const;  // (x to the right, z along the view)
    glm::dvec2 to_world(glm::dvec2 camera) const;
    double image_u(glm::dvec2 camera) const;        // where a camera-space point projects on the image line
    double pixel_centre(std::uint32_t pixel, std::uint32_t pixels) const;  // its u
    // The projector through u: a point where it starts (the eye, or on the eye's line) and its direction (z = 1).
    glm::dvec2 projector_origin(double u) const;
    glm::dvec2 projector_direction(double u) const;
};
// Throws InvalidInput on a camera the plan cannot take (eye at the target, near ≤ 0, far ≤ near, fov not in 0 … 180).
PlanCamera plan_camera(const Camera& camera);

// A primitive's image: its part in view as an interval of u, with its nearness g (1/z in perspective, −z
// orthographic: larger is nearer) at both ends; g is linear in u in between.
struct PrimitiveImage {
    double from = 0, to = 0;
    double g_from = 0, g_to = 0;
    glm::dvec2 a{0}, b{0};  // the part in view, camera space, a at `from`
    double nearness(double u) const;
    double depth(double u, bool perspective) const;  // z along the view at u
};
// The segment a–b (camera space) clipped to the near and far lines and the field of view; nothing when no part with
// a positive width on the image line is left.
std::optional<PrimitiveImage> image_of(const PlanCamera& camera, glm::dvec2 a, glm::dvec2 b);

// Where `other` hides `primitive`: the part of their overlap where other is nearer (ties: the lower index hides).
// Nothing when their images do not overlap; an empty interval (from = to) when they overlap and other hides nothing.
struct Hidden {
    bool overlap = false;
    double from = 0, to = 0;
};
Hidden hidden_by(const PrimitiveImage& primitive, const PrimitiveImage& other, bool other_first);

// The interval [from, to) less a union of intervals, in order.
std::vector<glm::dvec2> subtract(double from, double to, std::vector<glm::dvec2> removed);

// Image space: the projector through u against the segment a–b (camera space, unclipped); the depth z where it
// hits between the near and far lines.
std::optional<double> projector_hit(const PlanCamera& camera, double u, glm::dvec2 a, glm::dvec2 b);

struct FormsOptions {
    std::uint32_t pixels = 16;                            // the image's width (one row)
    std::uint64_t max_steps = std::uint64_t(1) << 32;     // comparisons plus tests before it stops (step bound)
};

struct FormsResult {
    std::vector<std::int32_t> object_image, image_image;  // per pixel, the primitive drawn (−1: background)
    std::uint64_t comparisons = 0, tests = 0;
    bool bounded = false;
};

// The scene's segments (the plane z = 0) seen by its camera through both forms, object space first. The scene is
// copied into the machine. InvalidInput when it has no segments, or pixels is not in 1 … 4096.
Steps<FormsEvent, FormsResult> general_forms(Scene scene, FormsOptions options = {});

}  // namespace hsr::algo
