// SPDX-License-Identifier: MIT
// Practice for cells and portals: a row of square rooms, each opening into the next through a gap in the wall they
// share. Which is the farthest room in the PVS of the first, the last one some sightline from it reaches through
// every opening on the way? Every answer is an event of the PVS lesson's own machine (its stab tree from room A) on
// the exercise's floor plan.
#include <cmath>
#include <cstdio>

#include "portals/cell_model.h"
#include "portals/pvs.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"

namespace hsr::viz::practice {
namespace {

constexpr double room = 2;  // each room is room × room in the plan

std::string room_name(std::size_t k) { return std::string(1, char('A' + k)); }

// What the question says, each template once (the catalogues' [exercise.portals] translate them).
namespace say {
using algo::Saying;
constexpr Saying farthest{"portals.farthest",
                          "Cells and portals: {rooms} square rooms in a row, {size} × {size} each in the plan, A from x = 0 to "
                          "{size}, B next to it, and so on, all from y = 0 to {size}. The openings in the walls: {openings}. "
                          "Which is the farthest room in A's PVS (some sightline from A reaches it through every opening on "
                          "the way)?"};
constexpr Saying opening{"portals.opening", "{from}–{to} at x = {x} from y = {y0} to {y1}"};
constexpr Saying all[] = {farthest, opening};
}  // namespace say

struct Opening {
    double y0, y1;  // in the wall x = room · (k + 1) between rooms k and k + 1
};

// Four rooms (easy) or five; openings 0.4 … 0.8 wide (hard: 0.2 … 0.5) anywhere along their wall, on a 0.1 grid.
std::vector<Opening> draw_openings(Dice& d, Level l) {
    const int rooms = l == Level::easy ? 4 : 5;
    std::vector<Opening> o;
    for (int k = 0; k + 1 < rooms; ++k) {
        const double width = l == Level::hard ? d.grid(2, 5, 1) / 10 : d.grid(4, 8, 1) / 10;
        const double y0 = d.grid(1, std::round((room - 0.1 - width) * 10), 1) / 10;
        o.push_back({y0, std::round((y0 + width) * 10) / 10});  // 1.3, not 1.2999999999999998
    }
    return o;
}

algo::Scene scene_of(const std::vector<Opening>& openings) {
    algo::Scene scene;
    scene.name = "a row of rooms";
    scene.camera.fov_y = 70;
    scene.camera.aspect = 4.0 / 3;
    scene.camera.near = 0.05;
    scene.camera.far = 40;
    algo::FloorPlan& plan = scene.floor_plan;
    plan.height = 2.5;
    for (std::size_t k = 0; k <= openings.size(); ++k) {
        const double x0 = room * double(k);
        plan.cells.push_back({room_name(k), {{x0, 0}, {x0 + room, 0}, {x0 + room, room}, {x0, room}}, 0});
    }
    for (std::size_t k = 0; k < openings.size(); ++k) {
        const double x = room * double(k + 1);
        plan.portals.push_back({{room_name(k), room_name(k + 1)}, {x, openings[k].y0}, {x, openings[k].y1}, 0, 0, {}, 0});
    }
    plan.eye = glm::dvec2(0.3, room / 2);  // in room A, looking down the row
    plan.look = glm::dvec2(room * double(openings.size() + 1), room / 2);
    return scene;
}

std::optional<Exercise> farthest_exercise(Dice& d, Level l) {
    const std::vector<Opening> openings = draw_openings(d, l);
    algo::Scene scene = scene_of(openings);
    const algo::CellModel model = algo::cell_model(scene);
    std::vector<algo::PvsEvent> events;
    auto machine = algo::build_pvs(&model);
    while (const algo::PvsEvent* e = machine.next()) events.push_back(*e);
    std::optional<std::size_t> started, farthest;
    std::uint32_t farthest_cell = 0;
    for (std::size_t step = 0; step < events.size(); ++step) {
        if (const auto* s = std::get_if<algo::StabTreeStarted>(&events[step]); s && s->cell == 0) started = step;
        if (const auto* t = std::get_if<algo::SightlineTested>(&events[step]); t && t->source == 0 && t->found &&
                                                                               t->line_space_area < 1e-3)
            return std::nullopt;  // a sightline so narrow that only a few rays find it: no fair question
        if (const auto* r = std::get_if<algo::CellReached>(&events[step]); r && r->source == 0 && r->cell >= farthest_cell)
            farthest = step, farthest_cell = r->cell;
    }
    if (!started || !farthest || farthest_cell == 0) return std::nullopt;
    Exercise e;
    std::vector<Wording> walls;
    nlohmann::json given_openings = nlohmann::json::array();
    for (std::size_t k = 0; k < openings.size(); ++k) {
        walls.push_back(Wording(say::opening, {{"from", room_name(k)},
                                               {"to", room_name(k + 1)},
                                               {"x", number_text(room * double(k + 1))},
                                               {"y0", number_text(openings[k].y0)},
                                               {"y1", number_text(openings[k].y1)}}));
        given_openings.push_back({room * double(k + 1), openings[k].y0, openings[k].y1});
    }
    e.ask(Wording(say::farthest, {{"rooms", std::to_string(openings.size() + 1)}, {"size", number_text(room)}}, {{"openings", walls}}));
    std::vector<Wording> rooms;
    for (std::size_t k = 1; k <= openings.size(); ++k) rooms.push_back(Wording::as_is(room_name(k)));
    e.offer(std::move(rooms), farthest_cell - 1);
    e.deciding = algo::describe(events[*farthest], model);
    e.deciding_step = *farthest;
    e.hold_at = *started;
    e.given = {{"kind", "farthest_visible"}, {"openings", given_openings}};
    e.scene = std::move(scene);
    e.algorithm = "portal_pvs";
    return e;
}

}  // namespace

std::vector<Topic> portal_topics() {
    return {{"portals", "Cells and portals: how far does A see?", {"portal_pvs", "portal_render", "portal_render_bbox"},
             [](Draw draw) {
                 Dice d(draw.seed);
                 return farthest_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
