// SPDX-License-Identifier: MIT
// Back-face culling, in the three forms the lectures give, one event per polygon:
//   view_vector     v̂ · n̂ with v from the eye to a point of the polygon (never a constant look direction, which is
//                   wrong for a wide field of view): front-facing when v̂ · n̂ < 0. (The lecture's v points the
//                   other way, toward the viewer, and so calls v̂ · n̂ < 0 a back face: the same test.)
//   plane_equation  N · eye + D, the eye in the polygon's plane equation: front-facing when > 0
//   screen_winding  after projection (clipped at the near plane first, then divided by w), the signed area of the
//                   polygon on the screen, i.e. the z of its projected normal: front-facing when counter-clockwise
// Polygons are wound counter-clockwise seen from outside (their front). Edge-on polygons (0) are culled.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>
#include <vector>

#include "core/events.h"
#include "core/phrase.h"
#include "core/plane.h"
#include "core/steps.h"
#include "scene/scene.h"

namespace hsr::algo {

enum class BackfaceTest : std::uint8_t { view_vector, plane_equation, screen_winding };
enum class Facing : std::uint8_t { front, back, edge_on, outside_view };

struct FaceTested {
    static constexpr std::string_view kind = "FaceTested";
    std::int32_t id;
    BackfaceTest test;
    Facing facing;
    double value;  // v̂ · n̂, N · eye + D, or the signed screen area (NDC units²)
    bool operator==(const FaceTested&) const = default;
};
struct CullingFinished {
    static constexpr std::string_view kind = "CullingFinished";
    std::uint32_t tested, culled;
    bool operator==(const CullingFinished&) const = default;
};
using CullEvent = std::variant<FaceTested, CullingFinished>;

struct Face {
    std::int32_t id = 0;
    std::vector<Vec3> vertices;  // world space, counter-clockwise seen from the front
};

// The ids of the faces kept (front-facing), in input order. The camera gives the eye (and, for the screen test,
// the projection). InvalidInput names a face with NaN, infinity, fewer than 3 vertices or no area.
Steps<CullEvent, std::vector<std::int32_t>> cull_back_faces(std::vector<Face> faces, Camera camera, BackfaceTest test);

// The scene's polygons as faces (its camera is the eye).
std::vector<Face> faces_of(const Scene& scene);

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const CullEvent& e);
std::string describe(const CullEvent& e);
std::string_view to_string(BackfaceTest t);
std::string_view to_string(Facing f);
const Saying& term(BackfaceTest t);  // words to translate
const Saying& term(Facing f);
std::span<const Saying> backface_sayings();  // every template back-face culling says

}  // namespace hsr::algo
