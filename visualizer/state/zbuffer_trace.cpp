// SPDX-License-Identifier: MIT
// The trace's fields of the z-buffer fill's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "zbuffer/zbuffer_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, ScreenStatus s) {
    j = s == ScreenStatus::drawn ? "drawn" : s == ScreenStatus::outside_view ? "outside view" : "zero area";
}
HSR_TO_JSON(BufferCleared, width, height, far_code)
HSR_TO_JSON(PolygonFillStarted, index, id, per_x)
HSR_TO_JSON(PolygonSkipped, index, id, why)
HSR_TO_JSON(SpanStarted, index, y, x_begin, x_end, depth)
HSR_TO_JSON(PixelTested, x, y, depth, incoming, stored, passes)
HSR_TO_JSON(DepthWritten, x, y, index, old_index, old_code, new_code)
HSR_TO_JSON(DepthTestFailed, x, y, incoming, stored)
HSR_TO_JSON(PolygonFillFinished, index, tested, written)
HSR_TO_JSON(FillFinished, polygons, tested, written)
HSR_TO_JSON(FillStepBoundReached, max_pixel_tests)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::ZBufferEvent)
}  // namespace hsr::viz
