// SPDX-License-Identifier: MIT
#include "analysis/lost_pixels.h"

#include "core/plane.h"

namespace hsr::analysis {

std::uint64_t lost_front_pixels(const algo::Scene& s, const algo::FrameDepth& culled, const algo::FrameDepth& all) {
    std::uint64_t lost = 0;
    for (std::size_t k = 0; k < all.image.ids.size(); ++k) {
        if (culled.image.ids[k] == all.image.ids[k]) continue;
        const std::int32_t p = all.polygon[k];
        if (p < 0) continue;
        algo::Plane plane;
        std::vector<algo::Vec3> v;
        for (const auto& q : s.polygons[std::size_t(p)].vertices) v.emplace_back(q);
        algo::plane_of(v, plane);
        lost += plane.distance(s.camera.eye) > 0;  // a front face was lost: a real difference
    }
    return lost;
}

}  // namespace hsr::analysis
