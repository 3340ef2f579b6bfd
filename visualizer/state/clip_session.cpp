#include "state/clip_session.h"

#include "state/clip_pseudocode.h"

namespace hsr::viz {
namespace {

ClipPlayer make_player(const Lesson& lesson, algo::ClipAlgorithm algorithm, PlayerOptions options) {
    algo::ClipJob job = algo::clip_job(lesson.scene);
    ClipView initial = initial_view(job, algorithm);
    return ClipPlayer(algo::clip_scene(std::move(job), algorithm), std::move(initial), options);
}

}  // namespace

ClipSession::ClipSession(Lesson lesson, PlayerOptions options)
    : lesson_(std::move(lesson)),
      algorithm_(algo::ClipAlgorithm(lesson_.algorithm.variant)),
      player_(make_player(lesson_, algorithm_, options)) {}

bool ClipSession::is_major_event(const algo::ClipEvent& e) { return is_major(e); }

std::string ClipSession::narration() const {
    const auto e = player_.last_applied();
    return e ? algo::describe(*e, space()) : std::string();
}

int ClipSession::current_line() const {
    const auto e = player_.last_applied();
    return e ? pseudocode_line(algorithm_, *e) : -1;
}

}  // namespace hsr::viz
