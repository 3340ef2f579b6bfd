// SPDX-License-Identifier: MIT
// The 27 outcode regions the clipping view labels (V): each label's code is the code mkcode gives a point there,
// for a perspective and an orthographic camera, and the 27 codes are the 27 different ones.
#include <set>

#include "catch.h"
#include "state/clip_regions.h"

using namespace hsr::algo;
using hsr::viz::outcode_region_lines;
using hsr::viz::outcode_regions;

TEST_CASE("Each of the 27 regions is labelled with the outcode of the point it is drawn at", "[clipping][regions][state]") {
    Camera perspective;
    perspective.eye = {1, 2, 6};
    perspective.target = {0, 0, 0};
    perspective.near = 0.5;
    perspective.far = 9;
    Camera orthographic = perspective;
    orthographic.projection = Projection::orthographic;
    orthographic.box[0] = -2, orthographic.box[1] = 3;
    for (const Camera& camera : {perspective, orthographic}) {
        const auto regions = outcode_regions(camera);
        REQUIRE(regions.size() == 27);
        std::set<int> codes;
        const glm::dmat4 vp = view_projection(camera);
        for (const auto& r : regions) {
            const glm::dvec4 clip = vp * glm::dvec4(r.at, 1.0);
            const Outcode machine = outcode(clip, ClipSpace::homogeneous);
            INFO("label " << to_string(r.code) << ", mkcode " << to_string(machine));
            CHECK(machine == r.code);  // in front of the eye: no w bit
            codes.insert(r.code.bits);
        }
        CHECK(codes.size() == 27);
        // 4 lines across the near plane, 4 across the far one, and the 4 side edges
        CHECK(outcode_region_lines(camera).size() == 12);
    }
}
