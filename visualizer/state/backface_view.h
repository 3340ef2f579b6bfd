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
    // Pixels of the camera's image the face wins in a ray cast of all faces, both sides, nothing culled (the
    // reference: analysis/face_visibility.h); none for a scene too large to cast at every load.
    std::optional<std::size_t> seen;
};

struct BackfaceView {
    algo::BackfaceTest test = algo::BackfaceTest::view_vector;
    algo::Vec3 eye{0};
    std::vector<FaceView> faces;
    int current = -1;  // index of the face tested last
    int kept = 0, culled = 0;
    // Against the ray cast, among the faces tested so far: kept but seen nowhere (a non-convex solid: culling is not
    // enough), and culled but seen (an open surface, or the eye inside: culling is wrong).
    int kept_hidden = 0, culled_seen = 0;
};

// The largest scene whose faces' visibility the view casts when it loads (about 0.1 s).
inline constexpr std::size_t max_faces_cast = 300;

BackfaceView initial_view(const std::vector<algo::Face>& faces, const algo::Camera& camera, algo::BackfaceTest test);
void reduce(BackfaceView& view, const algo::CullEvent& event);
std::size_t approx_bytes(const BackfaceView& view);

}  // namespace hsr::viz
