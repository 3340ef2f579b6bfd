// SPDX-License-Identifier: MIT
// Alpha compositing as the UBC notes give it (FCG 3.4; Porter and Duff, "Compositing Digital Images", SIGGRAPH '84),
// for the translucent layers one pixel's ray passes through.
//
//   straight alpha      (r, g, b, α):     "alpha as transparent coloured glass"
//   premultiplied alpha (αr, αg, αb, α):  "alpha as a screen/mesh": α is how much of the pixel the layer covers
//
//   F over B, premultiplied:  C′ = C_F + (1 − A_F) · C_B   the same for R, G, B and A: associative
//   F over B, straight:       C′ = (C_F · A_F + (1 − A_F) · C_B · A_B) / A′,   A′ = A_F + (1 − A_F) · A_B
//
//   back to front:  C = clear;  for each layer F, farthest first:  C = F over C
//   front to back:  C = clear;  for each layer F, nearest first:   C = C over F    ("under"),
//                   and stop once A is opaque enough: nothing behind can show
//
// Porter and Duff combine two premultiplied images A and B as F_A · A + F_B · B, with (F_A, F_B) per operator:
// over (1, 1 − α_A), in (α_B, 0), out (1 − α_B, 0), atop (α_B, 1 − α_A), xor (1 − α_B, 1 − α_A), plus (1, 1).
// Their derivation reads α as coverage by uncorrelated shapes: A covers α_A of the pixel, B α_B, both α_A · α_B.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "compositing/composite_events.h"
#include "core/steps.h"
#include "raycast/nearest_hit.h"
#include "scene/scene.h"

namespace hsr::algo {

Rgba premultiply(Rgba straight);
Rgba unpremultiply(Rgba premultiplied);  // (0, 0, 0, 0) where α = 0
Rgba over(Rgba front, Rgba back);             // premultiplied in and out
Rgba over_straight(Rgba front, Rgba back);    // the notes' non-premultiplied formula: straight in and out
// The "conventional" blend of straight colours, C′ = A_F · C_F + (1 − A_F) · C_B, which leaves B's alpha out: right
// when B is opaque, and not associative when it is not (the notes' "must avoid double-counting").
Rgba blend_naive(Rgba front, Rgba back);

struct Factors {
    double a, b;  // F_A, F_B
};
Factors porter_duff_factors(PorterDuff op, double alpha_a, double alpha_b);
Rgba porter_duff(PorterDuff op, Rgba a, Rgba b);  // premultiplied in and out
std::span<const PorterDuff> porter_duff_operators();  // the ones a lesson shows, in the paper's order

// A scene polygon the ray passes through, with its straight colour (its opacity as α).
struct Layer {
    SceneId id = 0;
    Rgba colour;
    double t = 0;  // along the ray
};
// The layers along the ray, nearest first.
std::vector<Layer> layers_along(const Scene& scene, const Ray& ray);
// The ray through the centre of the camera's image: from the eye toward its target.
Ray centre_ray(const Camera& camera);

struct CompositeOptions {
    double opaque_enough = 0.999;  // front to back stops once the composite's α reaches this
};

struct CompositeResult {
    Rgba back_to_front, front_to_back;  // premultiplied
    Rgba straight;                      // back to front with the straight formula
    std::size_t front_to_back_layers = 0;  // layers composited before it stopped
};

// Premultiplies each layer, composites them back to front (premultiplied and straight, side by side) and front to
// back with its early stop, compares the two orders, checks associativity on the three nearest layers (the
// premultiplied "over" and the naive blend), and applies the Porter–Duff operators to the two nearest. It makes at
// most 6 · layers + 16 steps: every loop runs over the layers once.
Steps<CompositeEvent, CompositeResult> composite(std::vector<Layer> layers, CompositeOptions options = {});

}  // namespace hsr::algo
