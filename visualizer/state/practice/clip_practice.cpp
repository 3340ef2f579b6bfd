// SPDX-License-Identifier: MIT
// Practice for the three clippers of the notes: an endpoint's outcode and what the first test of the outcodes
// decides (Cohen–Sutherland), where the visible part starts or ends (Liang–Barsky), an edge's case and a stage's
// vertex count (Sutherland–Hodgman). Every answer is an event of the machine run on the exercise's own segment or
// polygon; the question only says what the student needs to compute it by hand.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "clipping/clip_events.h"
#include "clipping/clip_scene.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

using algo::ClipEvent;
using algo::ClipPlane;
using algo::ClipSpace;
using algo::Vec4;

// The notes' canonical cube and its 6-bit outcodes first; clip space before the divide (a seventh bit for w < ε)
// once the student knows the cube.
ClipSpace space_for(Level l) { return l == Level::easy ? ClipSpace::cube : ClipSpace::homogeneous; }

// What the questions say, each template once (the catalogues' [exercise.clip] translate them).
namespace say {
using algo::Saying;
constexpr Saying cube{"clip.cube", "in the canonical view volume −1 ≤ x, y, z ≤ 1"};
constexpr Saying clip_space{"clip.clip_space", "in clip space (inside: −w ≤ x, y, z ≤ w and w ≥ ε, ε a tiny positive number)"};
constexpr Saying bits_cube{"clip.bits_cube", "Bits in the notes' order: z > 1, z < −1, y > 1, y < −1, x > 1, x < −1."};
constexpr Saying bits_clip_space{"clip.bits_clip_space",
                                 "Bits in the notes' order: z > w, z < −w, y > w, y < −w, x > w, x < −w; then \"+w\" when w < ε."};
constexpr Saying outcode{"clip.outcode", "Cohen–Sutherland, {setting}: what is the outcode of {name} = {point}? {bits}"};
constexpr Saying trivial{"clip.trivial",
                         "Cohen–Sutherland, {setting}: the segment runs from p1 = {p1} to p2 = {p2}. What does the first test "
                         "of the two outcodes decide?"};
constexpr Saying accepted{"clip.accepted", "trivially accepted (c1 | c2 = 0)"};
constexpr Saying rejected{"clip.rejected", "trivially rejected (c1 & c2 ≠ 0)"};
constexpr Saying neither{"clip.neither", "neither: the segment is cut at a plane"};
constexpr Saying t_enter{"clip.t_enter",
                         "Liang–Barsky, {setting}: the segment p(t) = p1 + t (p2 − p1), 0 ≤ t ≤ 1, from p1 = {p1} to p2 = {p2}. "
                         "At which t does its visible part start (t_enter)? Two decimals are enough."};
constexpr Saying t_leave{"clip.t_leave",
                         "Liang–Barsky, {setting}: the segment p(t) = p1 + t (p2 − p1), 0 ≤ t ≤ 1, from p1 = {p1} to p2 = {p2}. "
                         "At which t does its visible part end (t_leave)? Two decimals are enough."};
constexpr Saying edge{"clip.edge",
                      "Sutherland–Hodgman, {setting}: stage {plane} ({inequality}) takes the edge from s = {s} to e = {e}. "
                      "Which case is it?"};
constexpr Saying in_in{"clip.in_in", "in→in: emits e"};
constexpr Saying in_out{"clip.in_out", "in→out: emits the intersection i"};
constexpr Saying out_out{"clip.out_out", "out→out: emits nothing"};
constexpr Saying out_in{"clip.out_in", "out→in: emits i, then e"};
constexpr Saying stage_count{"clip.stage_count",
                             "Sutherland–Hodgman, {setting}, clips the polygon {polygon} against one plane after another, in "
                             "the order {order}. How many vertices does the polygon have after stage {plane}?"};
constexpr Saying all[] = {cube, clip_space, bits_cube, bits_clip_space, outcode, trivial, accepted, rejected, neither,
                          t_enter, t_leave, edge, in_in, in_out, out_out, out_in, stage_count};
}  // namespace say

Wording setting(ClipSpace s) { return Wording(s == ClipSpace::cube ? say::cube : say::clip_space); }

nlohmann::json numbers(const Vec4& p) { return nlohmann::json::array({p.x, p.y, p.z, p.w}); }
std::string point_text(const Vec4& p, ClipSpace s) { return algo::format_point(p, s); }

// A student reads a point to six digits: no boundary value closer to 0 than this, or the exercise would turn on a
// rounding (and a point on a plane is where the notes' tests and a student's reading may part).
constexpr double reading_margin = 5e-4;

bool near_a_plane(const Vec4& p, ClipSpace s) {
    for (int k = 0; k < algo::plane_count(s); ++k)
        if (std::abs(algo::boundary_value(p, algo::all_planes[std::size_t(k)], s)) < reading_margin) return true;
    return false;
}

// The exercise's scene, as the window plays it: the segment or polygon in clip space, seen in the cube setting by
// an orthographic camera and in clip space by a perspective one (clip_job's rule).
algo::Scene exercise_scene(ClipSpace s, std::vector<Vec4> primitive, const std::string& name) {
    algo::Scene scene;
    scene.name = name;
    scene.coordinates = algo::Coordinates::clip;
    scene.camera.projection = s == ClipSpace::cube ? algo::Projection::orthographic : algo::Projection::perspective;
    scene.camera.near = 1;
    scene.camera.far = s == ClipSpace::cube ? 3 : 5;  // the cube drawn as a cube (its box is 2 × 2 wide and high)
    const algo::Color orange = algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange);
    if (primitive.size() == 2) scene.segments.push_back({1, orange, primitive[0], primitive[1]});
    else scene.polygons.push_back({1, orange, std::move(primitive)});
    return scene;
}

// The events of the machine the window plays on the scene: their index is the step a student sees.
std::vector<ClipEvent> play(const algo::Scene& scene, algo::ClipAlgorithm algorithm) {
    std::vector<ClipEvent> events;
    auto machine = algo::clip_scene(algo::clip_job(scene), algorithm);
    while (const ClipEvent* e = machine.next()) events.push_back(*e);
    return events;
}

// One coordinate, for a point whose w is given: on a grid of halves (easy) or tenths (medium) between −2.5w and
// 2.5w; at the hard level, one time in two, a thousandth or a few from ±w.
double coordinate(Dice& d, Level l, double w) {
    const double reach = 2.5 * std::abs(w);
    switch (l) {
        case Level::easy: return d.grid(-3, 3, 0.5);
        case Level::medium: return d.grid(-std::round(reach * 10), std::round(reach * 10), 1) / 10;
        case Level::hard:
            if (d.coin()) return (d.coin() ? 1 : -1) * (std::abs(w) * 1000 + d.grid(-9, 9, 1)) / 1000;
            return d.grid(-std::round(reach * 10), std::round(reach * 10), 1) / 10;
    }
    return 0;
}

// A point inside the volume (one time in three) or anywhere around it; its w drawn too unless given.
Vec4 draw_point(Dice& d, Level l, ClipSpace s, std::optional<double> given_w = {}) {
    double w = given_w.value_or(1);
    if (s == ClipSpace::homogeneous && !given_w) {
        w = d.grid(1, 8, 1) / 2;                                    // 0.5 … 4
        if (l == Level::hard && d.below(6) == 0) w = -w;            // behind the eye: the seventh bit
    }
    if (d.below(3) == 0) {
        const double half = s == ClipSpace::cube ? 1 : std::abs(w);
        auto inside = [&] { return d.grid(-std::round(half * 10) + 1, std::round(half * 10) - 1, 1) / 10; };
        return {inside(), inside(), inside(), w};
    }
    return {coordinate(d, l, w), coordinate(d, l, w), coordinate(d, l, w), w};
}

// "the answer and three others, each one bit away", in an order the dice choose
std::vector<std::string> outcode_choices(Dice& d, algo::Outcode answer, ClipSpace s) {
    std::vector<std::string> choices{algo::to_string(answer)};
    for (int tries = 0; choices.size() < 4 && tries < 50; ++tries) {
        const ClipPlane flip = algo::all_planes[std::size_t(d.below(algo::plane_count(s)))];
        const std::string other = algo::to_string(algo::Outcode{std::uint8_t(answer.bits ^ algo::Outcode::mask(flip))});
        if (std::find(choices.begin(), choices.end(), other) == choices.end()) choices.push_back(other);
    }
    for (std::size_t i = choices.size(); i > 1; --i) std::swap(choices[i - 1], choices[std::size_t(d.below(int(i)))]);
    return choices;
}

Wording bit_order(ClipSpace s) { return Wording(s == ClipSpace::cube ? say::bits_cube : say::bits_clip_space); }

// Choices that read the same in every language (outcodes), the right one first among them.
std::vector<Wording> as_is(const std::vector<std::string>& texts) {
    std::vector<Wording> words;
    for (const std::string& t : texts) words.push_back(Wording::as_is(t));
    return words;
}

std::optional<Exercise> outcode_exercise(Dice& d, Level l) {
    const ClipSpace s = space_for(l);
    const Vec4 p1 = draw_point(d, l, s), p2 = draw_point(d, l, s);
    if (near_a_plane(p1, s) || near_a_plane(p2, s)) return std::nullopt;
    const algo::Endpoint asked = d.coin() ? algo::Endpoint::p1 : algo::Endpoint::p2;
    algo::Scene scene = exercise_scene(s, {p1, p2}, "an outcode");
    const std::vector<ClipEvent> events = play(scene, algo::ClipAlgorithm::cohen_sutherland);
    for (std::size_t step = 0; step < events.size(); ++step) {
        const ClipEvent* e = &events[step];
        const auto* o = std::get_if<algo::OutcodeComputed>(e);
        if (!o || o->round != 1 || o->endpoint != asked) continue;
        const std::string name = asked == algo::Endpoint::p1 ? "p1" : "p2";
        Exercise x;
        x.ask(Wording(say::outcode, {{"name", name}, {"point", point_text(o->p, s)}},
                      {{"setting", {setting(s)}}, {"bits", {bit_order(s)}}}));
        const std::vector<std::string> codes = outcode_choices(d, o->code, s);
        x.offer(as_is(codes), std::size_t(std::find(codes.begin(), codes.end(), algo::to_string(o->code)) - codes.begin()));
        x.deciding = algo::describe(*e, s);
        x.deciding_step = step;
        x.given = {{"kind", "outcode"}, {"space", s == ClipSpace::cube ? "cube" : "homogeneous"}, {"point", numbers(o->p)}};
        x.scene = std::move(scene);
        x.algorithm = "cohen_sutherland";
        return x;
    }
    return std::nullopt;
}


std::optional<Exercise> trivial_test_exercise(Dice& d, Level l) {
    const ClipSpace s = space_for(l);
    Vec4 p1 = draw_point(d, l, s), p2 = draw_point(d, l, s);
    if (d.below(3) == 0) {  // both beyond one plane, so that rejections come up as often as the other answers
        const int axis = d.below(3);
        const double side = d.coin() ? 1 : -1;
        p1[axis] = side * (std::abs(p1[axis]) + std::abs(p1.w) * 1.2);
        p2[axis] = side * (std::abs(p2[axis]) + std::abs(p2.w) * 1.2);
    }
    if (near_a_plane(p1, s) || near_a_plane(p2, s)) return std::nullopt;
    algo::Scene scene = exercise_scene(s, {p1, p2}, "the trivial tests");
    const std::vector<ClipEvent> events = play(scene, algo::ClipAlgorithm::cohen_sutherland);
    for (std::size_t step = 0; step < events.size(); ++step) {
        const ClipEvent* e = &events[step];
        const auto* c = std::get_if<algo::CodesCompared>(e);
        if (!c) continue;
        Exercise x;
        x.ask(Wording(say::trivial, {{"p1", point_text(p1, s)}, {"p2", point_text(p2, s)}}, {{"setting", {setting(s)}}}));
        x.offer({Wording(say::accepted), Wording(say::rejected), Wording(say::neither)},
                (c->c1 | c->c2).inside() ? 0 : !(c->c1 & c->c2).inside() ? 1 : 2);
        x.deciding = algo::describe(*e, s);
        x.deciding_step = step;
        x.given = {{"kind", "trivial_test"}, {"space", s == ClipSpace::cube ? "cube" : "homogeneous"},
                   {"p1", numbers(p1)}, {"p2", numbers(p2)}};
        x.scene = std::move(scene);
        x.algorithm = "cohen_sutherland";
        return x;
    }
    return std::nullopt;
}

std::optional<Exercise> parameter_exercise(Dice& d, Level l) {
    const ClipSpace s = space_for(l);
    const Vec4 p1 = draw_point(d, l, s), p2 = draw_point(d, l, s);
    if (near_a_plane(p1, s) || near_a_plane(p2, s)) return std::nullopt;
    algo::Scene scene = exercise_scene(s, {p1, p2}, "where the visible part starts and ends");
    const std::vector<ClipEvent> events = play(scene, algo::ClipAlgorithm::liang_barsky);
    std::size_t steps[2] = {0, 0}, tested_at[2] = {0, 0};
    std::optional<std::size_t> last_boundary;  // the plane's test (its q/p) comes just before its update
    std::optional<algo::ParameterUpdated> last[2];
    std::string sentence[2];
    bool clipped = false;
    for (std::size_t step = 0; step < events.size(); ++step) {
        // an update that changes nothing does not decide the answer: a second plane through the same corner moves t by
        // an ulp or so (0.8333333333333333 → 0.8333333333333334), and holding there showed the answer already
        if (const auto* u = std::get_if<algo::ParameterUpdated>(&events[step]);
            u && std::abs(u->after - u->before) > 1e-9 * std::max(1.0, std::abs(u->after))) {
            const std::size_t k = u->which == algo::Parameter::t_enter ? 0 : 1;
            last[k] = *u;
            steps[k] = step;
            tested_at[k] = last_boundary.value_or(step);
            sentence[k] = algo::describe(events[step], s);
        }
        if (const auto* f = std::get_if<algo::SegmentFinished>(&events[step])) clipped = f->outcome == algo::ClipOutcome::clipped;
        if (std::holds_alternative<algo::BoundaryTested>(events[step])) last_boundary = step;
    }
    if (!clipped) return std::nullopt;  // no visible part to ask about, or all of it
    std::size_t k = d.coin() ? 0 : 1;
    if (!last[k]) k = 1 - k;
    const double t_enter = last[0] ? last[0]->after : 0.0, t_leave = last[1] ? last[1]->after : 1.0;
    if (!last[k] || t_leave - t_enter < 0.02) return std::nullopt;  // a visible part too short to read
    Exercise x;
    x.ask(Wording(k == 0 ? say::t_enter : say::t_leave, {{"p1", point_text(p1, s)}, {"p2", point_text(p2, s)}},
                  {{"setting", {setting(s)}}}));
    x.answer = decimal_text(last[k]->after, 4);
    x.tolerance = 0.005;
    x.deciding = sentence[k];
    x.deciding_step = steps[k];
    x.hold_at = tested_at[k];
    x.given = {{"kind", k == 0 ? "t_enter" : "t_leave"}, {"space", s == ClipSpace::cube ? "cube" : "homogeneous"},
               {"p1", numbers(p1)}, {"p2", numbers(p2)}};
    x.scene = std::move(scene);
    x.algorithm = "liang_barsky";
    return x;
}

// A triangle (easy, medium) or a quadrilateral (hard), its corners in order around their centre: never crossing
// itself, never three in a line.
std::optional<std::vector<Vec4>> draw_polygon(Dice& d, Level l, ClipSpace s) {
    const int corners = l == Level::hard ? 4 : 3;
    std::vector<Vec4> v;
    for (int i = 0; i < corners; ++i) {
        Vec4 p = draw_point(d, l, s, 1.0);  // one w for the polygon: its corners on one side of the eye
        if (l == Level::easy) p.z = 0;
        v.push_back(p);
    }
    Vec4 centre{0, 0, 0, 0};
    for (const Vec4& p : v) centre += p / double(corners);
    std::sort(v.begin(), v.end(), [&](const Vec4& a, const Vec4& b) {
        return std::atan2(a.y - centre.y, a.x - centre.x) < std::atan2(b.y - centre.y, b.x - centre.x);
    });
    for (int i = 0; i < corners; ++i) {
        const Vec4 &a = v[std::size_t(i)], &b = v[std::size_t((i + 1) % corners)], &c = v[std::size_t((i + 2) % corners)];
        const glm::dvec3 ab(b - a), ac(c - a);
        if (glm::length(glm::cross(ab, ac)) < 0.05) return std::nullopt;
        if (near_a_plane(a, s)) return std::nullopt;
    }
    return v;
}

std::string polygon_text(const std::vector<Vec4>& v, ClipSpace s) {
    std::string t;
    for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + point_text(v[i], s);
    return t;
}

nlohmann::json polygon_numbers(const std::vector<Vec4>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (const Vec4& p : v) a.push_back(numbers(p));
    return a;
}

std::string stage_order(ClipSpace s) {
    return s == ClipSpace::cube ? "z max, z min, y max, y min, x max, x min"
                                : "z max, z min, y max, y min, x max, x min, w min";
}


// Replays the stages from the events to know each stage's input (the machine gives indices, the student points).
std::optional<Exercise> edge_case_exercise(Dice& d, Level l) {
    const ClipSpace s = space_for(l);
    const auto polygon = draw_polygon(d, l, s);
    if (!polygon) return std::nullopt;
    algo::Scene scene = exercise_scene(s, *polygon, "an edge's case");
    const std::vector<ClipEvent> events = play(scene, algo::ClipAlgorithm::sutherland_hodgman);
    std::vector<Vec4> input = *polygon, output;
    struct Candidate {
        algo::EdgeClassified edge;
        Vec4 from, to;
        std::size_t step;
        std::string sentence;
    };
    std::vector<Candidate> cut_edges;  // edges of stages that cut something: in→in everywhere teaches nothing
    std::vector<Candidate> stage;
    for (std::size_t step = 0; step < events.size(); ++step) {
        const ClipEvent* e = &events[step];
        if (std::get_if<algo::StageStarted>(e)) {
            output.clear();
            stage.clear();
        } else if (const auto* c = std::get_if<algo::EdgeClassified>(e)) {
            const Vec4 from = input[c->from], to = input[(c->from + 1) % input.size()];
            // an end on this stage's plane (an intersection made by an earlier stage can be) would turn on a rounding
            if (std::abs(c->bc_from) >= reading_margin && std::abs(c->bc_to) >= reading_margin)
                stage.push_back({*c, from, to, step, algo::describe(*e, s)});
            if (c->edge_case == algo::EdgeCase::in_out || c->edge_case == algo::EdgeCase::out_in) output.push_back(c->intersection);
            if (c->edge_case == algo::EdgeCase::in_in || c->edge_case == algo::EdgeCase::out_in) output.push_back(to);
        } else if (std::get_if<algo::StageFinished>(e)) {
            const bool cuts = std::any_of(stage.begin(), stage.end(), [](const Candidate& edge) { return edge.edge.edge_case != algo::EdgeCase::in_in; });
            if (cuts) cut_edges.insert(cut_edges.end(), stage.begin(), stage.end());
            input = output;
        }
    }
    if (cut_edges.empty()) return std::nullopt;
    const Candidate& c = cut_edges[std::size_t(d.below(int(cut_edges.size())))];
    Exercise x;
    x.ask(Wording(say::edge,
                  {{"plane", std::string(algo::plane_name(c.edge.plane))},
                   {"inequality", std::string(algo::plane_inequality(c.edge.plane, s))},
                   {"s", point_text(c.from, s)},
                   {"e", point_text(c.to, s)}},
                  {{"setting", {setting(s)}}}));
    // in the order of algo::EdgeCase
    x.offer({Wording(say::in_in), Wording(say::in_out), Wording(say::out_out), Wording(say::out_in)}, std::size_t(c.edge.edge_case));
    x.deciding = c.sentence;
    x.deciding_step = c.step;
    x.given = {{"kind", "edge_case"}, {"space", s == ClipSpace::cube ? "cube" : "homogeneous"},
               {"plane", std::string(algo::plane_name(c.edge.plane))}, {"s", numbers(c.from)}, {"e", numbers(c.to)}};
    x.scene = std::move(scene);
    x.algorithm = "sutherland_hodgman";
    return x;
}

std::optional<Exercise> stage_count_exercise(Dice& d, Level l) {
    const ClipSpace s = space_for(l);
    const auto polygon = draw_polygon(d, l, s);
    if (!polygon) return std::nullopt;
    algo::Scene scene = exercise_scene(s, *polygon, "a stage's vertex count");
    const std::vector<ClipEvent> events = play(scene, algo::ClipAlgorithm::sutherland_hodgman);
    struct Candidate {
        algo::StageFinished stage;
        std::size_t step;
        std::string sentence;
        std::size_t started;  // the stage's first event: its edges count the answer out one by one
    };
    std::size_t started = 0;
    std::vector<Candidate> changed;  // stages whose count differs from their input's
    std::uint32_t input = 0;
    // A vertex on a plane (an earlier stage's intersection can land on it: the edge crosses z = −1 where y = 1)
    // is in or out by a rounding: the counts from that stage on are no question to ask.
    bool clear = true;
    for (std::size_t step = 0; step < events.size() && clear; ++step) {
        const ClipEvent* e = &events[step];
        if (const auto* stage = std::get_if<algo::StageStarted>(e)) input = stage->input_vertices, started = step;
        if (const auto* c = std::get_if<algo::EdgeClassified>(e))
            clear = std::abs(c->bc_from) >= reading_margin && std::abs(c->bc_to) >= reading_margin;
        if (const auto* f = std::get_if<algo::StageFinished>(e); f && f->output_vertices != input)
            changed.push_back({*f, step, algo::describe(*e, s), started});
    }
    if (changed.empty()) return std::nullopt;
    const Candidate& c = changed[std::size_t(d.below(int(changed.size())))];
    Exercise x;
    x.ask(Wording(say::stage_count,
                  {{"polygon", polygon_text(*polygon, s)}, {"order", stage_order(s)}, {"plane", std::string(algo::plane_name(c.stage.plane))}},
                  {{"setting", {setting(s)}}}));
    x.answer = std::to_string(c.stage.output_vertices);
    x.tolerance = 0;
    x.deciding = c.sentence;
    x.deciding_step = c.step;
    x.hold_at = c.started;
    x.given = {{"kind", "stage_count"}, {"space", s == ClipSpace::cube ? "cube" : "homogeneous"},
               {"plane", std::string(algo::plane_name(c.stage.plane))}, {"polygon", polygon_numbers(*polygon)}};
    x.scene = std::move(scene);
    x.algorithm = "sutherland_hodgman";
    return x;
}

// One of a topic's kinds of question, by the dice.
MakeExercise either(std::optional<Exercise> (*a)(Dice&, Level), std::optional<Exercise> (*b)(Dice&, Level)) {
    return [a, b](Draw draw) {
        Dice d(draw.seed);
        return d.coin() ? a(d, draw.level) : b(d, draw.level);
    };
}

}  // namespace

std::vector<Topic> clipping_topics() {
    return {
        {"cohen_sutherland", "Cohen–Sutherland: outcodes and the trivial tests", {"cohen_sutherland"}, either(outcode_exercise, trivial_test_exercise), {say::all}},
        {"liang_barsky", "Liang–Barsky: where the visible part starts and ends", {"liang_barsky"},
         [](Draw draw) {
             Dice d(draw.seed);
             return parameter_exercise(d, draw.level);
         },
         {say::all}},
        {"sutherland_hodgman", "Sutherland–Hodgman: edge cases and vertex counts", {"sutherland_hodgman"}, either(edge_case_exercise, stage_count_exercise), {say::all}},
    };
}

}  // namespace hsr::viz::practice
