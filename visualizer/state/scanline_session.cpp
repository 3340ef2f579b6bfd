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

// The Brown notes' classic scan-line algorithm: no z-buffer, the polygon table's planes compared where spans begin.
const Pseudocode<ScanLineEvent> classic_lines = {
    {"ET = each non-horizontal edge: x, y_max, Δx, ID", {step<EdgeTableBuilt>()}},
    {"PT = each polygon: ID, plane eq., colour, in/out", {}},
    {"for each scan line y:", {step<ScanLineStarted>()}},
    {"  AET += the ET's edges starting at y", {micro<EdgeEntered>()}},
    {"  AET -= the edges that ended", {micro<EdgeLeft>()}},
    {"  sort the AET by increasing x", {}},
    {"  for each intersection E, left to right:", {}},
    {"    left edge: P's flag = in  (entering)", {micro<EdgeCrossed>([](const EdgeCrossed& e) { return e.entering; })}},
    {"    right edge: P's flag = out  (leaving)", {micro<EdgeCrossed>()}},
    {"    two or more in: the nearest by their planes", {micro<DepthsCompared>()}},
    {"    two in pierce before the next E: an extra E", {micro<PiercingFound>()}},
    {"    use its colour (none in: background) to the next E", {micro<SpanColored>()}},
    {"done", {step<ScanFinished>(), step<ScanStepBoundReached>()}},
};

}  // namespace

ScanLineSession::RunType ScanLineSession::machine(const Lesson& lesson, bool find_piercings) {
    const Scene scene = grid_scene(lesson);
    auto polygons = std::make_shared<const std::vector<ScreenPolygon>>(project_polygons(scene, lesson.grid));
    ScanView initial = initial_view(polygons, lesson.grid);
    const ScanLineOptions options = scan_line_options(scene, lesson.grid, lesson.depth_format);
    if (machine_of<ScanLineMachine>(lesson) == ScanLineMachine::classic) {
        initial.classic = true;
        return {classic_scan_line(*polygons, {.line = options, .find_piercings = find_piercings}), std::move(initial)};
    }
    return {scan_line(*polygons, options), std::move(initial)};
}

ScanLineSession::ScanLineSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options), options_(options) {}

void ScanLineSession::set_find_piercings(bool on) {
    if (!classic() || on == find_piercings_) return;
    find_piercings_ = on;
    auto [run, initial] = machine(lesson(), on);
    replace_player(PlayerType(std::move(run), std::move(initial), options_));
}

std::string ScanLineSession::sentence_of(const ScanLineEvent& e, const ScanView&) { return describe(e); }
std::string ScanLineSession::describe_event(const ScanLineEvent& e) const { return sentence_of(e, view()); }
std::string ScanLineSession::speak_event(const ScanLineEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<ScanLineEvent>& ScanLineSession::table() const { return classic() ? classic_lines : scan_lines; }

const FamilyFacts ScanLineSession::facts = {
    .topic = "Scan line",
    .speaks_to =
        [](const algo::Scene& s, const algo::AlgorithmInfo& a) {
            return expects_from_renderer(s, std::get<ScanLineMachine>(a.machine) == ScanLineMachine::classic ? "scanline-classic" : "scanline");
        },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_zbuffer,
};

}  // namespace hsr::viz
