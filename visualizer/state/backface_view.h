// SPDX-License-Identifier: MIT
// What a back-face culling lesson shows: every face, its verdict once tested, and the face being tested.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "culling/backface.h"

namespace hsr::viz {

struct FaceView {
    std::int32_t id;
    std::shared_ptr<const std::vector<algo::Vec3>> vertices;  // world space, never changed
    algo::Plane plane;
    std::optional<algo::Facing> facing;  // once tested
    double value = 0;                    // v̂·n̂, N·eye + D or the screen area
};

struct BackfaceView {
    algo::BackfaceTest test = algo::BackfaceTest::view_vector;
    algo::Vec3 eye{0};
    std::vector<FaceView> faces;
    int current = -1;  // index of the face tested last
    int kept = 0, culled = 0;
};

BackfaceView initial_view(const std::vector<algo::Face>& faces, const algo::Camera& camera, algo::BackfaceTest test);
void reduce(BackfaceView& view, const algo::CullEvent& event);
std::size_t approx_bytes(const BackfaceView& view);

}  // namespace hsr::viz
