// A z-buffer lesson: the fill over a classroom-sized grid of fat pixels, with the depth format, near and far the
// user can change (the machine reruns; the step stays).
#pragma once

#include "state/session.h"
#include "state/zbuffer_view.h"

namespace hsr::viz {

class ZBufferSession : public PlayerSession<algo::ZBufferEvent, algo::FrameDepth, ZView> {
public:
    explicit ZBufferSession(Lesson lesson, PlayerOptions options = {});
    std::span<const std::string_view> pseudocode() const override;

    algo::DepthFormat format() const { return view().format; }
    algo::DepthRange range() const { return view().range; }
    void set_format(algo::DepthFormat f);
    void set_range(algo::DepthRange r);  // near and far of the camera; ignored unless 0 < near < far
    // Pixels where the image differs from the double-precision ray cast through the same centres (z-fighting,
    // mostly), for the finished fill.
    std::size_t pixels_unlike_ray_cast() const { return unlike_ray_cast_; }

private:
    std::string describe_event(const algo::ZBufferEvent& e) const override;
    int line_of(const algo::ZBufferEvent& e) const override;
    bool is_major(const algo::ZBufferEvent& e) const override;
    void rerun();

    algo::Scene scene_;  // the lesson's, with the near and far the user chose
    algo::DepthFormat format_;
    PlayerOptions options_;
    std::size_t unlike_ray_cast_ = 0;
};

}  // namespace hsr::viz
