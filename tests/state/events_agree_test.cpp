// SPDX-License-Identifier: MIT
// The event log is the truth the window shows: folding a machine's events must give exactly its answer.
#include <random>

#include "catch.h"
#include "clipping/clip_test_helpers.h"
#include "state/clip_view.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

ClipJob random_job(std::mt19937_64& rng, ClipSpace s, int n) {
    ClipJob job{.space = s};
    PrimitiveId id = 1;
    for (int i = 0; i < n; ++i) job.points.push_back({id++, hsr::test::random_point(rng, s)});
    for (int i = 0; i < n; ++i)
        job.segments.push_back({id++, hsr::test::random_point(rng, s), hsr::test::random_point(rng, s)});
    for (int i = 0; i < n; ++i) {
        ClipPolygon p{id++, {}};
        for (int k = 0; k < 3 + i % 4; ++k) p.vertices.push_back(hsr::test::random_point(rng, s));
        job.polygons.push_back(p);
    }
    return job;
}

}  // namespace

TEST_CASE("every clipping machine's events fold to the same answer it returns", "[state][clipping]") {
    const ClipSpace space = GENERATE(ClipSpace::cube, ClipSpace::homogeneous);
    const ClipAlgorithm algorithm =
        GENERATE(ClipAlgorithm::cohen_sutherland, ClipAlgorithm::liang_barsky, ClipAlgorithm::sutherland_hodgman);
    std::mt19937_64 rng(11);
    const ClipJob job = random_job(rng, space, 300);
    ClipView view = initial_view(job, algorithm);
    auto machine = clip_scene(job, algorithm);
    for (const auto& e : machine) reduce(view, e);
    const auto& result = machine.result();
    REQUIRE(answers(view).size() == result.size());
    CHECK(answers(view) == result);
    for (const auto& p : view.primitives) CHECK(p.status == PrimitiveStatus::done);
}
