// SPDX-License-Identifier: MIT
// The trace's fields of cells and portals (the PVS and portal_render)'s events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "portals/portal_events.h"

namespace hsr::algo {

HSR_TO_JSON(StabTreeStarted, cell)
HSR_TO_JSON(SightlineTested, source, portals, found, line_space_area, point, direction, blocked_in_3d)
HSR_TO_JSON(CellReached, source, cell, depth, node, parent, portal)
HSR_TO_JSON(StabBoundReached, source, cell, limit, cells_assumed)
HSR_TO_JSON(PvsBuilt, cells, visible_pairs, sightline_tests)
inline void to_json(nlohmann::json& j, PortalVerdict v) { j = std::string(to_string(v)); }
inline void to_json(nlohmann::json& j, CullReason r) { j = std::string(to_string(r)); }
HSR_TO_JSON(EyeLocated, cell, path)
HSR_TO_JSON(PvsRowRead, cell, visible)
HSR_TO_JSON(CellVisited, cell, depth, frustum)
HSR_TO_JSON(PortalTested, portal, verdict, visible_part, narrowed)
HSR_TO_JSON(CellPolygonCulled, polygon, reason)
HSR_TO_JSON(CellPolygonDrawn, polygon, visible_part)
HSR_TO_JSON(PortalBoundReached, cell, limit)
HSR_TO_JSON(PortalRenderFinished, visits, drawn, culled_back_face, culled_frustum, portals_passed)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::PvsEvent)
HSR_TRACE_LINES(algo::PortalEvent)
}  // namespace hsr::viz
