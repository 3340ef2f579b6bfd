// A back-face culling lesson: one of the three tests over the scene's polygons, seen from its camera.
#pragma once

#include "state/cull_view.h"
#include "state/session.h"

namespace hsr::viz {

class CullSession : public PlayerSession<algo::CullEvent, std::vector<std::int32_t>, CullView> {
public:
    explicit CullSession(Lesson lesson, PlayerOptions options = {});
    std::span<const std::string_view> pseudocode() const override;

private:
    std::string describe_event(const algo::CullEvent& e) const override;
    int line_of(const algo::CullEvent& e) const override;
    bool is_major(const algo::CullEvent& e) const override;
};

}  // namespace hsr::viz
