// SPDX-License-Identifier: MIT
// What the hierarchical intersection test tells (the Greek notes' IntersectionTest(M), Bounding Volumes (7)): each
// model entered, each bounding volume tested, each primitive tested exhaustively at the bottom level, each component
// skipped because an earlier one already answered (v || …), and each false alarm: a volume the ray meets although
// nothing inside it does.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "core/phrase.h"

namespace hsr::algo {

// The kinds of bounding volume; progressive hulls test the 6-, 14- and 26-DOP of a model, outermost first.
enum class VolumeKind : std::uint8_t { aabb, sphere, obb, kdop, hulls };

struct RayStartedAt {
    static constexpr std::string_view kind = "RayStartedAt";
    std::uint32_t ray;
    double ox, oy, oz, dx, dy, dz;
    bool operator==(const RayStartedAt&) const = default;
};
// IntersectionTest(M) called on a node of the hierarchy; bottom: it holds primitives and no components.
struct ModelEntered {
    static constexpr std::string_view kind = "ModelEntered";
    std::uint32_t ray, node, depth;
    bool bottom;
    std::uint32_t primitives;  // in its subtree
    bool operator==(const ModelEntered&) const = default;
};
// LLIntersectionTest(BoundingBox(M)): the ray against the node's volume (k: which hull, for k-DOPs and hulls).
struct VolumeTested {
    static constexpr std::string_view kind = "VolumeTested";
    std::uint32_t ray, node;
    VolumeKind volume;
    std::uint32_t k;
    bool hit;
    double enter, exit;  // where the ray is inside it (when hit)
    bool operator==(const VolumeTested&) const = default;
};
// LLIntersectionTest(M) at the bottom level: the ray against one of the node's primitives.
struct PrimitiveHitTested {
    static constexpr std::string_view kind = "PrimitiveHitTested";
    std::uint32_t ray, node, polygon;
    std::int32_t id;
    bool hit;
    double t;
    bool operator==(const PrimitiveHitTested&) const = default;
};
// v is already true: the component M→C is not tested (the || stops there).
struct ComponentSkipped {
    static constexpr std::string_view kind = "ComponentSkipped";
    std::uint32_t ray, node, component;
    bool operator==(const ComponentSkipped&) const = default;
};
// IntersectionTest(M) returns; a false alarm when its volume was hit and nothing below it was.
struct ModelAnswered {
    static constexpr std::string_view kind = "ModelAnswered";
    std::uint32_t ray, node;
    bool hit, false_alarm;
    bool operator==(const ModelAnswered&) const = default;
};
struct RayAnswered {
    static constexpr std::string_view kind = "RayAnswered";
    std::uint32_t ray;
    bool hit;
    std::uint32_t volume_tests, primitive_tests, false_alarms;
    bool operator==(const RayAnswered&) const = default;
};
struct IntersectionFinished {
    static constexpr std::string_view kind = "IntersectionFinished";
    std::uint32_t rays, hits;
    std::uint64_t volume_tests, primitive_tests, false_alarms, steps;
    bool bounded;
    bool operator==(const IntersectionFinished&) const = default;
};

using IntersectionEvent = std::variant<RayStartedAt, ModelEntered, VolumeTested, PrimitiveHitTested, ComponentSkipped,
                                       ModelAnswered, RayAnswered, IntersectionFinished>;

std::string_view to_string(VolumeKind kind);
Phrase phrase(const IntersectionEvent& e);
std::string describe(const IntersectionEvent& e);
std::span<const Saying> intersection_sayings();

}  // namespace hsr::algo
