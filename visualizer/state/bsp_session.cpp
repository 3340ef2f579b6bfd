#include "state/bsp_session.h"

#include <array>
#include <chrono>

#include "core/overloaded.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's BuildBSP ("BSP Algorithm (2)"); Left is the front of P_i, Right its back.
constexpr std::array<std::string_view, 10> build_lines = {
    "BuildBSP(BSPnode, polygonDB);",
    "{",
    "  Select a polygon (plane) Pi from polygonDB;",
    "  Assign Pi to BSPnode;",
    "  /* Partition scene polygons into those on either side",
    "     of plane Pi, splitting polygons that intersect Pi */",
    "  Partition(Pi, polygonDB, polygonDBL, polygonDBR);",
    "  if (polygonDBL != empty) BuildBSP(BSPnode->Left, polygonDBL);",
    "  if (polygonDBR != empty) BuildBSP(BSPnode->Right, polygonDBR);",
    "}",
};

// The lecture's DisplayBSP ("BSP Algorithm (4)"); 'left' is the front of the node's plane.
constexpr std::array<std::string_view, 14> display_lines = {
    "DisplayBSP (BSPnode, v);",
    "{",
    "  if IsLeaf (BSPnode) Render (BSPnode->Polygon)",
    "  else if (v in 'left' subspace of BSPnode->Polygon) {",
    "    DisplayBSP (BSPnode->Right, v);",
    "    Render (BSPnode->Polygon);",
    "    DisplayBSP (BSPnode->Left, v);",
    "  }",
    "  else /* v in 'right' subspace of BSPnode->Polygon */ {",
    "    DisplayBSP (BSPnode->Left, v);",
    "    Render (BSPnode->Polygon);",
    "    DisplayBSP (BSPnode->Right, v);",
    "  }",
    "}",
};

SplitterRule rule_named(const std::string& s) {
    return s == "balanced" ? SplitterRule::balanced : s == "fewest-splits" ? SplitterRule::fewest_splits
                         : s == "weighted"    ? SplitterRule::weighted
                                              : SplitterRule::first;
}

BspSession::PlayerType make_player(const Lesson& lesson, PlayerOptions options) {
    BspJob job = bsp_job(lesson.scene, rule_named(lesson.splitter));
    BspView initial = initial_view(job);
    return BspSession::PlayerType(bsp_scene(std::move(job)), std::move(initial), options);
}

}  // namespace

BspSession::BspSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, make_player(lesson, options)),
      kind_(BspLesson(lesson.algorithm.variant)),
      job_(bsp_job(lesson.scene, rule_named(lesson.splitter))),
      options_(options) {
    BspJob job = job_;
    stats_.polygons_in = job.polygons.size();
    stats_.rule = job.options.splitter;
    const auto start = std::chrono::steady_clock::now();
    const BspTree tree = build_bsp(std::move(job.polygons), job.options).run_to_end();
    stats_.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats_.polygons_after = tree.polygons.size();
    stats_.nodes = tree.nodes.size();
    stats_.depth = tree.depth;
    stats_.splits = tree.splits;
    if (kind_ == BspLesson::traversal)  // the traversal lesson starts with the tree built
        player().step_forward_until([](const BspEvent& e) { return std::holds_alternative<BuildFinished>(e); });
}

void BspSession::move_eye(Vec3 eye) {
    if (view().two_d) eye.z = 0;
    job_.eye = eye;
    rerun();
}

void BspSession::rerun() { replace_player(PlayerType(bsp_scene(job_), initial_view(job_), options_)); }

void BspSession::move_vertex(std::size_t input, std::size_t vertex, Vec3 to) {
    if (input >= job_.polygons.size() || vertex >= job_.polygons[input].vertices.size()) return;
    if (view().two_d) to.z = 0;
    algo::BspJob edited = job_;
    edited.polygons[input].vertices[vertex] = to;
    if (algo::measure(edited.polygons[input].vertices) <= 1e-9) return;  // a segment of no length is not an edit
    // a drag is many small moves: one undo step for consecutive moves of the same vertex
    const bool same_drag = !undo_.empty() && last_moved_ == std::pair{input, vertex};
    if (!same_drag) undo_.push_back(job_);
    last_moved_ = {input, vertex};
    redo_.clear();
    job_ = std::move(edited);
    rerun();
}

bool BspSession::undo() {
    if (undo_.empty()) return false;
    redo_.push_back(std::move(job_));
    job_ = std::move(undo_.back());
    undo_.pop_back();
    last_moved_.reset();
    rerun();
    return true;
}

bool BspSession::redo() {
    if (redo_.empty()) return false;
    undo_.push_back(std::move(job_));
    job_ = std::move(redo_.back());
    redo_.pop_back();
    last_moved_.reset();
    rerun();
    return true;
}

algo::Scene BspSession::edited_scene() const {
    algo::Scene s = lesson().scene;
    s.camera.eye = job_.eye;
    for (const algo::BspInput& in : job_.polygons) {
        for (auto& seg : s.segments)
            if (seg.id == in.id && in.vertices.size() == 2) seg.a = glm::dvec4(in.vertices[0], 1.0), seg.b = glm::dvec4(in.vertices[1], 1.0);
        for (auto& poly : s.polygons)
            if (poly.id == in.id && in.vertices.size() == poly.vertices.size())
                for (std::size_t k = 0; k < in.vertices.size(); ++k) poly.vertices[k] = glm::dvec4(in.vertices[k], 1.0);
    }
    return s;
}

std::span<const std::string_view> BspSession::pseudocode() const {
    if (kind_ == BspLesson::build && !view().built) return build_lines;
    return display_lines;
}

std::string BspSession::describe_event(const BspEvent& e) const { return describe(e, namer(view())); }

int BspSession::line_of(const BspEvent& event) const {
    return std::visit(overloaded{
                          [](const BuildStarted&) { return 0; },
                          [](const CandidateScored&) { return 2; },
                          [](const SplitterChosen& e) { return e.parent < 0 ? 3 : e.side == Side::front ? 7 : 8; },
                          [](const PolygonClassified&) { return 6; },
                          [](const PolygonSplit&) { return 5; },
                          [](const NodeFinished&) { return 6; },
                          [](const BuildFinished&) { return 9; },
                          [](const EyeClassified& e) { return e.side == Side::back ? 8 : 3; },
                          [](const PolygonDrawn& e) { return e.leaf ? 2 : e.eye_side == Side::back ? 10 : 5; },
                          [](const TraversalFinished&) { return 13; },
                          [](const BspBoundReached&) { return 0; },
                      },
                      event);
}

bool BspSession::is_major(const BspEvent& event) const {
    return std::visit(overloaded{
                          [](const BuildStarted&) { return true; },
                          [](const CandidateScored&) { return false; },
                          [](const SplitterChosen&) { return true; },
                          [](const PolygonClassified&) { return false; },
                          [](const PolygonSplit&) { return true; },
                          [](const NodeFinished&) { return true; },
                          [](const BuildFinished&) { return true; },
                          [](const EyeClassified&) { return false; },
                          [](const PolygonDrawn&) { return true; },
                          [](const TraversalFinished&) { return true; },
                          [](const BspBoundReached&) { return true; },
                      },
                      event);
}

}  // namespace hsr::viz
