#include "state/scanline_session.h"

#include <array>

#include "core/overloaded.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lectures' scan-line algorithm, hybrid with a one-scan-line z-buffer.
constexpr std::array<std::string_view, 11> scan_lines = {
    "ET = every non-horizontal edge, by the first scan line it crosses",
    "for each scan line y:",
    "  AET += the ET's edges starting at y",
    "  AET -= the edges that ended",
    "  sort the AET by the x where each edge crosses y",
    "  clear the line's z-buffer",
    "  for each edge E of the AET, left to right:",
    "    flip the in/out flag of E's polygon P",
    "    if P is now out:  z-test P's span into the line",
    "  output the line's colours as spans",
    "done",
};

}  // namespace

ScanLineSession::RunType ScanLineSession::machine(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    auto polygons = std::make_shared<const std::vector<ScreenPolygon>>(project_polygons(scene, lesson.grid));
    ScanView initial = initial_view(polygons, lesson.grid);
    return {scan_line(*polygons, scan_line_options(scene, lesson.grid, lesson.depth_format)), std::move(initial)};
}

ScanLineSession::ScanLineSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::span<const std::string_view> ScanLineSession::pseudocode() const { return scan_lines; }

std::string ScanLineSession::sentence_of(const ScanLineEvent& e, const ScanView&) { return describe(e); }
std::string ScanLineSession::describe_event(const ScanLineEvent& e) const { return sentence_of(e, view()); }

int ScanLineSession::line_of(const ScanLineEvent& event) const {
    return std::visit(overloaded{
                          [](const EdgeTableBuilt&) { return 0; },
                          [](const ScanLineStarted&) { return 1; },
                          [](const EdgeEntered&) { return 2; },
                          [](const EdgeLeft&) { return 3; },
                          [](const EdgeCrossed& e) { return e.entering ? 7 : 8; },
                          [](const SpanColored&) { return 9; },
                          [](const ScanFinished&) { return 10; },
                          [](const ScanStepBoundReached&) { return 10; },
                      },
                      event);
}

// A Step is a scan line; its edges and spans are micro-steps.
bool ScanLineSession::is_major(const ScanLineEvent& e) const {
    return std::holds_alternative<ScanLineStarted>(e) || std::holds_alternative<EdgeTableBuilt>(e) ||
           std::holds_alternative<ScanFinished>(e) || std::holds_alternative<ScanStepBoundReached>(e);
}

const FamilyFacts ScanLineSession::facts = {
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return expects_from_renderer(s, "scanline"); },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_zbuffer,
};

}  // namespace hsr::viz
