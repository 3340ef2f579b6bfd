// SPDX-License-Identifier: MIT
// The floating horizon against an exact ray walk (GMP) over the terrain's section under each column, on terrains
// built to break it: level views where curves tie, straight-down views, spikes narrower than a column, heights near
// the double limits next to tiny ones, rows that lie exactly on one line of sight, and one row.
#include <cmath>
#include <filesystem>
#include <limits>

#include "analysis/exact_horizon.h"
#include "catch.h"
#include "core/numeric.h"
#include "horizon/floating_horizon.h"
#include "scene/load_scene.h"
#include "scene/load_terrain.h"

using namespace hsr::algo;
using hsr::analysis::exact_horizon;

namespace {

Terrain terrain_of(int columns, int rows, double elevation, auto height) {
    Terrain t{.columns = columns, .rows = rows, .elevation = elevation};
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) t.heights.push_back(height(i, j));
    return t;
}

struct Agreement {
    std::uint64_t points = 0, visible = 0, differing = 0, near_ties = 0;
};

// Every point of the machine's image against the exact walk; a disagreement within `tie` screen units of the other
// answer is a near-tie (double rounding of y = h·cos + z·sin), any other fails.
Agreement compare(const Terrain& t, int columns, double tie = 0) {
    const HorizonImage image = floating_horizon(t, {.columns = columns}).run_to_end();
    const auto exact = exact_horizon(t, columns);
    Agreement a;
    for (int row = 0; row < t.rows; ++row)
        for (int c = 0; c < columns; ++c) {
            const bool shown = image.at(row, c) != Sight::hidden;
            const std::size_t k = std::size_t(row) * std::size_t(columns) + std::size_t(c);
            ++a.points, a.visible += shown;
            if (shown == exact.at(row, c)) continue;
            if (exact.margin[k] <= tie) ++a.near_ties;
            else {
                ++a.differing;
                UNSCOPED_INFO("row " << row << ", column " << c << ": machine " << (shown ? "visible" : "hidden") << ", margin "
                                     << exact.margin[k]);
            }
        }
    return a;
}

}  // namespace

TEST_CASE("The floating horizon agrees with the exact ray walk on random hills at every elevation", "[horizon]") {
    for (const std::uint32_t seed : {1u, 2u, 3u, 4u})
        for (const double elevation : {0.0, 10.0, 30.0, 55.0, 80.0, 90.0})
            for (const int columns : {7, 40, 97}) {
                CAPTURE(seed, elevation, columns);
                const Terrain t = hills_terrain(24, 16, seed, elevation);
                const Agreement a = compare(t, columns, 1e-12);
                CHECK(a.differing == 0);
                CHECK(a.near_ties <= a.points / 1000);
                CHECK(a.visible > std::uint64_t(columns));  // more than the nearest curve: the test is not vacuous
                if (elevation <= 30) CHECK(a.visible < a.points);  // steeper views see all of these gentle hills
                if (elevation == 90) CHECK(a.visible == a.points);
            }
}

TEST_CASE("Level and straight-down views of a flat terrain: ties count as hidden, in the machine and the walk", "[horizon]") {
    const auto flat = [](int, int) { return 0.0; };
    SECTION("level (0°): every curve lies on the first, so only the first shows") {
        const Agreement a = compare(terrain_of(5, 6, 0, flat), 16);
        CHECK(a.differing == 0);
        CHECK(a.near_ties == 0);
        CHECK(a.visible == 16);
    }
    SECTION("straight down (90°): each curve lies above the last on screen, so every point shows") {
        const Agreement a = compare(terrain_of(5, 6, 90, flat), 16);
        CHECK(a.differing == 0);
        CHECK(a.visible == a.points);
    }
    SECTION("seen from below a level horizon, a lower curve shows below") {
        const Terrain t = terrain_of(3, 3, 0, [](int, int j) { return j == 2 ? -1.0 : 0.0; });
        const HorizonImage image = floating_horizon(t, {.columns = 4}).run_to_end();
        for (int c = 0; c < 4; ++c) CHECK((image.at(1, c) == Sight::hidden && image.at(2, c) == Sight::below));
        CHECK(compare(t, 4).differing == 0);
    }
}

TEST_CASE("A spike narrower than a column is seen only where a column's centre falls on it", "[horizon]") {
    // A wall of height 10 in row 1 only at sample 3 of 9, then a high ridge behind it everywhere
    const Terrain t = terrain_of(9, 3, 20, [](int i, int j) { return j == 1 && i == 3 ? 10.0 : j == 2 ? 2.0 : 0.0; });
    for (const int columns : {3, 8, 16, 64, 501}) {
        CAPTURE(columns);
        CHECK(compare(t, columns, 1e-12).differing == 0);
    }
    // With 64 columns of 8/64 = 0.125 world units, the spike (from x = 2 to 4) covers 16 columns' centres
    const HorizonImage image = floating_horizon(t, {.columns = 64}).run_to_end();
    int ridge_hidden = 0;
    for (int c = 0; c < 64; ++c) ridge_hidden += image.at(2, c) == Sight::hidden;
    CHECK(ridge_hidden > 0);
    CHECK(ridge_hidden < 16);
}

TEST_CASE("Heights near the double limits next to tiny ones stay finite and exact", "[horizon]") {
    const Terrain t = terrain_of(4, 4, 30, [](int i, int j) {
        if ((i + j) % 3 == 0) return 1e300;
        if ((i + j) % 3 == 1) return -1e300;
        return 1e-300;
    });
    const HorizonImage image = floating_horizon(t, {.columns = 12}).run_to_end();
    for (const double y : image.y) CHECK(std::isfinite(y));
    const Agreement a = compare(t, 12, 1e-12 * 1e300);
    CHECK(a.differing == 0);
}

TEST_CASE("Rows laid on one line of sight are near-ties: the machine and the walk split them alike", "[horizon]") {
    // At 45° a row dz behind and dz lower lies on the same line of sight: y = h·cos + z·sin is constant
    const Terrain exact_tie = terrain_of(3, 5, 45, [](int, int j) { return -double(j); });
    const Agreement a = compare(exact_tie, 8, 1e-12);
    CHECK(a.differing == 0);
    // And a stack nudged by 1e-9 above that line: each row shows above the last, by a margin the walk agrees with
    const Terrain nudged = terrain_of(3, 5, 45, [](int, int j) { return -double(j) + 1e-9 * j; });
    CHECK(compare(nudged, 8, 1e-14).differing == 0);
    // The tie is a tie in doubles too: cos and sin of 45° are one number
    const HorizonImage tied = floating_horizon(exact_tie, {.columns = 8}).run_to_end();
    for (int row = 1; row < 5; ++row) CHECK(tied.at(row, 3) == Sight::hidden);
}

TEST_CASE("Every extreme terrain keeps its promise: the machine agrees with the exact walk", "[horizon][extreme]") {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/assets/scenes/extreme")) {
        if (!entry.path().filename().string().starts_with("horizon_")) continue;
        const Scene s = load_scene(entry.path().string());
        INFO(entry.path().filename().string());
        REQUIRE(s.terrain.rows > 0);
        ++scenes;
        double largest = s.terrain.rows * s.terrain.dz;  // what a screen y is made of: heights and depths
        for (const double h : s.terrain.heights) largest = std::max(largest, std::abs(h));
        for (const int columns : {3, 20, 64}) {
            const Agreement a = compare(s.terrain, columns, 1e-12 * largest);
            CHECK(a.differing == 0);
            CHECK(a.near_ties <= a.points / 10 + 1);
            if (largest < 1e6) CHECK(a.near_ties == 0);  // at heights of a few units doubles decide every point
        }
        const HorizonImage image = floating_horizon(s.terrain, {.columns = 20}).run_to_end();
        for (const double y : image.y) CHECK(std::isfinite(y));
        const std::string name = entry.path().filename().string();
        std::uint64_t shown = 0;
        for (const Sight sight : image.sight) shown += sight != Sight::hidden;
        if (name == "horizon_straight_down.toml" || name == "horizon_limits_1e300.toml") CHECK(shown >= 20);
        if (name == "horizon_straight_down.toml") CHECK(shown == image.sight.size());
        if (name == "horizon_line_of_sight.toml") CHECK(shown == 20);  // the first row only
        if (name == "horizon_level_ties.toml")  // rows 1 and 3 repeat row 0: hidden; row 2 above, row 4 below
            for (int c = 0; c < 20; ++c)
                CHECK((image.at(1, c) == Sight::hidden && image.at(2, c) == Sight::above && image.at(4, c) == Sight::below));
        if (name == "horizon_subcolumn_spike.toml") {  // 16 columns: centres on the spike's feet; 3: the middle one on it
            const HorizonImage sixteen = floating_horizon(s.terrain, {.columns = 16}).run_to_end();
            const HorizonImage three = floating_horizon(s.terrain, {.columns = 3}).run_to_end();
            for (int c = 0; c < 16; ++c)  // row 1 is level ground at every centre, and the ridge shows behind it
                CHECK((sixteen.y[std::size_t(16 + c)] == sixteen.y[16] && sixteen.at(2, c) == Sight::above));
            CHECK((three.at(1, 1) == Sight::above && three.at(2, 1) == Sight::hidden));
        }
    }
    CHECK(scenes == 5);
}

TEST_CASE("One row is all seen, and the events fold to the image", "[horizon]") {
    const Terrain one = terrain_of(2, 1, 30, [](int i, int) { return double(i); });
    auto machine = floating_horizon(one, {.columns = 5});
    int points = 0, curves = 0;
    for (const HorizonEvent& e : machine) {
        if (const auto* p = std::get_if<PointTested>(&e)) {
            ++points;
            CHECK(p->first);
            CHECK(p->sight == Sight::above);
        }
        curves += std::holds_alternative<CurveDrawn>(e);
    }
    CHECK(points == 5);
    CHECK(curves == 1);
}

TEST_CASE("Each point's event carries the horizons before it and its verdict follows from them", "[horizon]") {
    const Terrain t = hills_terrain(16, 12, 9, 35);
    auto machine = floating_horizon(t, {.columns = 30});
    std::vector<double> upper(30, -INFINITY), lower(30, INFINITY);
    std::uint64_t shown = 0;
    for (const HorizonEvent& e : machine) {
        const auto* p = std::get_if<PointTested>(&e);
        if (!p) continue;
        const auto c = std::size_t(p->column);
        if (!p->first) CHECK((p->upper == upper[c] && p->lower == lower[c]));
        const Sight expected = p->y > upper[c] ? Sight::above : p->y < lower[c] ? Sight::below : Sight::hidden;
        CHECK(p->sight == expected);
        upper[c] = std::max(upper[c], p->y), lower[c] = std::min(lower[c], p->y);
        shown += p->sight != Sight::hidden;
    }
    const HorizonImage image = machine.result();
    CHECK(image.upper == upper);
    CHECK(image.lower == lower);
    std::uint64_t image_shown = 0;
    for (const Sight s : image.sight) image_shown += s != Sight::hidden;
    CHECK(image_shown == shown);
}

TEST_CASE("A bad terrain is refused with what is wrong, in code and in a scene file", "[horizon][bad_input]") {
    Terrain t = terrain_of(3, 2, 30, [](int, int) { return 0.0; });
    t.heights[4] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(floating_horizon(t, {}).run_to_end(), Catch::Contains("NaN"));
    CHECK_THROWS_WITH(floating_horizon(terrain_of(3, 2, 30, [](int, int) { return 0.0; }), {.columns = 0}).run_to_end(),
                      Catch::Contains("columns"));
    CHECK_THROWS_WITH(floating_horizon(terrain_of(3, 2, 95, [](int, int) { return 0.0; }), {}).run_to_end(), Catch::Contains("elevation"));
    CHECK_THROWS_WITH(floating_horizon(terrain_of(1, 2, 30, [](int, int) { return 0.0; }), {}).run_to_end(), Catch::Contains("2 columns"));
    const auto load = [](const char* text) { return load_scene_text("t.toml", text); };
    CHECK_THROWS_WITH(load("[terrain]\nheights = [[0, 1, 2], [0, 1]]\n"), Catch::Contains("terrain.heights[1]") && Catch::Contains("row 0 has 3"));
    CHECK_THROWS_WITH(load("[terrain]\nheights = [[0, 1, 2], [0, 1, \"x\"]]\n"), Catch::Contains("terrain.heights[1][2]"));
    CHECK_THROWS_WITH(load("[terrain]\nheights = [[0, 1e301]]\n"), Catch::Contains("±1e300"));
    CHECK_THROWS_WITH(load("[terrain]\ngenerate = \"mountains\"\n"), Catch::Contains("terrain.generate"));
    CHECK_THROWS_WITH(load("[terrain]\ngenerate = \"hills\"\ncolumns = 100000\nrows = 100000\n"), Catch::Contains("at most"));
    CHECK_THROWS_WITH(load("[terrain]\nheights = [[0, 1]]\nelevation = -5\n"), Catch::Contains("elevation"));
    const Scene s = load("[terrain]\ngenerate = \"hills\"\ncolumns = 10\nrows = 7\nseed = 4\nspacing = [0.5, 2]\n");
    CHECK(s.terrain.columns == 10);
    CHECK(s.terrain.rows == 7);
    CHECK(s.terrain.dx == 0.5);
    CHECK(s.terrain.heights == hills_terrain(10, 7, 4).heights);
}
