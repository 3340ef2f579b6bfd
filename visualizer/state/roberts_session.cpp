// SPDX-License-Identifier: MIT
#include "state/roberts_session.h"

#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/numeric.h"
#include "core/overloaded.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The Brown notes' Roberts (object precision): "compare each edge with every object".
const Pseudocode<RobertsEvent> roberts_lines = {
    {"bodies = the convex solids; edges = their edges", {step<BodiesFound>()}},
    {"for each edge E of each body:", {}},
    {"  if both faces of E face away: remove E", {step<EdgeRemoved>()}},
    {"  for each other body B:", {}},
    {"    hidden by B = the points of E whose segment", {}},
    {"      to the eye passes through B's inside", {micro<EdgeTested>()}},
    {"  draw what is left of E", {step<EdgeFinished>()}},
    {"done", {step<RobertsFinished>()}},
};

// Four boxes turned at random in front of the camera, apart enough to be convex bodies of their own.
std::optional<Scene> random_boxes(std::uint32_t seed, bool) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-2.5, 2.5), size(0.4, 1.2), angle(0, 3.1);
    Scene s;
    s.name = "random boxes " + std::to_string(seed);
    s.camera.eye = {1, 2, 11}, s.camera.target = {0, 0, 0}, s.camera.near = 1, s.camera.far = 30;
    for (int b = 0; b < 4; ++b) {
        const Vec3 c(pos(rng), pos(rng), pos(rng)), h(size(rng), size(rng), size(rng));
        const glm::dmat4 turn = glm::rotate(glm::dmat4(1), angle(rng), glm::normalize(Vec3(pos(rng), 3, pos(rng))));
        const auto corner = [&](int i) {
            return c + Vec3(turn * glm::dvec4((i & 1 ? 1 : -1) * h.x, (i & 2 ? 1 : -1) * h.y, (i & 4 ? 1 : -1) * h.z, 0));
        };
        const Color colour{std::uint8_t(90 + 40 * b), std::uint8_t(200 - 30 * b), 230};
        static constexpr int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& q : quads) {
            ScenePolygon p;
            p.id = SceneId(s.polygons.size() + 1), p.color = colour;
            for (int k : q) p.vertices.emplace_back(corner(k), 1.0);
            s.polygons.push_back(p);
        }
    }
    try {
        (void)convex_bodies(s);  // boxes that touch or overlap share no edge, but say so if they did
    } catch (const InvalidInput&) {
        return std::nullopt;
    }
    return s;
}

}  // namespace

RobertsView roberts_initial_view(const Scene& scene) {
    RobertsView v;
    v.input = std::make_shared<const LineDrawingInput>(convex_bodies(scene));
    v.edges.resize(v.input->edges.size());
    return v;
}

RobertsSession::RunType RobertsSession::machine(const Lesson& lesson) {
    RobertsView initial = roberts_initial_view(lesson.scene);
    return {roberts(lesson.scene), std::move(initial)};
}

void reduce(RobertsView& v, const RobertsEvent& event) {
    std::visit(overloaded{
                   [&](const BodiesFound&) {},
                   [&](const EdgeRemoved& e) {
                       v.edges[e.edge].removed = v.edges[e.edge].finished = true;
                       v.edge = int(e.edge), v.by = -1, v.last_test.reset();
                       ++v.removed;
                   },
                   [&](const EdgeTested& e) {
                       if (e.hides) v.edges[e.edge].hidden.emplace_back(e.t0, e.t1);
                       v.edge = int(e.edge), v.by = int(e.by), v.last_test = e;
                       ++v.tests;
                   },
                   [&](const EdgeFinished& e) {
                       RobertsEdgeView& edge = v.edges[e.edge];
                       std::sort(edge.hidden.begin(), edge.hidden.end());
                       std::vector<std::pair<double, double>> merged;
                       for (const auto& p : edge.hidden)
                           if (!merged.empty() && p.first <= merged.back().second) merged.back().second = std::max(merged.back().second, p.second);
                           else merged.push_back(p);
                       edge.hidden = std::move(merged);
                       edge.finished = true;
                       v.edge = int(e.edge), v.by = -1, v.last_finished = e;
                       v.drawn += e.pieces > 0;
                   },
                   [&](const RobertsFinished&) { v.done = true, v.edge = -1, v.by = -1; },
               },
               event);
}

std::size_t approx_bytes(const RobertsView& v) {
    std::size_t n = sizeof(RobertsView) + v.edges.capacity() * sizeof(RobertsEdgeView);
    for (const auto& e : v.edges) n += e.hidden.capacity() * sizeof(std::pair<double, double>);
    return n;
}

RobertsSession::RobertsSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string RobertsSession::sentence_of(const RobertsEvent& e, const RobertsView&) { return describe(e); }
std::string RobertsSession::describe_event(const RobertsEvent& e) const { return sentence_of(e, view()); }
std::string RobertsSession::speak_event(const RobertsEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<RobertsEvent>& RobertsSession::table() const { return roberts_lines; }

const FamilyFacts RobertsSession::facts = {
    .topic = "Hidden lines",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &random_boxes,
    .measure = &analysis::measure_roberts,
};

}  // namespace hsr::viz
