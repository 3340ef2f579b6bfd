// SPDX-License-Identifier: MIT
// Walking through a culling lesson's scene: the eye moves with the keyboard (a step forward or back, a turn) and
// the mouse (a drag looks around), each culling stage is switched on and off, and every change runs the pipeline
// again from the new eye, on the scene prepared once (the hierarchy, the solid occluders, a floor plan's PVS do not
// change when only the eye moves). The counts, the time per stage and the frame time follow the walk. The Hi-Z
// stage may draw first what the previous frame saw (frame-to-frame coherence, named in the Greek notes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "culling/pipeline.h"

namespace hsr::viz {

class Walkthrough {
public:
    // The walk starts at the scene's camera with `stages` on; it renders at `viewport`.
    Walkthrough(const algo::Scene& scene, std::vector<algo::Stage> stages, algo::Viewport viewport, algo::PipelineOptions options = {});

    // One key press: `forward` steps along the heading (−1 back), `turn_left` turns by a few degrees (−1 right).
    // The eye keeps its height: one walks through a city, one does not fly.
    void walk(int forward, int turn_left);
    // A mouse drag of (right, down) points: the heading turns and the gaze tilts (never straight up or down).
    void look(double right, double down);
    void toggle(algo::Stage stage);
    [[nodiscard]] bool on(algo::Stage stage) const;
    // The stages this scene can run (portals only for a floor plan; hse always runs and is not switched).
    [[nodiscard]] std::vector<algo::Stage> switchable() const;
    void set_coherent(bool coherent);
    [[nodiscard]] bool coherent() const { return coherent_; }

    // The frame at the eye now: run again after a move or a switch, else the last one.
    const algo::PipelineResult& frame();
    [[nodiscard]] const algo::PipelineResult& last() const { return last_; }  // the frame made last
    [[nodiscard]] const algo::Camera& camera() const { return camera_; }
    [[nodiscard]] const algo::Scene& scene() const { return prepared_.scene; }
    [[nodiscard]] double frame_ms() const { return frame_ms_; }          // the last frame's pipeline, in all
    [[nodiscard]] double prepared_ms() const { return prepared_.milliseconds; }  // once, before the first frame
    [[nodiscard]] std::uint64_t frames() const { return frames_; }
    [[nodiscard]] std::uint32_t drawn_first() const { return drawn_first_; }  // coherence: what Hi-Z drew first
    // Why the last frame could not be made (empty: it was): a stage refused the eye where it stands.
    [[nodiscard]] const std::string& error() const { return error_; }
    // One line for a log: the eye, the stages on, what each left out, the frame time.
    [[nodiscard]] std::string summary() const;

private:
    algo::PreparedScene prepared_;
    algo::PipelineOptions options_;
    algo::Camera camera_;
    double yaw_ = 0, pitch_ = 0, step_ = 1;  // heading about +y (0: along −z), tilt; a step's length
    bool coherent_ = false, dirty_ = true;
    algo::PipelineResult last_;
    std::vector<std::uint8_t> seen_;  // what the last frame saw (coherence)
    double frame_ms_ = 0;
    std::uint64_t frames_ = 0;
    std::uint32_t drawn_first_ = 0;
    std::string error_;
    void aim();
};

}  // namespace hsr::viz
