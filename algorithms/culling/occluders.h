// SPDX-License-Identifier: MIT
// From-point occlusion culling with planar occluders (the lecture, after Coorg and Teller):
//
//   choose occluders:   rank the front-facing polygons by f = −A (n̂ · v̂) / |v|², keep the best few
//                       (A its area, n̂ its normal, v from the viewpoint to its centre)
//   occlusion frustum:  the planes through the viewpoint and each edge of an occluder, and the occluder's own plane
//   cull:               from the top of the hierarchy, a box wholly inside one occlusion frustum is rejected with
//                       its subtree; a box partly inside is split into its children; each primitive left is culled
//                       when its box lies wholly inside one frustum, else passed on to hidden-surface elimination
//
// One occluder at a time: an object hidden only by two adjacent occluders together (the partial occlusion
// problem) is not in either frustum, so it is passed on. The notes' answers (culling/occluder_shapes.h), chosen in
// OcclusionOptions:
//   kind = proxy:  each polygon replaced by its proxy (perpendicular to the view, inscribed in its frustum)
//   kind = solid:  Papaioannou's solid occluders: a closed convex object is one occluder, its volume's proxy;
//                  polygons of no such object stay planar; all ranked together by f
//   fusion:        a box in no single frustum is still culled when its image lies in the union of the images of
//                  the occluders it lies wholly behind
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/phrase.h"
#include "core/steps.h"
#include "culling/hierarchy.h"
#include "culling/occluder_shapes.h"

namespace hsr::algo {

enum class OccluderKind : std::uint8_t { planar, proxy, solid };
std::string_view to_string(OccluderKind k);  // "planar", "proxy", "solid"

struct OccluderChosen {
    static constexpr std::string_view kind = "OccluderChosen";
    std::uint32_t polygon;  // index into the scene's polygons (a solid: its first face)
    double rank, area;      // f = −A (n̂ · v̂) / |v|², of the occluder's outline
    OccluderKind shape = OccluderKind::planar;  // the polygon itself, its proxy, or a solid's proxy
    std::uint32_t faces = 1;                    // the scene polygons it stands for
    std::vector<Vec3> outline;                  // the polygon whose frustum culls
    bool operator==(const OccluderChosen&) const = default;
};
enum class OcclusionOutcome : std::uint8_t { occluded, partly, visible };
struct OcclusionTested {
    static constexpr std::string_view kind = "OcclusionTested";
    std::int32_t node;       // −1: a primitive's own box, tested at the leaf that holds it
    std::int32_t primitive;  // −1: a node
    OcclusionOutcome outcome;
    std::int32_t occluder;   // occluded by one: which (index into the chosen ones); else −1
    std::uint32_t fused = 0;  // occluded by fusion: the number of occluders whose images together cover it
    bool operator==(const OcclusionTested&) const = default;
};
struct OcclusionFinished {
    static constexpr std::string_view kind = "OcclusionFinished";
    std::uint32_t occluders, culled, passed;
    std::uint32_t fused = 0;  // of the culled, those no single occluder hid
    bool operator==(const OcclusionFinished&) const = default;
};
using OcclusionEvent = std::variant<OccluderChosen, OcclusionTested, OcclusionFinished>;
// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const OcclusionEvent& e);
std::string describe(const OcclusionEvent& e);
std::span<const Saying> occluder_sayings();

struct Occluder {
    std::uint32_t polygon;
    double rank;
    OccluderKind shape = OccluderKind::planar;
    std::vector<std::uint32_t> faces;  // the scene polygons it stands for
    std::vector<Vec3> outline;
    std::vector<Plane> frustum;  // fronts inside: the edge planes, then the occluder's plane (its far side inside)
    std::vector<Vec2> image;  // the outline's image on the view plane (fusion), counter-clockwise
};

struct OcclusionOptions {
    std::uint32_t max_occluders = 8;
    std::vector<std::uint8_t> candidates;  // per polygon: may it be tested at all (earlier stages); empty: all
    OccluderKind kind = OccluderKind::planar;
    bool fusion = false;
    // kind = solid: the scene's convex solids (convex_solids), found once beforehand like the hierarchy (objects
    // do not change from frame to frame); null: found here. Must outlive the machine.
    const std::vector<std::vector<std::uint32_t>>* solids = nullptr;
};

struct OcclusionCull {
    std::vector<Occluder> occluders;
    std::vector<std::uint8_t> kept;  // per polygon
    std::uint32_t culled = 0;
};

// The hierarchy is over the scene's polygons (in order); both must outlive the machine.
Steps<OcclusionEvent, OcclusionCull> occlusion_cull(const Scene* scene, const Hierarchy* hierarchy, OcclusionOptions options = {});

// The rank of a polygon as an occluder from `eye` (0 when it faces away): its area over the squared distance,
// times the cosine of its turn from the eye.
double occluder_rank(const std::vector<Vec3>& polygon, const Vec3& eye);
// The same seen by the camera: from its eye, or for an orthographic camera along its view direction (the area it
// covers on the screen, whatever its distance).
double occluder_rank(const std::vector<Vec3>& polygon, const Camera& camera);

}  // namespace hsr::algo
