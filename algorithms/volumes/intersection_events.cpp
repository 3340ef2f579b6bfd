// SPDX-License-Identifier: MIT
#include "volumes/intersection_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

namespace {
// What the intersection test says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying ray{"intersection.ray", "Ray {ray} from ({ox}, {oy}, {oz}) along ({dx}, {dy}, {dz}): IntersectionTest(root)."};
constexpr Saying model{"intersection.model", "IntersectionTest(node {node}), depth {depth}: {primitives} primitives below; not the bottom level, so its bounding volume first."};
constexpr Saying bottom{"intersection.bottom", "IntersectionTest(node {node}), depth {depth}: the bottom level; LLIntersectionTest on its {primitives} primitives."};
constexpr Saying volume_hit{"intersection.volume_hit", "Node {node}'s {volume} is hit (the ray is inside it from t = {enter} to {exit}): test its components."};
constexpr Saying volume_miss{"intersection.volume_miss", "Node {node}'s {volume} is missed: nothing inside it can be hit, and no test is made below it."};
constexpr Saying primitive_hit{"intersection.primitive_hit", "Node {node}: the ray hits polygon {id} at t = {t}."};
constexpr Saying primitive_miss{"intersection.primitive_miss", "Node {node}: the ray misses polygon {id}."};
constexpr Saying skipped{"intersection.skipped", "v is already true at node {node}: component {component} is not tested."};
constexpr Saying answered_hit{"intersection.answered_hit", "IntersectionTest(node {node}) returns true."};
constexpr Saying answered_miss{"intersection.answered_miss", "IntersectionTest(node {node}) returns false."};
constexpr Saying false_alarm{"intersection.false_alarm", "IntersectionTest(node {node}) returns false although its volume was hit: a false alarm, paid for by its void space."};
constexpr Saying ray_hit{"intersection.ray_hit", "Ray {ray} meets the model: {volumes} volume tests, {primitives} primitive tests, {alarms} false alarms."};
constexpr Saying ray_miss{"intersection.ray_miss", "Ray {ray} misses the model: {volumes} volume tests, {primitives} primitive tests, {alarms} false alarms."};
constexpr Saying done{"intersection.done", "Done: {hits} of {rays} rays meet the model; {volumes} volume tests, {primitives} primitive tests, {alarms} false alarms."};
constexpr Saying bound{"intersection.bound", "Stopped: the step bound of {steps} tests was reached."};
constexpr Saying all[] = {ray, model, bottom, volume_hit, volume_miss, primitive_hit, primitive_miss, skipped, answered_hit, answered_miss,
                          false_alarm, ray_hit, ray_miss, done, bound};
}  // namespace say

std::string volume_name(VolumeKind kind, std::uint32_t k) {
    switch (kind) {
        case VolumeKind::aabb: return "AABB";
        case VolumeKind::sphere: return "sphere";
        case VolumeKind::obb: return "OBB";
        case VolumeKind::kdop:
        case VolumeKind::hulls: break;
    }
    return std::to_string(k) + "-DOP";
}

}  // namespace

std::string_view to_string(VolumeKind kind) {
    switch (kind) {
        case VolumeKind::aabb: return "aabb";
        case VolumeKind::sphere: return "sphere";
        case VolumeKind::obb: return "obb";
        case VolumeKind::kdop: return "kdop";
        case VolumeKind::hulls: break;
    }
    return "hulls";
}

std::span<const Saying> intersection_sayings() { return say::all; }

Phrase phrase(const IntersectionEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    const auto f = [](double v) { return format_number(v); };
    return std::visit(
        overloaded{
            [&](const RayStartedAt& e) {
                return Phrase(say::ray, {{"ray", n(e.ray)}, {"ox", f(e.ox)}, {"oy", f(e.oy)}, {"oz", f(e.oz)}, {"dx", f(e.dx)}, {"dy", f(e.dy)}, {"dz", f(e.dz)}});
            },
            [&](const ModelEntered& e) {
                return Phrase(e.bottom ? say::bottom : say::model, {{"node", n(e.node)}, {"depth", n(e.depth)}, {"primitives", n(e.primitives)}});
            },
            [&](const VolumeTested& e) {
                if (!e.hit) return Phrase(say::volume_miss, {{"node", n(e.node)}, {"volume", volume_name(e.volume, e.k)}});
                return Phrase(say::volume_hit, {{"node", n(e.node)}, {"volume", volume_name(e.volume, e.k)}, {"enter", f(e.enter)}, {"exit", f(e.exit)}});
            },
            [&](const PrimitiveHitTested& e) {
                if (!e.hit) return Phrase(say::primitive_miss, {{"node", n(e.node)}, {"id", n(e.id)}});
                return Phrase(say::primitive_hit, {{"node", n(e.node)}, {"id", n(e.id)}, {"t", f(e.t)}});
            },
            [&](const ComponentSkipped& e) { return Phrase(say::skipped, {{"node", n(e.node)}, {"component", n(e.component)}}); },
            [&](const ModelAnswered& e) {
                if (e.false_alarm) return Phrase(say::false_alarm, {{"node", n(e.node)}});
                return Phrase(e.hit ? say::answered_hit : say::answered_miss, {{"node", n(e.node)}});
            },
            [&](const RayAnswered& e) {
                return Phrase(e.hit ? say::ray_hit : say::ray_miss, {{"ray", n(e.ray)}, {"volumes", n(e.volume_tests)}, {"primitives", n(e.primitive_tests)},
                                                                   {"alarms", n(e.false_alarms)}});
            },
            [&](const IntersectionFinished& e) {
                if (e.bounded) return Phrase(say::bound, {{"steps", n(e.steps)}});
                return Phrase(say::done, {{"hits", n(e.hits)}, {"rays", n(e.rays)}, {"volumes", n(e.volume_tests)}, {"primitives", n(e.primitive_tests)},
                                          {"alarms", n(e.false_alarms)}});
            },
        },
        event);
}

std::string describe(const IntersectionEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
