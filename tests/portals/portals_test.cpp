// SPDX-License-Identifier: MIT
// Cells and portals: the PVS matches the lecture's example and is symmetric and conservative (a 2D ray walk from
// random points never sees a cell outside it); the BSP finds the cell brute force finds; portal_render draws every
// polygon a ray cast from the eye sees; and the extremes (an eye in an opening, a portal edge-on, an eye in a wall,
// cycles, 1000 cells) end well.
#include <algorithm>
#include <random>

#include <glm/geometric.hpp>

#include "catch.h"
#include "analysis/portal_coverage.h"
#include "portals/plan_ray.h"
#include "portals/portal_render.h"
#include "raycast/nearest_hit.h"
#include "raycast/ray_cast.h"
#include "scene/load_scene.h"

using namespace hsr::algo;
using namespace hsr::analysis;

namespace {

Scene scene_named(const std::string& name) { return load_scene(std::string(HSR_SOURCE_DIR "/assets/scenes/") + name); }

std::uint32_t named(const CellModel& m, const std::string& name) {
    return std::uint32_t(std::find_if(m.cells.begin(), m.cells.end(), [&](const Cell& c) { return c.name == name; }) - m.cells.begin());
}

struct Built {
    CellModel model;
    CellBsp bsp;
    Pvs pvs;
};
Built build(const Scene& s) {
    Built b{cell_model(s), {}, {}};
    b.bsp = build_cell_bsp(b.model);
    b.pvs = build_pvs(&b.model).run_to_end();
    return b;
}

Coverage coverage(const Built& b, const PortalRenderResult& r, Viewport vp) { return portal_coverage(b.model, r, vp); }

void look_from(Built& b, Vec2 eye, Vec2 look) {
    b.model.camera.eye = world_point(eye, 1.6);
    b.model.camera.target = world_point(look, 1.4);
}

}  // namespace

TEST_CASE("the lecture's A-E example: the PVS matrix, symmetric, from stab trees", "[portals][pvs]") {
    const Built b = build(scene_named("cells_lecture.toml"));
    const auto& m = b.model;
    for (std::uint32_t i = 0; i < b.pvs.cells; ++i)
        for (std::uint32_t j = 0; j < b.pvs.cells; ++j) {
            INFO(m.cells[i].name << " and " << m.cells[j].name);
            CHECK(b.pvs.visible(i, j) == b.pvs.visible(j, i));
        }
    // the lecture's matrix: A sees D and E; B sees C and E; neither sees the other, nor A sees C
    CHECK(b.pvs.visible(named(m, "A"), named(m, "D")));
    CHECK_FALSE(b.pvs.visible(named(m, "A"), named(m, "C")));
    CHECK_FALSE(b.pvs.visible(named(m, "B"), named(m, "D")));
    CHECK(b.pvs.row(named(m, "E")).size() == 5);
    // E's stab tree reaches A through D: A's node has D's node as its parent
    const auto& tree = b.pvs.trees[named(m, "E")];
    const auto a = std::find_if(tree.begin(), tree.end(), [&](const StabNode& n) { return n.cell == named(m, "A"); });
    REQUIRE(a != tree.end());
    CHECK(tree[std::size_t(a->parent)].cell == named(m, "D"));
    CHECK_FALSE(b.pvs.bounded);
}

TEST_CASE("the from-region PVS is conservative: a ray from anywhere in a cell sees only cells in its PVS", "[portals][pvs]") {
    for (const char* file : {"cells_lecture.toml", "cells_l_corridor.toml", "cells_ring.toml", "cells_general.toml"}) {
        INFO(file);
        const Built b = build(scene_named(file));
        const PvsSampling sampled = sample_pvs(b.model, b.pvs, 2000, 7);
        CHECK(sampled.missed == 0);
        // in the PVS, never seen by these rays (the report gives it per scene)
        const std::uint64_t slack = sampled.slack, pairs = sampled.pairs;
        CHECK(slack * 5 <= pairs);  // the rays find most pairs the PVS holds: it is not "everything visible"
    }
}

TEST_CASE("the PVS is conservative in 3D: rays at any height and slope through windows and doors reach only PVS cells", "[portals][pvs][3d]") {
    int through_two = 0;  // rays that pass two openings in a row, over all the scenes
    for (const char* file : {"cells_lecture.toml", "cells_ring.toml", "cells_general.toml", "cells_windows_3d.toml", "cells_shaped_openings.toml"}) {
        INFO(file);
        const Built b = build(scene_named(file));
        PortableRandom rng(17);
        const auto unit = [&](PortableRandom& r) { return r.uniform(-1, 1); };
        const auto height = [&](PortableRandom& r) { return r.uniform(0.05, b.model.height - 0.05); };
        int outside_pvs = 0, through_one = 0;
        for (std::uint32_t c = 0; c < b.pvs.cells; ++c)
            for (int k = 0; k < 4000; ++k) {
                const Vec2 at = random_point_in(b.model.cells[c].outline, rng);
                Vec3 d(unit(rng), 0.4 * unit(rng), unit(rng));
                if (glm::length(d) < 1e-3) continue;
                const auto cells = cells_along_ray(b.model, c, world_point(at, height(rng)), d);
                through_one += cells.size() >= 2, through_two += cells.size() >= 3;
                for (std::uint32_t s : cells) outside_pvs += !b.pvs.visible(c, s);
            }
        CHECK(outside_pvs == 0);
        CHECK(through_one > 0);  // the rays do pass openings: the check is not empty
    }
    CHECK(through_two > 100);
}

TEST_CASE("windows at different heights: the plan sees through, the 3D test does not, and says why", "[portals][pvs][3d]") {
    const Scene s = scene_named("cells_windows_3d.toml");
    const CellModel m = cell_model(s);
    auto machine = build_pvs(&m);
    int blocked = 0;
    for (const auto& e : machine)
        if (const auto* t = std::get_if<SightlineTested>(&e); t && t->blocked_in_3d) {
            ++blocked;
            CHECK_FALSE(t->found);
            CHECK(t->line_space_area > 0);  // the plan's sightlines exist
        }
    CHECK(blocked == 2);  // A→B→C→D and D→C→B→A
    const Pvs& pvs = machine.result();
    CHECK_FALSE(pvs.visible(named(m, "A"), named(m, "D")));
    CHECK(pvs.visible(named(m, "A"), named(m, "C")));
    // a ray that climbs through the low window and the high one cannot come down to the last low one
    CHECK(cells_along_ray(m, named(m, "A"), world_point({1.9, 1.0}, 0.6), Vec3(1, 1, 0)) ==
          std::vector<std::uint32_t>{named(m, "A"), named(m, "B"), named(m, "C")});
}

TEST_CASE("openings of any shape: the wall pieces round them cover the wall but the opening, once", "[portals][shapes]") {
    const Built b = build(scene_named("cells_shaped_openings.toml"));
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> along(0.01, 2.99), height(0.01, 2.99);
    for (const Portal& p : b.model.portals) {
        INFO(b.model.cells[p.from].name << " to " << b.model.cells[p.to].name);
        int in_opening_count = 0;
        for (int k = 0; k < 3000; ++k) {
            // a point of the wall (x = 3 or 6, plan y in [0, 3]), and a ray to it from inside `from`, square on
            const Vec3 at = world_point({p.left.x, along(rng)}, height(rng));
            const Vec3 from_inside = at - 0.5 * p.plane.n;
            const Ray ray{from_inside, p.plane.n};
            int walls_hit = 0;
            for (std::uint32_t q : b.model.cells[p.from].polygons) {
                const CellPolygon& poly = b.model.polygons[q];
                if (std::abs(poly.plane.distance(at)) < 1e-9 && hit(ray, poly.vertices, poly.plane)) ++walls_hit;
            }
            const bool open = in_opening(p, at, 1e-6);
            const bool on_edge = !open && in_opening(p, at, -1e-6);
            if (on_edge) continue;  // within a micron of the opening's edge: either may claim it
            in_opening_count += open;
            CHECK(walls_hit == (open ? 0 : 1));
        }
        CHECK(in_opening_count > 100);
    }
}

TEST_CASE("cell location by the BSP tree agrees with testing every cell, for 10^5 random points", "[portals][bsp]") {
    const Scene s = scene_named("cells_chain_1000.toml");
    const CellModel m = cell_model(s);
    const CellBsp bsp = build_cell_bsp(m);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-2, 42), y(-2, 102);
    int disagree = 0, inside_some = 0;
    std::size_t deepest = 0;
    for (int k = 0; k < 100000; ++k) {
        const Vec2 p(x(rng), y(rng));
        const CellLocation where = locate_cell(bsp, p);
        const auto truth = cell_at(m, p);
        disagree += where.cell != truth;
        inside_some += truth.has_value();
        deepest = std::max(deepest, where.path.path.size());
    }
    CHECK(disagree == 0);
    CHECK(inside_some > 30000);
    CHECK(deepest < 64);  // O(log n_c) for 1000 cells, with some splitting: far from 1000
}

TEST_CASE("portal_render draws every polygon a ray cast from the eye sees", "[portals][render]") {
    const bool bbox = GENERATE(false, true);
    INFO((bbox ? "bounding-box frusta" : "exact frusta"));
    for (const char* file : {"cells_lecture.toml", "cells_l_corridor.toml", "cells_ring.toml", "cells_general.toml",
                             "cells_windows_3d.toml", "cells_shaped_openings.toml"}) {
        INFO(file);
        Built b = build(scene_named(file));
        PortableRandom rng(11);
        const auto angle = [](PortableRandom& r) { return r.uniform(0, 2 * M_PI); };
        for (std::uint32_t c = 0; c < b.pvs.cells; ++c)
            for (int k = 0; k < 3; ++k) {
                const Vec2 eye = random_point_in(b.model.cells[c].outline, rng, 0.2);
                const double a = angle(rng);
                look_from(b, eye, eye + Vec2(std::cos(a), std::sin(a)));
                const PortalRenderResult r = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera, {.bounding_box_frusta = bbox}).run_to_end();
                INFO("eye (" << eye.x << ", " << eye.y << ") in " << b.model.cells[c].name);
                REQUIRE(r.eye_cell == std::int32_t(c));
                const Coverage cover = coverage(b, r, {48, 36});
                CHECK(cover.missed == 0);
                CHECK(cover.seen > 0);
            }
    }
}

TEST_CASE("narrowing pays: exact frusta draw fewer polygons than bounding-box ones, and the PVS alone more", "[portals][render]") {
    SECTION("through a window seen obliquely, the bounding box takes in a crate the exact frustum leaves out") {
        Built b = build(scene_named("cells_general.toml"));
        const PortalRenderResult exact = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera).run_to_end();
        const PortalRenderResult boxed = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera, {.bounding_box_frusta = true}).run_to_end();
        const auto crate = std::size_t(std::find_if(b.model.polygons.begin(), b.model.polygons.end(), [](const CellPolygon& p) { return p.id == 903; }) -
                                       b.model.polygons.begin());
        CHECK_FALSE(exact.drawn[crate]);
        CHECK(boxed.drawn[crate]);
        CHECK(std::count(exact.drawn.begin(), exact.drawn.end(), 1) < std::count(boxed.drawn.begin(), boxed.drawn.end(), 1));
        CHECK(coverage(b, exact, {64, 48}).missed == 0);
    }
    Built b = build(scene_named("cells_lecture.toml"));
    const PortalRenderResult exact = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera).run_to_end();
    const PortalRenderResult boxed = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera, {.bounding_box_frusta = true}).run_to_end();
    const auto count = [](const PortalRenderResult& r) { return std::count(r.drawn.begin(), r.drawn.end(), 1); };
    std::size_t in_pvs = 0;
    for (std::uint32_t c : b.pvs.row(std::uint32_t(exact.eye_cell))) in_pvs += b.model.cells[c].polygons.size();
    CHECK(count(exact) <= count(boxed));
    CHECK(count(boxed) < std::int64_t(in_pvs));
    CHECK(exact.eye_cell == std::int32_t(named(b.model, "E")));
}

TEST_CASE("portal extremes: an eye in an opening, a portal edge-on, an eye in a wall, cycles, 1000 cells", "[portals][extremes]") {
    SECTION("an eye standing in an opening sees into both cells") {
        Built b = build(scene_named("cells_lecture.toml"));
        look_from(b, {5.0, 2.0}, {5.0, 5.0});  // in the opening E→C, looking into C and B
        const PortalRenderResult r = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera).run_to_end();
        CHECK(r.eye_cell >= 0);
        CHECK(coverage(b, r, {48, 36}).missed == 0);
    }
    SECTION("a portal seen edge-on passes nothing, and misses nothing") {
        // The eye in E stands in the plane of the opening S→W (y = 2), which it sees edge-on from the side: it is
        // rejected, and the ray cast sees nothing through it either. (An eye nearer a wall than the near distance
        // would see through the wall, in any renderer: the near plane cuts the wall away. Not tested here.)
        Built b = build(scene_named("cells_ring.toml"));
        look_from(b, {5.0, 2.0}, {0.0, 2.0});
        auto m = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera);
        bool edge_on_rejected = false;
        for (const auto& e : m)
            if (const auto* t = std::get_if<PortalTested>(&e); t && b.model.cells[b.model.portals[t->portal].to].name == "W")
                edge_on_rejected |= t->verdict == PortalVerdict::faces_away;
        CHECK(edge_on_rejected);
        CHECK(coverage(b, m.result(), {48, 36}).missed == 0);
    }
    SECTION("an eye in a wall or outside the plan is in no cell, and nothing is drawn") {
        Built b = build(scene_named("cells_ring.toml"));
        look_from(b, {3.0, 3.0}, {5, 5});  // inside the pillar
        const PortalRenderResult r = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera).run_to_end();
        CHECK(r.eye_cell == -1);
        CHECK(std::count(r.drawn.begin(), r.drawn.end(), 1) == 0);
    }
    SECTION("a cycle in the cell graph ends, the traversal never re-entering a cell on its way") {
        Built b = build(scene_named("cells_ring.toml"));
        const auto machine = [&] { return portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera); };
        std::size_t events = 0;
        auto m = machine();
        for (const auto& e : m) events += 1 + 0 * e.index();
        CHECK(events < 1000);
        CHECK_FALSE(m.result().bounded);
    }
    SECTION("a depth bound ends with its event and stays conservative") {
        Built b = build(scene_named("cells_lecture.toml"));
        auto m = portal_render(&b.model, &b.bsp, &b.pvs, b.model.camera, {.max_depth = 1});
        bool bound = false;
        for (const auto& e : m) bound |= std::holds_alternative<PortalBoundReached>(e);
        CHECK(bound);
        CHECK(m.result().bounded);
        CHECK(coverage(b, m.result(), {48, 36}).missed == 0);
    }
    SECTION("1000 chained cells: the PVS is built within its bounds and stays small") {
        const Built b = build(scene_named("cells_chain_1000.toml"));
        CHECK_FALSE(b.pvs.bounded);
        std::uint64_t pairs = 0;
        for (std::uint8_t v : b.pvs.matrix) pairs += v;
        CHECK(pairs < 1000 * 40);  // each room sees a few along its row, not the whole chain
        CHECK(pairs >= 1000 * 3);  // itself and at least its two neighbours
    }
    SECTION("a stab-tree bound counts what lies beyond as visible") {
        const Scene s = scene_named("cells_l_corridor.toml");
        const CellModel m = cell_model(s);
        const Pvs pvs = build_pvs(&m, {.max_depth = 1}).run_to_end();
        CHECK(pvs.bounded);
        CHECK(pvs.row(named(m, "S1")).size() == 6);  // every cell reachable, conservatively
    }
}
