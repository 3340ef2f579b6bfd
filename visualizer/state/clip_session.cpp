// SPDX-License-Identifier: MIT
#include "state/clip_session.h"

#include "state/clip_pseudocode.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

}  // namespace

ClipSession::RunType ClipSession::machine(const Lesson& lesson) {
    const auto algorithm = machine_of<algo::ClipAlgorithm>(lesson);
    algo::ClipJob job = algo::clip_job(lesson.scene);
    ClipView initial = initial_view(job, algorithm);
    return {algo::clip_scene(std::move(job), algorithm), std::move(initial)};
}

ClipSession::ClipSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options), algorithm_(machine_of<algo::ClipAlgorithm>(lesson)) {}

std::string ClipSession::sentence_of(const algo::ClipEvent& e, const ClipView& view) { return algo::describe(e, view.space); }
std::string ClipSession::describe_event(const algo::ClipEvent& e) const { return sentence_of(e, view()); }
std::string ClipSession::speak_event(const algo::ClipEvent& e) const { return window_strings().say(algo::phrase(e, view().space)); }
const Pseudocode<algo::ClipEvent>& ClipSession::table() const { return pseudocode_table(algorithm_); }

const FamilyFacts ClipSession::facts = {
    .topic = "Clipping",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo& a) {  // Sutherland–Hodgman clips the polygons, the others the segments
        return !s.expect.clip.empty() && !(a.id == "sutherland_hodgman" ? s.polygons.empty() : s.segments.empty());
    },
    .random_scene = &random_clipping_scene,
    .measure = &analysis::measure_clipping,
};

}  // namespace hsr::viz
