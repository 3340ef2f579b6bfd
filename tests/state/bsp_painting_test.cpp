// SPDX-License-Identifier: MIT
// The image beside the BSP traversal: what DisplayBSP has painted so far, seen from the eye. In a 2D plan it is
// the first-person strip; a near wall covers a far one only once it is painted, after it.
#include "bsp/bsp_scene.h"
#include "catch.h"
#include "state/bsp_painting.h"
#include "state/bsp_view.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

// A narrow near wall (id 1) in front of a wide far wall (id 2), the eye at the origin looking along +y.
Scene two_walls() {
    Scene s;
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 1, 0}, s.camera.up = {0, 0, 1};
    s.camera.fov_y = 60, s.camera.near = 0.1, s.camera.far = 100;
    s.segments.push_back({1, {230, 0, 0}, {-0.5, 2, 0, 1}, {0.5, 2, 0, 1}});
    s.segments.push_back({2, {0, 200, 0}, {-20, 6, 0, 1}, {20, 6, 0, 1}});
    return s;
}

// The view after the events up to (and including) the k-th polygon drawn; k = 0: the tree built, nothing drawn.
BspView view_after_drawn(const Scene& scene, int k) {
    const BspJob job = bsp_job(scene, SplitterRule::first);
    BspView view = initial_view(job);
    for (const auto& e : bsp_scene(job)) {
        if (const auto* d = std::get_if<PolygonDrawn>(&e); d && int(d->order) > k) break;
        reduce(view, e);
    }
    return view;
}

}  // namespace

TEST_CASE("the first-person strip paints the far wall first and the near wall over it", "[state][bsp][painting]") {
    const Scene scene = two_walls();
    const Viewport size{200, 40};
    const int middle = size.width / 2, horizon = size.height / 2, edge = 5;

    const Image none = bsp_painted_so_far(view_after_drawn(scene, 0), scene, size);
    for (int x = 0; x < size.width; ++x) CHECK(none.id(x, horizon) == 0);

    const Image far_only = bsp_painted_so_far(view_after_drawn(scene, 1), scene, size);
    CHECK(far_only.id(middle, horizon) == 2);  // the far wall, drawn first, fills the field of view
    CHECK(far_only.id(edge, horizon) == 2);

    const Image both = bsp_painted_so_far(view_after_drawn(scene, 2), scene, size);
    CHECK(both.id(middle, horizon) == 1);  // the near wall, narrower, covers the middle
    CHECK(both.id(edge, horizon) == 2);    // and only the middle: its ends are at ±14° of a 60° field
    // nearer is taller: the near wall covers more rows of its column than the far wall of its own
    int near_rows = 0, far_rows = 0;
    for (int y = 0; y < size.height; ++y) near_rows += both.id(middle, y) == 1, far_rows += both.id(edge, y) == 2;
    CHECK(near_rows > far_rows);
    CHECK(far_rows > 0);
}

TEST_CASE("a wall behind the eye is clipped away, not painted through the eye", "[state][bsp][painting]") {
    Scene scene = two_walls();
    scene.segments.push_back({3, {0, 0, 230}, {-5, -1, 0, 1}, {5, -1, 0, 1}});  // behind the eye
    const Image image = bsp_painted_so_far(view_after_drawn(scene, 3), scene, {120, 30});
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) CHECK(image.id(x, y) != 3);
}

TEST_CASE("the strip's camera looks along the plan camera's heading, up along +z", "[state][bsp][painting]") {
    Camera plan;
    plan.eye = {1, 1, 0}, plan.target = {1, 5, 0}, plan.fov_y = 60;
    const Camera c = strip_camera(plan, 4);
    CHECK(c.up == Vec3(0, 0, 1));
    CHECK(c.target.x == Approx(1));
    CHECK(c.target.y == Approx(2));
    // the field of view spans the width: tan(fov_y / 2) × aspect = tan(30°)
    CHECK(std::tan(c.fov_y * 3.14159265358979 / 360) * 4 == Approx(std::tan(3.14159265358979 / 6)));
}
