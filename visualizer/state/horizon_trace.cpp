// SPDX-License-Identifier: MIT
// The trace's fields of the floating horizon's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "horizon/horizon_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, Sight s) { j = std::string(to_string(s)); }

HSR_TO_JSON(CurveStarted, row, z)
HSR_TO_JSON(PointTested, row, column, x, height, y, first, upper, lower, sight)
HSR_TO_JSON(CurveDrawn, row, above, below, hidden)
HSR_TO_JSON(HorizonFinished, visible, hidden)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::HorizonEvent)
}  // namespace hsr::viz
