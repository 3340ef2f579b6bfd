// SPDX-License-Identifier: MIT
// The trace's fields of back-face culling's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "culling/backface.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, BackfaceTest t) { j = std::string(to_string(t)); }
inline void to_json(nlohmann::json& j, Facing f) { j = std::string(to_string(f)); }
HSR_TO_JSON(FaceTested, id, test, facing, value)
HSR_TO_JSON(CullingFinished, tested, culled)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::CullEvent)
}  // namespace hsr::viz
