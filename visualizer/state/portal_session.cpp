// SPDX-License-Identifier: MIT
#include "state/portal_session.h"

#include <algorithm>

#include "core/overloaded.h"
#include "scene/random_scene.h"
#include "state/long_work.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

const Pseudocode<PvsEvent> pvs_lines = {
    {"for each cell c:  StabTree(c)", {}},
    {"StabTree(c):  c sees itself; for each portal P out of c: Stab(c, [P])", {step<StabTreeStarted>()}},
    {"Stab(c, portals):", {}},
    {"  if no sightline passes through all the portals: return", {step<SightlineTested>()}},
    {"  add the cell c' behind the last portal to PVS(c)", {micro<CellReached>()}},
    {"  for each portal P' out of c' (not back on the way):", {}},
    {"    Stab(c, portals + P')", {step<StabBoundReached>()}},
    {"the PVS matrix: row c = PVS(c)", {step<PvsBuilt>()}},
};

const Pseudocode<PortalEvent> render_lines = {
    {"main():", {}},
    {"  determine cell c of viewpoint using BSP tree", {step<EyeLocated>()}},
    {"  determine PVS of cell c using PVS matrix", {step<PvsRowRead>()}},
    {"  f = original view frustum; portal_render(c, f, PVS)", {step<CellVisited>([](const CellVisited& e) { return e.depth == 0; }), step<PortalRenderFinished>()}},
    {"portal_render(cell c, frustum f, list PVS):", {}},
    {"  for each polygon R in c:", {}},
    {"    if (R is portal) & (c' in PVS):", {}},
    {"      f' = clip_frustum(f, R)", {step<PortalTested>([](const PortalTested& e) { return e.verdict == PortalVerdict::passed; })}},
    {"      if (f' <> empty) portal_render(c', f', PVS)", {step<CellVisited>(), step<PortalTested>([](const PortalTested& e) { return e.verdict != PortalVerdict::not_in_pvs; }), step<PortalBoundReached>()}},
    {"    else if (R is portal) {}", {step<PortalTested>()}},
    {"    else:  /* R is not portal */", {}},
    {"      if (!back_face(R)):", {micro<CellPolygonCulled>([](const CellPolygonCulled& e) { return e.reason == CullReason::back_face; })}},
    {"        R' = clip_poly(f, R)", {}},
    {"        if (R' <> empty) render(R')", {micro<CellPolygonCulled>(), micro<CellPolygonDrawn>()}},
};

}  // namespace

PvsSession::RunType PvsSession::machine(const Lesson& lesson) {
    auto world = portal_world(lesson.scene);
    PvsView initial;
    initial.world = world;
    initial.matrix.assign(world->pvs.matrix.size(), 0);
    return {build_pvs(&world->model), std::move(initial)};
}

std::shared_ptr<const PortalWorld> portal_world(const Scene& scene) {
    auto w = std::make_shared<PortalWorld>();
    w->model = cell_model(scene);
    w->bsp = build_cell_bsp(w->model);
    w->pvs = LongWork::run_to_end(build_pvs(&w->model));
    return w;
}

// ── [SECTION] the pre-processing ─────────────────────────────────────────────────────────────────────────────
void reduce(PvsView& v, const PvsEvent& event) {
    std::visit(overloaded{
                   [&](const StabTreeStarted& e) {
                       v.source = std::int32_t(e.cell), v.tree = {{e.cell, -1, -1}}, v.sequence.clear();
                       v.matrix[std::size_t(e.cell) * v.world->pvs.cells + e.cell] = 1;
                   },
                   [&](const SightlineTested& e) {
                       v.sequence = e.portals, v.found = e.found, v.blocked_in_3d = e.blocked_in_3d, ++v.tests;
                       v.sight_point = e.point, v.sight_direction = e.direction;
                   },
                   [&](const CellReached& e) {
                       v.matrix[std::size_t(e.source) * v.world->pvs.cells + e.cell] = 1;
                       v.tree.push_back({e.cell, e.parent, e.portal});
                   },
                   [&](const StabBoundReached&) { v.bounded = true; },
                   [&](const PvsBuilt&) { v.done = true, v.matrix = v.world->pvs.matrix; },
               },
               event);
}

std::size_t approx_bytes(const PvsView& v) {
    return sizeof(PvsView) + v.matrix.capacity() + v.tree.capacity() * sizeof(StabNode) + v.sequence.capacity() * 4;
}

PvsSession::PvsSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string PvsSession::sentence_of(const PvsEvent& e, const PvsView& view) { return describe(e, view.world->model); }
std::string PvsSession::describe_event(const PvsEvent& e) const { return sentence_of(e, view()); }
std::string PvsSession::speak_event(const PvsEvent& e) const { return window_strings().say(phrase(e, view().world->model)); }

// ── [SECTION] the runtime ───────────────────────────────────────────────────────────────────────────────────
void reduce(PortalView& v, const PortalEvent& event) {
    std::visit(overloaded{
                   [&](const EyeLocated& e) { v.eye_cell = e.cell, v.bsp_path = e.path; },
                   [&](const PvsRowRead& e) { v.pvs_row = e.visible; },
                   [&](const CellVisited& e) {
                       // the way here: as deep as the depth, the narrowing that led here last
                       v.path.resize(e.depth), v.passed.resize(std::min<std::size_t>(v.passed.size(), e.depth));
                       v.path.push_back(e.cell);
                       v.cell = std::int32_t(e.cell), v.frustum = e.frustum, v.visited[e.cell] = 1, ++v.visits;
                       v.portal = -1, v.polygon = -1;
                   },
                   [&](const PortalTested& e) {
                       v.portal = std::int32_t(e.portal), v.verdict = e.verdict;
                       // back in the cell the portal leads out of: the way here ends there
                       const std::uint32_t from = v.world->model.portals[e.portal].from;
                       const auto at = std::find(v.path.rbegin(), v.path.rend(), from);
                       if (at != v.path.rend()) {
                           const auto depth = std::size_t(v.path.rend() - at) - 1;
                           v.path.resize(depth + 1), v.passed.resize(std::min(v.passed.size(), depth));
                           v.cell = std::int32_t(from);
                       }
                       if (e.verdict != PortalVerdict::passed) return;
                       ++v.portals_passed;
                       v.passed.push_back({e.portal, e.visible_part, frustum_section(e.narrowed, v.camera, 1.0)});
                   },
                   [&](const CellPolygonCulled& e) {
                       v.polygon = std::int32_t(e.polygon);
                       if (v.fate[e.polygon] == PolygonFate::drawn) return;  // drawn through another portal already
                       v.fate[e.polygon] = e.reason == CullReason::back_face ? PolygonFate::back_face : PolygonFate::frustum;
                       ++(e.reason == CullReason::back_face ? v.culled_back_face : v.culled_frustum);
                   },
                   [&](const CellPolygonDrawn& e) {
                       v.polygon = std::int32_t(e.polygon);
                       if (v.fate[e.polygon] != PolygonFate::drawn) ++v.drawn;
                       v.fate[e.polygon] = PolygonFate::drawn;
                   },
                   [&](const PortalBoundReached&) { v.bounded = true; },
                   [&](const PortalRenderFinished&) { v.done = true, v.cell = -1, v.portal = -1, v.polygon = -1; },
               },
               event);
}

std::vector<std::uint32_t> named_polygons(const PortalView& v) {
    std::vector<std::uint32_t> out;
    if (v.cell < 0) return out;
    if (v.polygon >= 0) out.push_back(std::uint32_t(v.polygon));
    for (std::uint32_t p : v.world->model.cells[std::size_t(v.cell)].polygons)
        if (v.fate[p] == PolygonFate::untouched) {  // the cell tests its polygons in this order
            out.push_back(p);
            break;
        }
    return out;
}

std::vector<Vec3> exact_section(const PortalView::Narrowing& n, const Camera& camera) {
    const Vec3 ahead = glm::normalize(camera.target - camera.eye);
    std::vector<Vec3> out;
    for (const Vec3& q : n.visible_part)
        if (const double d = glm::dot(q - camera.eye, ahead); d > 1e-12) out.push_back(camera.eye + (q - camera.eye) / d);
    return out;
}

bool wider_than_exact(const PortalView::Narrowing& n, const Camera& camera) {
    // each corner of the section 1 unit ahead, against the visible part's corners seen from the eye at that distance
    const std::vector<Vec3> exact = exact_section(n, camera);
    if (exact.size() != n.section.size()) return true;
    for (const Vec3& q : n.section)
        if (std::none_of(exact.begin(), exact.end(), [&](const Vec3& r) { return glm::length(q - r) < 1e-6; })) return true;
    return false;
}

std::size_t approx_bytes(const PortalView& v) {
    std::size_t b = sizeof(PortalView) + v.visited.capacity() + v.fate.capacity() + v.frustum.capacity() * sizeof(Plane) +
                    (v.pvs_row.capacity() + v.path.capacity()) * 4 + v.bsp_path.capacity() * 4;
    for (const auto& n : v.passed) b += sizeof(n) + n.visible_part.capacity() * sizeof(Vec3);
    return b;
}

namespace {

PortalRenderSession::RunType render_run(std::shared_ptr<const PortalWorld> world, const Camera& camera, bool bbox) {
    PortalView initial;
    initial.world = world;
    initial.camera = camera;
    initial.visited.assign(world->model.cells.size(), 0);
    initial.fate.assign(world->model.polygons.size(), PolygonFate::untouched);
    return {portal_render(&world->model, &world->bsp, &world->pvs, camera, {.bounding_box_frusta = bbox}), std::move(initial)};
}

}  // namespace

PortalRenderSession::RunType PortalRenderSession::machine(const Lesson& lesson) {
    auto world = portal_world(lesson.scene);
    return render_run(world, world->model.camera, machine_of<PortalMachine>(lesson) == PortalMachine::render_bbox);
}

PortalRenderSession::PortalRenderSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options),
      world_(view().world),
      bbox_(machine_of<PortalMachine>(lesson) == PortalMachine::render_bbox),
      options_(options) {}

PortalRenderSession::PlayerType PortalRenderSession::make_player(const Camera& camera) const {
    auto run = render_run(world_, camera, bbox_);
    return PlayerType(std::move(run.machine), std::move(run.initial), options_);
}

void PortalRenderSession::move_eye(Vec2 plan) {
    Camera c = view().camera;
    const Vec3 look = c.target - c.eye;
    c.eye = {plan.x, c.eye.y, -plan.y};
    c.target = c.eye + look;
    replace_player(make_player(c));
}

std::string PortalRenderSession::sentence_of(const PortalEvent& e, const PortalView& view) { return describe(e, view.world->model); }
std::string PortalRenderSession::describe_event(const PortalEvent& e) const { return sentence_of(e, view()); }
std::string PortalRenderSession::speak_event(const PortalEvent& e) const { return window_strings().say(phrase(e, view().world->model)); }

const Pseudocode<PvsEvent>& PvsSession::table() const { return pvs_lines; }
const Pseudocode<PortalEvent>& PortalRenderSession::table() const { return render_lines; }

const FamilyFacts PvsSession::facts = {
    .topic = "Cells and portals",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return !s.expect.pvs.empty(); },
    .random_scene = [](std::uint32_t seed, bool) -> std::optional<algo::Scene> { return algo::cell_maze({.rows = 4, .cols = 4, .seed = seed}); },
    .measure = &analysis::measure_portals,
};

const FamilyFacts PortalRenderSession::facts = PvsSession::facts;  // the same scenes and measurements as the pre-processing

}  // namespace hsr::viz
