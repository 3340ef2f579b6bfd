// SPDX-License-Identifier: MIT
// The trace's fields of the intersection test's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "volumes/intersection_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, VolumeKind k) { j = std::string(to_string(k)); }

HSR_TO_JSON(RayStartedAt, ray, ox, oy, oz, dx, dy, dz)
HSR_TO_JSON(ModelEntered, ray, node, depth, bottom, primitives)
HSR_TO_JSON(VolumeTested, ray, node, volume, k, hit, enter, exit)
HSR_TO_JSON(PrimitiveHitTested, ray, node, polygon, id, hit, t)
HSR_TO_JSON(ComponentSkipped, ray, node, component)
HSR_TO_JSON(ModelAnswered, ray, node, hit, false_alarm)
HSR_TO_JSON(RayAnswered, ray, hit, volume_tests, primitive_tests, false_alarms)
HSR_TO_JSON(IntersectionFinished, rays, hits, volume_tests, primitive_tests, false_alarms, steps, bounded)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::IntersectionEvent)
}  // namespace hsr::viz
