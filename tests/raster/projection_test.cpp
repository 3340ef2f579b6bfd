// SPDX-License-Identifier: MIT
// Projection of whole batches on every core: the same answers, in the same order, as polygon after polygon, and
// the first bad polygon named as a loop in order would name it.
#include "catch.h"

#include <limits>
#include <random>

#include "raster/screen_polygon.h"
#include "scene/generated_scenes.h"

using namespace hsr::algo;

namespace {

bool same(const ScreenPolygon& a, const ScreenPolygon& b) {
    return a.id == b.id && a.color == b.color && a.status == b.status && a.vertices == b.vertices && a.plane == b.plane &&
           a.row_begin == b.row_begin && a.row_end == b.row_end;
}

std::vector<ClipSpacePolygon> random_clip_polygons(int count) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> xy(-1.5, 1.5), z(-1.2, 1.2), w(-0.3, 2);
    std::vector<ClipSpacePolygon> out;
    for (int k = 0; k < count; ++k) {
        ClipSpacePolygon p{SceneId(k + 1), {std::uint8_t(k), 1, 2}, {}};
        for (int i = 0; i < 3; ++i) {
            const double ww = w(rng);
            p.vertices.emplace_back(xy(rng) * ww, xy(rng) * ww, z(rng) * ww, ww);
        }
        out.push_back(p);
    }
    return out;
}

}  // namespace

TEST_CASE("project_polygons on every core answers as project_polygon, polygon by polygon, in order", "[projection]") {
    const Viewport vp{640, 480};
    const auto clip = random_clip_polygons(20000);  // enough for every core to take a chunk
    const auto batch = project_polygons(clip, vp);
    REQUIRE(batch.size() == clip.size());
    std::size_t drawn = 0, outside = 0;
    for (std::size_t k = 0; k < clip.size(); ++k) {
        INFO("polygon " << k);
        REQUIRE(same(batch[k], project_polygon(clip[k].id, clip[k].color, clip[k].vertices, vp)));
        drawn += batch[k].status == ScreenStatus::drawn, outside += batch[k].status == ScreenStatus::outside_view;
    }
    CHECK(drawn > 5000);
    CHECK(outside > 500);  // clipped away whole, as some of these must be
}

TEST_CASE("project_polygons names the first polygon refused, whichever core met it", "[projection]") {
    auto clip = random_clip_polygons(20000);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    clip[19000].vertices[1].x = nan;  // in the last chunk
    clip[4321].vertices[0].w = nan;   // the first in order, in an earlier chunk
    REQUIRE_THROWS_WITH(project_polygons(clip, {64, 48}), Catch::Contains("polygon 4322"));
}

TEST_CASE("a scene's projection on every core keeps the scene's order", "[projection]") {
    const auto city = generated_scene("city:20000");
    REQUIRE(city);
    const Viewport vp{320, 200};
    const auto batch = project_polygons(*city, vp);
    REQUIRE(batch.size() == city->polygons.size());
    for (std::size_t k = 0; k < batch.size(); k += 7) {
        std::vector<glm::dvec4> clip;
        for (const auto& v : city->polygons[k].vertices) clip.push_back(to_clip(*city, v));
        INFO("polygon " << k);
        REQUIRE(same(batch[k], project_polygon(city->polygons[k].id, city->polygons[k].color, clip, vp)));
    }
}
