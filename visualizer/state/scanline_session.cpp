// SPDX-License-Identifier: MIT
#include "state/scanline_session.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lectures' scan-line algorithm, hybrid with a one-scan-line z-buffer.
const Pseudocode<ScanLineEvent> scan_lines = {
    {"ET = every non-horizontal edge, by the first scan line it crosses", {step<EdgeTableBuilt>()}},
    {"for each scan line y:", {step<ScanLineStarted>()}},
    {"  AET += the ET's edges starting at y", {micro<EdgeEntered>()}},
    {"  AET -= the edges that ended", {micro<EdgeLeft>()}},
    {"  sort the AET by the x where each edge crosses y", {}},
    {"  clear the line's z-buffer", {}},
    {"  for each edge E of the AET, left to right:", {}},
    {"    flip the in/out flag of E's polygon P", {micro<EdgeCrossed>([](const EdgeCrossed& e) { return e.entering; })}},
    {"    if P is now out:  z-test P's span into the line", {micro<EdgeCrossed>()}},
    {"  output the line's colours as spans", {micro<SpanColored>()}},
    {"done", {step<ScanFinished>(), step<ScanStepBoundReached>()}},
};

}  // namespace

ScanLineSession::RunType ScanLineSession::machine(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    auto polygons = std::make_shared<const std::vector<ScreenPolygon>>(project_polygons(scene, lesson.grid));
    ScanView initial = initial_view(polygons, lesson.grid);
    return {scan_line(*polygons, scan_line_options(scene, lesson.grid, lesson.depth_format)), std::move(initial)};
}

ScanLineSession::ScanLineSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string ScanLineSession::sentence_of(const ScanLineEvent& e, const ScanView&) { return describe(e); }
std::string ScanLineSession::describe_event(const ScanLineEvent& e) const { return sentence_of(e, view()); }
std::string ScanLineSession::speak_event(const ScanLineEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<ScanLineEvent>& ScanLineSession::table() const { return scan_lines; }

const FamilyFacts ScanLineSession::facts = {
    .topic = "Scan line",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return expects_from_renderer(s, "scanline"); },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_zbuffer,
};

}  // namespace hsr::viz
