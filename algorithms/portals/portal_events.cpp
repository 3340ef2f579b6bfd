// SPDX-License-Identifier: MIT
#include "portals/portal_events.h"

#include "core/events.h"
#include "core/overloaded.h"
#include "core/phrase.h"
#include "portals/cell_model.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }

std::string cell_name(const CellModel& m, std::uint32_t c) { return c < m.cells.size() ? m.cells[c].name : "#" + n(c); }

std::string names(const CellModel& m, const std::vector<std::uint32_t>& cells) {
    std::string s;
    for (std::uint32_t c : cells) s += (s.empty() ? "" : ", ") + cell_name(m, c);
    return "{" + s + "}";
}

}  // namespace

namespace {
// What the PVS and portal machines say, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying not_in_pvs{"portals.not_in_pvs", "not in the PVS"};
constexpr Saying faces_away{"portals.faces_away", "faces away from the eye"};
constexpr Saying outside_frustum{"portals.outside_frustum", "outside the frustum"};
constexpr Saying on_path{"portals.on_path", "leads back to a cell on the way"};
constexpr Saying passed{"portals.passed", "passed"};
constexpr Saying back_face{"portals.back_face", "back-face"};
constexpr Saying frustum{"portals.frustum", "frustum"};
constexpr Saying stab_tree{"portals.stab_tree", "Stab tree of cell {cell}: it sees itself; now each portal out of it."};
constexpr Saying one_portal{"portals.one_portal", "Through one portal, {sequence}: a sightline always exists."};
constexpr Saying found{"portals.found", "Sightline through {portals} portals {sequence}: found (line-space area {area})."};
constexpr Saying blocked_3d{"portals.blocked_3d",
                            "Sightline through {portals} portals {sequence}: none in 3D: in the plan lines pass, but each goes "
                            "above or below one of the openings."};
constexpr Saying none{"portals.none", "Sightline through {portals} portals {sequence}: none, the portals cannot all be seen through along one line."};
constexpr Saying reached{"portals.reached",
                         "Cell {cell} is potentially visible from {source} ({depth} {depth?portal|portals} away)."};
constexpr Saying stab_bound{"portals.stab_bound",
                            "Stopped at the bound of {limit} in cell {cell}: {assumed} cells beyond are counted visible from "
                            "{source}, to stay conservative."};
constexpr Saying pvs_built{"portals.pvs_built", "PVS matrix built: {set} of {entries} entries set, after {tests} sightline tests."};
constexpr Saying no_cell{"portals.no_cell", "The eye is in no cell (in a wall, or outside the plan): nothing is drawn."};
constexpr Saying located{"portals.located", "The BSP tree locates the eye in cell {cell} after {nodes} nodes."};
constexpr Saying row{"portals.row", "PVS row of {cell}: {visible}."};
constexpr Saying visited{"portals.visited",
                         "portal_render({cell}): a frustum of {sides} side planes, {depth} {depth?portal|portals} deep."};
constexpr Saying tested{"portals.tested", "portal {from}→{to}: {verdict}."};
constexpr Saying tested_passed{"portals.tested_passed",
                               "portal {from}→{to}: {verdict}; the frustum narrows to its visible part ({corners} corners, "
                               "{sides} side planes)."};
constexpr Saying culled{"portals.culled", "Polygon {id} culled: {reason}."};
constexpr Saying drawn{"portals.drawn", "Polygon {id} drawn: its part inside the frustum has {corners} corners."};
constexpr Saying render_bound{"portals.render_bound",
                              "Stopped at the bound of {limit} before cell {cell}: the rest of the PVS is drawn against the whole "
                              "view frustum."};
constexpr Saying finished{"portals.finished",
                          "Done: {visits} cell {visits?visit|visits}, {passed} {passed?portal|portals} passed, {drawn} polygons "
                          "drawn, {back} back-face and {frustum} frustum culls."};
constexpr Saying all[] = {not_in_pvs, faces_away, outside_frustum, on_path, passed, back_face, frustum, stab_tree, one_portal,
                          found, blocked_3d, none, reached, stab_bound, pvs_built, no_cell, located, row, visited, tested,
                          tested_passed, culled, drawn, render_bound, finished};
}  // namespace say
}  // namespace

const Saying& term(PortalVerdict v) {
    switch (v) {
        case PortalVerdict::not_in_pvs: return say::not_in_pvs;
        case PortalVerdict::faces_away: return say::faces_away;
        case PortalVerdict::outside_frustum: return say::outside_frustum;
        case PortalVerdict::on_path: return say::on_path;
        case PortalVerdict::passed: return say::passed;
    }
    return say::passed;
}

const Saying& term(CullReason r) { return r == CullReason::back_face ? say::back_face : say::frustum; }

std::string_view to_string(PortalVerdict v) { return term(v).english; }
std::string_view to_string(CullReason r) { return term(r).english; }

std::span<const Saying> portal_sayings() { return say::all; }

Phrase phrase(const PvsEvent& event, const CellModel& m) {
    return std::visit(
        overloaded{
            [&](const StabTreeStarted& e) { return Phrase(say::stab_tree, {{"cell", cell_name(m, e.cell)}}); },
            [&](const SightlineTested& e) {
                std::string seq;
                for (std::uint32_t k : e.portals) seq += (seq.empty() ? cell_name(m, m.portals[k].from) : "") + "→" + cell_name(m, m.portals[k].to);
                if (e.portals.size() == 1) return Phrase(say::one_portal, {{"sequence", seq}});
                return Phrase(e.found ? say::found : e.blocked_in_3d ? say::blocked_3d : say::none,
                              {{"portals", n(e.portals.size())}, {"sequence", seq}, {"area", format_number(e.line_space_area)}});
            },
            [&](const CellReached& e) {
                return Phrase(say::reached, {{"cell", cell_name(m, e.cell)}, {"source", cell_name(m, e.source)}, {"depth", n(e.depth)}});
            },
            [&](const StabBoundReached& e) {
                return Phrase(say::stab_bound, {{"limit", n(e.limit)}, {"cell", cell_name(m, e.cell)}, {"assumed", n(e.cells_assumed)},
                                                {"source", cell_name(m, e.source)}});
            },
            [&](const PvsBuilt& e) {
                return Phrase(say::pvs_built, {{"set", n(e.visible_pairs)}, {"entries", n(std::uint64_t(e.cells) * e.cells)},
                                               {"tests", n(e.sightline_tests)}});
            },
        },
        event);
}

Phrase phrase(const PortalEvent& event, const CellModel& m) {
    return std::visit(
        overloaded{
            [&](const EyeLocated& e) {
                if (e.cell < 0) return Phrase(say::no_cell);
                return Phrase(say::located, {{"cell", cell_name(m, std::uint32_t(e.cell))}, {"nodes", n(e.path.size())}});
            },
            [&](const PvsRowRead& e) { return Phrase(say::row, {{"cell", cell_name(m, e.cell)}, {"visible", names(m, e.visible)}}); },
            [&](const CellVisited& e) {
                return Phrase(say::visited, {{"cell", cell_name(m, e.cell)}, {"sides", n(e.frustum.size() - 2)}, {"depth", n(e.depth)}});
            },
            [&](const PortalTested& e) {
                const Portal& p = m.portals[e.portal];
                return Phrase(e.verdict == PortalVerdict::passed ? say::tested_passed : say::tested,
                              {{"from", cell_name(m, p.from)}, {"to", cell_name(m, p.to)}, {"corners", n(e.visible_part.size())},
                               {"sides", n(e.narrowed.size() - 2)}},
                              Terms{{"verdict", &term(e.verdict)}});
            },
            [&](const CellPolygonCulled& e) {
                return Phrase(say::culled, {{"id", std::to_string(m.polygons[e.polygon].id)}}, Terms{{"reason", &term(e.reason)}});
            },
            [&](const CellPolygonDrawn& e) {
                return Phrase(say::drawn, {{"id", std::to_string(m.polygons[e.polygon].id)}, {"corners", n(e.visible_part.size())}});
            },
            [&](const PortalBoundReached& e) { return Phrase(say::render_bound, {{"limit", n(e.limit)}, {"cell", cell_name(m, e.cell)}}); },
            [&](const PortalRenderFinished& e) {
                return Phrase(say::finished, {{"visits", n(e.visits)}, {"passed", n(e.portals_passed)}, {"drawn", n(e.drawn)},
                                              {"back", n(e.culled_back_face)}, {"frustum", n(e.culled_frustum)}});
            },
        },
        event);
}

std::string describe(const PvsEvent& event, const CellModel& m) { return phrase(event, m).english(); }
std::string describe(const PortalEvent& event, const CellModel& m) { return phrase(event, m).english(); }

}  // namespace hsr::algo
