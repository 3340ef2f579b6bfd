// SPDX-License-Identifier: MIT
// What the cells-and-portals machines tell as they run: the pre-processing (a stab tree from each cell, giving the
// PVS matrix) and the runtime portal_render (locate the eye's cell, take its PVS row, draw through narrowing
// frusta). Cells, portals and polygons are indices into the CellModel; planes and points are in world space.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

#include "core/phrase.h"
#include "core/plane.h"

namespace hsr::algo {

// ── Pre-processing: stab trees and the PVS matrix ─────────────────────────────────────────────────────────────
struct StabTreeStarted {
    static constexpr std::string_view kind = "StabTreeStarted";
    std::uint32_t cell;
    bool operator==(const StabTreeStarted&) const = default;
};
struct SightlineTested {
    static constexpr std::string_view kind = "SightlineTested";
    std::uint32_t source;
    std::vector<std::uint32_t> portals;  // the sequence, out of `source` first
    bool found;                          // some line passes through every portal of the sequence, each its way
    double line_space_area;              // of the set of such lines (0: none, or only a grazing one)
    glm::dvec2 point{0}, direction{0};   // found or blocked_in_3d: a line of the plan through them all, for drawing
    bool blocked_in_3d = false;          // the plan has sightlines, but they pass above or below an opening
    bool operator==(const SightlineTested&) const = default;
};
struct CellReached {
    static constexpr std::string_view kind = "CellReached";
    std::uint32_t source, cell, depth;  // depth: portals from the source
    std::uint32_t node;                 // its index in the source's stab tree
    std::int32_t parent, portal;        // the parent node, and the portal from it into `cell`
    bool operator==(const CellReached&) const = default;
};
struct StabBoundReached {
    static constexpr std::string_view kind = "StabBoundReached";
    std::uint32_t source, cell;  // the sequence that reached the bound ends in `cell`
    std::uint64_t limit;
    std::uint32_t cells_assumed;  // cells beyond it counted visible, to stay conservative
    bool operator==(const StabBoundReached&) const = default;
};
struct PvsBuilt {
    static constexpr std::string_view kind = "PvsBuilt";
    std::uint32_t cells;
    std::uint64_t visible_pairs, sightline_tests;
    bool operator==(const PvsBuilt&) const = default;
};
using PvsEvent = std::variant<StabTreeStarted, SightlineTested, CellReached, StabBoundReached, PvsBuilt>;

// ── Runtime: portal_render ────────────────────────────────────────────────────────────────────────────────────
struct EyeLocated {
    static constexpr std::string_view kind = "EyeLocated";
    std::int32_t cell;                // −1: the eye is in no cell (in a wall, or outside the plan)
    std::vector<std::int32_t> path;   // the BSP nodes from the root
    bool operator==(const EyeLocated&) const = default;
};
struct PvsRowRead {
    static constexpr std::string_view kind = "PvsRowRead";
    std::uint32_t cell;
    std::vector<std::uint32_t> visible;
    bool operator==(const PvsRowRead&) const = default;
};
struct CellVisited {
    static constexpr std::string_view kind = "CellVisited";
    std::uint32_t cell, depth;      // depth: portals passed to get here
    std::vector<Plane> frustum;     // its side planes (fronts inside), then near and far
    bool operator==(const CellVisited&) const = default;
};
enum class PortalVerdict : std::uint8_t {
    not_in_pvs,      // the cell behind it is not in the PVS row
    faces_away,      // the eye is behind the opening (it would lead back)
    outside_frustum, // clipped by the frustum, nothing of it is left
    on_path,         // the cell behind it is already on the way here (a cycle)
    passed,          // the frustum is narrowed to it and the cell behind is visited
};
struct PortalTested {
    static constexpr std::string_view kind = "PortalTested";
    std::uint32_t portal;
    PortalVerdict verdict;
    std::vector<Vec3> visible_part;  // of the opening, clipped by the frustum (empty unless passed)
    std::vector<Plane> narrowed;     // passed: the new frustum's side planes
    bool operator==(const PortalTested&) const = default;
};
enum class CullReason : std::uint8_t { back_face, frustum };
struct CellPolygonCulled {
    static constexpr std::string_view kind = "CellPolygonCulled";
    std::uint32_t polygon;
    CullReason reason;
    bool operator==(const CellPolygonCulled&) const = default;
};
struct CellPolygonDrawn {
    static constexpr std::string_view kind = "CellPolygonDrawn";
    std::uint32_t polygon;
    std::vector<Vec3> visible_part;  // clipped by the frustum
    bool operator==(const CellPolygonDrawn&) const = default;
};
struct PortalBoundReached {
    static constexpr std::string_view kind = "PortalBoundReached";
    std::uint32_t cell;    // the recursion stopped before entering it; the rest of the PVS row is drawn unnarrowed
    std::uint64_t limit;
    bool operator==(const PortalBoundReached&) const = default;
};
struct PortalRenderFinished {
    static constexpr std::string_view kind = "PortalRenderFinished";
    std::uint32_t visits, drawn, culled_back_face, culled_frustum, portals_passed;
    bool operator==(const PortalRenderFinished&) const = default;
};
using PortalEvent = std::variant<EyeLocated, PvsRowRead, CellVisited, PortalTested, CellPolygonCulled, CellPolygonDrawn,
                                 PortalBoundReached, PortalRenderFinished>;

struct CellModel;
// Sentences with the cells' names from the model.
// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const PvsEvent& e, const CellModel& model);
Phrase phrase(const PortalEvent& e, const CellModel& model);
std::string describe(const PvsEvent& e, const CellModel& model);
std::string describe(const PortalEvent& e, const CellModel& model);
const Saying& term(PortalVerdict v);  // words to translate
const Saying& term(CullReason r);
std::span<const Saying> portal_sayings();  // every template the PVS and portal machines say
std::string_view to_string(PortalVerdict v);
std::string_view to_string(CullReason r);

}  // namespace hsr::algo
