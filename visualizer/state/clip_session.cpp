#include "state/clip_session.h"

#include "state/clip_pseudocode.h"

namespace hsr::viz {
namespace {

ClipPlayer make_player(const Lesson& lesson, PlayerOptions options) {
    const auto algorithm = algo::ClipAlgorithm(lesson.algorithm.variant);
    algo::ClipJob job = algo::clip_job(lesson.scene);
    ClipView initial = initial_view(job, algorithm);
    return ClipPlayer(algo::clip_scene(std::move(job), algorithm), std::move(initial), options);
}

}  // namespace

ClipSession::ClipSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, make_player(lesson, options)), algorithm_(algo::ClipAlgorithm(lesson.algorithm.variant)) {}

std::span<const std::string_view> ClipSession::pseudocode() const { return viz::pseudocode(algorithm_); }
std::string ClipSession::describe_event(const algo::ClipEvent& e) const { return algo::describe(e, space()); }
int ClipSession::line_of(const algo::ClipEvent& e) const { return pseudocode_line(algorithm_, e); }
bool ClipSession::is_major(const algo::ClipEvent& e) const { return viz::is_major(e); }

}  // namespace hsr::viz
