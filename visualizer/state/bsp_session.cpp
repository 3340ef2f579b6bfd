// SPDX-License-Identifier: MIT
#include "state/bsp_session.h"

#include <algorithm>
#include <chrono>
#include <random>
#include <cstdio>
#include <unordered_map>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "state/bsp_painting.h"
#include "state/long_work.h"
#include "state/strings.h"
#include "core/okabe_ito.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's BuildBSP ("BSP Algorithm (2)"); Left is the front of P_i, Right its back.
const Pseudocode<BspEvent> build_lines = {
    {"BuildBSP(BSPnode, polygonDB);", {step<BuildStarted>(), step<BspBoundReached>()}},
    {"{ /* L, Left: front (the normal's side); R: back */", {}},
    {"  Select a polygon (plane) Pi from polygonDB;", {micro<CandidateScored>()}},
    {"  Assign Pi to BSPnode;", {step<SplitterChosen>([](const SplitterChosen& e) { return e.parent < 0; })}},
    {"  /* Partition scene polygons into those on either side", {}},
    {"     of plane Pi, splitting polygons that intersect Pi */", {step<PolygonSplit>()}},
    {"  Partition(Pi, polygonDB, polygonDBL, polygonDBR);", {micro<PolygonClassified>(), step<NodeFinished>()}},
    {"  if (polygonDBL != empty) BuildBSP(BSPnode->Left, polygonDBL);",
     {step<SplitterChosen>([](const SplitterChosen& e) { return e.side == Side::front; })}},
    {"  if (polygonDBR != empty) BuildBSP(BSPnode->Right, polygonDBR);", {step<SplitterChosen>()}},
    {"}", {step<BuildFinished>()}},
};

// The lecture's DisplayBSP, back to front.
const Pseudocode<BspEvent> display_lines = {
    {"DisplayBSP (BSPnode, v);", {step<BspBoundReached>()}},
    {"{ /* left: front, the normal's side; right: back */", {}},
    {"  if IsLeaf (BSPnode) Render (BSPnode->Polygon)", {step<PolygonDrawn>([](const PolygonDrawn& e) { return e.leaf; })}},
    {"  else if (v in 'left' subspace of BSPnode->Polygon) {",
     {micro<EyeClassified>([](const EyeClassified& e) { return e.side != Side::back; })}},
    {"    DisplayBSP (BSPnode->Right, v);", {}},
    {"    Render (BSPnode->Polygon);", {step<PolygonDrawn>([](const PolygonDrawn& e) { return e.eye_side != Side::back; })}},
    {"    DisplayBSP (BSPnode->Left, v);", {}},
    {"  }", {}},
    {"  else /* v in 'right' subspace of BSPnode->Polygon */ {", {micro<EyeClassified>()}},
    {"    DisplayBSP (BSPnode->Left, v);", {}},
    {"    Render (BSPnode->Polygon);", {step<PolygonDrawn>()}},
    {"    DisplayBSP (BSPnode->Right, v);", {}},
    {"  }", {}},
    {"}", {step<TraversalFinished>()}},
};

// DisplayBSP front to back: the near side first, each polygon only on pixels still empty.
const Pseudocode<BspEvent> display_front_to_back_lines = {
    {"DisplayBSP (BSPnode, v);  /* front to back */", {step<BspBoundReached>()}},
    {"{ /* left: front, the normal's side; right: back */", {}},
    {"  if IsLeaf (BSPnode) Render (BSPnode->Polygon)", {step<PolygonDrawn>([](const PolygonDrawn& e) { return e.leaf; })}},
    {"  else if (v in 'left' subspace of BSPnode->Polygon) {",
     {micro<EyeClassified>([](const EyeClassified& e) { return e.side != Side::back; })}},
    {"    DisplayBSP (BSPnode->Left, v);", {}},
    {"    Render (BSPnode->Polygon);  /* where still empty */", {step<PolygonDrawn>([](const PolygonDrawn& e) { return e.eye_side != Side::back; })}},
    {"    DisplayBSP (BSPnode->Right, v);", {}},
    {"  }", {}},
    {"  else /* v in 'right' subspace of BSPnode->Polygon */ {", {micro<EyeClassified>()}},
    {"    DisplayBSP (BSPnode->Right, v);", {}},
    {"    Render (BSPnode->Polygon);  /* where still empty */", {step<PolygonDrawn>()}},
    {"    DisplayBSP (BSPnode->Left, v);", {}},
    {"  }", {}},
    {"}", {step<TraversalFinished>()}},
};

// The lesson's job: its scene with its splitter rule and display order.
BspJob job_of(const Lesson& lesson) {
    BspJob job = bsp_job(lesson.scene, lesson.splitter);
    job.order = lesson.front_to_back ? Order::front_to_back : Order::back_to_front;
    return job;
}

}  // namespace

BspSession::RunType BspSession::machine(const Lesson& lesson) {
    BspJob job = job_of(lesson);
    BspView initial = initial_view(job);
    return {bsp_scene(std::move(job)), std::move(initial)};
}

BspSession::BspSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options),
      kind_(machine_of<algo::BspMachine>(lesson)),
      job_(job_of(lesson)),
      options_(options),
      heading_(lesson.scene.camera.target - lesson.scene.camera.eye) {
    measure();
    if (kind_ == algo::BspMachine::traversal)  // the traversal lesson starts with the tree built
        player().step_forward_until([](const BspEvent& e) { return std::holds_alternative<BuildFinished>(e); });
}

void BspSession::move_eye(Vec3 eye) {
    if (view().two_d) eye.z = 0;
    job_.eye = eye;
    rerun();
}

void BspSession::drive(int forward, int left) {
    if (!view().two_d || (forward == 0 && left == 0)) return;
    heading_.z = 0;
    if (glm::length(heading_) < 1e-12) heading_ = {0, 1, 0};
    const double turn = glm::radians(5.0 * left), c = std::cos(turn), s = std::sin(turn);
    heading_ = glm::normalize(Vec3(c * heading_.x - s * heading_.y, s * heading_.x + c * heading_.y, 0));
    Vec3 eye = job_.eye.at + double(forward) * plan_size(view()) / 50 * heading_;
    eye.z = 0;
    job_.eye.at = eye;
    rerun();
}

void BspSession::measure() {
    BspJob job = job_;
    stats_.polygons_in = job.polygons.size();
    stats_.rule = job.options.splitter;
    const auto start = std::chrono::steady_clock::now();
    const BspTree tree = LongWork::run_to_end(build_bsp(std::move(job.polygons), job.options));
    stats_.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats_.polygons_after = tree.held();
    stats_.nodes = tree.nodes.size();
    stats_.depth = tree.depth;
    stats_.splits = tree.splits;
    edited_ = scene_of_job();
}

void BspSession::rerun() {
    replace_player(PlayerType(bsp_scene(job_), initial_view(job_), options_));
    measure();  // an edited scene: the panel's figures are the edited tree's
}

void BspSession::move_vertex(std::size_t input, std::size_t vertex, Vec3 to) {
    if (input >= job_.polygons.size() || vertex >= job_.polygons[input].vertices.size()) return;
    if (view().two_d) to.z = 0;
    algo::BspJob edited = job_;
    edited.polygons[input].vertices[vertex] = to;
    if (algo::measure(edited.polygons[input].vertices) <= 1e-9) return;  // a segment of no length is not an edit
    // a drag is many small moves: one undo step for consecutive moves of the same vertex
    history_.record(job_, last_moved_ == std::pair{input, vertex});
    last_moved_ = {input, vertex};
    job_ = std::move(edited);
    rerun();
}

void BspSession::edit(algo::BspJob edited) {
    history_.record(job_);
    last_moved_.reset();
    job_ = std::move(edited);
    rerun();
}

bool BspSession::add_segment(Vec3 a, Vec3 b) {
    if (!view().two_d) return false;
    a.z = b.z = 0;
    if (glm::length(b - a) <= 1e-9) return false;
    std::int32_t id = 0;
    for (const algo::BspInput& in : job_.polygons) id = std::max(id, in.id);
    algo::BspJob edited = job_;
    edited.polygons.push_back({id + 1, {a, b}});
    edit(std::move(edited));
    return true;
}

bool BspSession::delete_input(std::size_t input) {
    if (input >= job_.polygons.size() || job_.polygons.size() <= 1) return false;
    algo::BspJob edited = job_;
    edited.polygons.erase(edited.polygons.begin() + std::ptrdiff_t(input));
    edit(std::move(edited));
    return true;
}

void BspSession::set_order(algo::Order order) {
    if (job_.order == order) return;
    algo::BspJob edited = job_;
    edited.order = order;
    edit(std::move(edited));
}

void BspSession::set_splitter(algo::SplitterRule rule) {
    if (job_.options.splitter == rule) return;
    algo::BspJob edited = job_;
    edited.options.splitter = rule;
    edit(std::move(edited));
}

void BspSession::reorder_inputs(Insertion how, std::uint64_t seed) {
    algo::BspJob edited = job_;
    if (how == Insertion::reversed) {
        std::reverse(edited.polygons.begin(), edited.polygons.end());
    } else {
        std::mt19937_64 rng(seed);
        std::shuffle(edited.polygons.begin(), edited.polygons.end(), rng);
    }
    edit(std::move(edited));
}

bool BspSession::undo() {
    if (!history_.undo(job_)) return false;
    last_moved_.reset();
    rerun();
    return true;
}

bool BspSession::redo() {
    if (!history_.redo(job_)) return false;
    last_moved_.reset();
    rerun();
    return true;
}

algo::Scene BspSession::scene_of_job() const {
    algo::Scene s = lesson().scene;
    s.camera.eye = job_.eye.at;
    if (view().two_d) s.camera.target = job_.eye.at + heading_;  // the eye looks where it looked, wherever it is dragged
    // Inputs as the edits left them: moved, added (new ids, colours in turn from the palette) or deleted.
    // The scene's colour and opacity by id (the last primitive with an id wins), looked up once per input
    std::unordered_map<std::int32_t, algo::Color> color_of;
    std::unordered_map<std::int32_t, double> opacity_of;
    for (const auto& seg : s.segments) color_of.insert_or_assign(seg.id, seg.color);
    for (const auto& poly : s.polygons) color_of.insert_or_assign(poly.id, poly.color), opacity_of.insert_or_assign(poly.id, poly.opacity);
    std::vector<algo::SceneSegment> segments;
    std::vector<algo::ScenePolygon> polygons;
    for (const algo::BspInput& in : job_.polygons) {
        const auto known = color_of.find(in.id);
        const algo::Color color = known != color_of.end() ? known->second : algo::okabe_ito::as<algo::Color>(algo::okabe_ito::series[std::size_t(in.id) % algo::okabe_ito::series.size()]);
        if (in.vertices.size() == 2) {
            segments.push_back({in.id, color, glm::dvec4(in.vertices[0], 1.0), glm::dvec4(in.vertices[1], 1.0)});
            continue;
        }
        algo::ScenePolygon p{in.id, color, {}};
        for (const auto& v : in.vertices) p.vertices.emplace_back(v, 1.0);
        if (const auto o = opacity_of.find(in.id); o != opacity_of.end()) p.opacity = o->second;
        polygons.push_back(std::move(p));
    }
    if (view().two_d) s.segments = std::move(segments);
    else s.polygons = std::move(polygons);
    return s;
}

std::string BspSession::sentence_of(const BspEvent& e, const BspView& view) { return describe(e, namer(view)); }
std::string BspSession::describe_event(const BspEvent& e) const { return sentence_of(e, view()); }
std::string BspSession::speak_event(const BspEvent& e) const { return window_strings().say(phrase(e, namer(view()))); }

// BuildBSP while the tree is being built (up to its last event), DisplayBSP from the traversal's first event.
const Pseudocode<BspEvent>& BspSession::table() const {
    const auto e = player().last_applied();
    if (!e || build_lines.line_of(*e) >= 0) return build_lines;
    return view().order == Order::front_to_back ? display_front_to_back_lines : display_lines;
}

// Either table says, whichever is shown: a Step back from the traversal may land in the build.
bool BspSession::is_major(const BspEvent& e) const {
    return build_lines.is_major(e).value_or(display_lines.is_major(e).value_or(true));
}

const FamilyFacts BspSession::facts = {
    .topic = "BSP trees",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return !s.expect.bsp.empty() || expects_from_renderer(s, "bsp"); },
    .random_scene = [](std::uint32_t seed, bool two_d) -> std::optional<algo::Scene> { return two_d ? random_segment_scene_2d(seed) : random_triangle_scene(seed, false); },
    .measure = &analysis::measure_hidden_surfaces,
};

std::string tree_summary(const BspSession& s) {
    const BspSession::Stats& st = s.stats();
    const BspView& v = s.view();
    if (!v.built)
        return tr("bsp.stats_building", {{"in", std::to_string(st.polygons_in)},
                                         {"nodes", std::to_string(v.nodes.size())},
                                         {"splits", std::to_string(v.splits)}});
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.3f", st.build_ms);
    return tr("bsp.stats", {{"in", std::to_string(st.polygons_in)},
                            {"after", std::to_string(st.polygons_after)},
                            {"splits", std::to_string(st.splits)},
                            {"nodes", std::to_string(st.nodes)},
                            {"depth", std::to_string(st.depth)},
                            {"ms", ms}});
}

}  // namespace hsr::viz
