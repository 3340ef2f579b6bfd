// SPDX-License-Identifier: MIT
#include "portals/portal_events.h"

#include "core/events.h"
#include "core/overloaded.h"
#include "portals/cell_model.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }

std::string cell_name(const CellModel& m, std::uint32_t c) { return c < m.cells.size() ? m.cells[c].name : "#" + n(c); }

std::string portal_name(const CellModel& m, std::uint32_t k) {
    const Portal& p = m.portals[k];
    return "portal " + cell_name(m, p.from) + "→" + cell_name(m, p.to);
}

std::string names(const CellModel& m, const std::vector<std::uint32_t>& cells) {
    std::string s;
    for (std::uint32_t c : cells) s += (s.empty() ? "" : ", ") + cell_name(m, c);
    return "{" + s + "}";
}

}  // namespace

std::string_view to_string(PortalVerdict v) {
    switch (v) {
        case PortalVerdict::not_in_pvs: return "not in the PVS";
        case PortalVerdict::faces_away: return "faces away from the eye";
        case PortalVerdict::outside_frustum: return "outside the frustum";
        case PortalVerdict::on_path: return "leads back to a cell on the way";
        case PortalVerdict::passed: return "passed";
    }
    return "?";
}

std::string_view to_string(CullReason r) { return r == CullReason::back_face ? "back-face" : "frustum"; }

std::string describe(const PvsEvent& event, const CellModel& m) {
    return std::visit(
        overloaded{
            [&](const StabTreeStarted& e) -> std::string { return "Stab tree of cell " + cell_name(m, e.cell) + ": it sees itself; now each portal out of it."; },
            [&](const SightlineTested& e) -> std::string {
                std::string seq;
                for (std::uint32_t k : e.portals) seq += (seq.empty() ? cell_name(m, m.portals[k].from) : "") + "→" + cell_name(m, m.portals[k].to);
                if (e.portals.size() == 1) return "Through one portal, " + seq + ": a sightline always exists.";
                return "Sightline through " + n(e.portals.size()) + " portals " + seq + ": " +
                       (e.found           ? "found (line-space area " + format_number(e.line_space_area) + ")."
                        : e.blocked_in_3d ? "none in 3D: in the plan lines pass, but each goes above or below one of the openings."
                                          : "none, the portals cannot all be seen through along one line.");
            },
            [&](const CellReached& e) -> std::string {
                return "Cell " + cell_name(m, e.cell) + " is potentially visible from " + cell_name(m, e.source) + " (" + n(e.depth) +
                       (e.depth == 1 ? " portal away)." : " portals away).");
            },
            [&](const StabBoundReached& e) -> std::string {
                return "Stopped at the bound of " + n(e.limit) + " in cell " + cell_name(m, e.cell) + ": " + n(e.cells_assumed) +
                       " cells beyond are counted visible from " + cell_name(m, e.source) + ", to stay conservative.";
            },
            [&](const PvsBuilt& e) -> std::string {
                return "PVS matrix built: " + n(e.visible_pairs) + " of " + n(std::uint64_t(e.cells) * e.cells) + " entries set, after " +
                       n(e.sightline_tests) + " sightline tests.";
            },
        },
        event);
}

std::string describe(const PortalEvent& event, const CellModel& m) {
    return std::visit(
        overloaded{
            [&](const EyeLocated& e) -> std::string {
                if (e.cell < 0) return "The eye is in no cell (in a wall, or outside the plan): nothing is drawn.";
                return "The BSP tree locates the eye in cell " + cell_name(m, std::uint32_t(e.cell)) + " after " + n(e.path.size()) + " nodes.";
            },
            [&](const PvsRowRead& e) -> std::string { return "PVS row of " + cell_name(m, e.cell) + ": " + names(m, e.visible) + "."; },
            [&](const CellVisited& e) -> std::string {
                return "portal_render(" + cell_name(m, e.cell) + "): a frustum of " + n(e.frustum.size() - 2) + " side planes, " + n(e.depth) +
                       (e.depth == 1 ? " portal deep." : " portals deep.");
            },
            [&](const PortalTested& e) -> std::string {
                std::string s = portal_name(m, e.portal) + ": " + std::string(to_string(e.verdict));
                if (e.verdict == PortalVerdict::passed)
                    s += "; the frustum narrows to its visible part (" + n(e.visible_part.size()) + " corners, " + n(e.narrowed.size() - 2) + " side planes)";
                return s + ".";
            },
            [&](const CellPolygonCulled& e) -> std::string {
                return "Polygon " + std::to_string(m.polygons[e.polygon].id) + " culled: " + std::string(to_string(e.reason)) + ".";
            },
            [&](const CellPolygonDrawn& e) -> std::string {
                return "Polygon " + std::to_string(m.polygons[e.polygon].id) + " drawn (" + n(e.visible_part.size()) + " corners inside the frustum).";
            },
            [&](const PortalBoundReached& e) -> std::string {
                return "Stopped at the bound of " + n(e.limit) + " before cell " + cell_name(m, e.cell) +
                       ": the rest of the PVS is drawn against the whole view frustum.";
            },
            [&](const PortalRenderFinished& e) -> std::string {
                return "Done: " + n(e.visits) + (e.visits == 1 ? " cell visit, " : " cell visits, ") + n(e.portals_passed) +
                       (e.portals_passed == 1 ? " portal passed, " : " portals passed, ") + n(e.drawn) + " polygons drawn, " +
                       n(e.culled_back_face) + " back-face and " + n(e.culled_frustum) + " frustum culls.";
            },
        },
        event);
}

}  // namespace hsr::algo
