// SPDX-License-Identifier: MIT
#include "scene/load_terrain.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/numeric.h"
#include "core/portable_random.h"

namespace hsr::algo {

namespace {

// What is wrong with a terrain's sizes and angle, or empty.
std::string terrain_problem(int columns, int rows, double elevation) {
    if (columns < 2) return "a terrain needs at least 2 columns (a curve is drawn between samples)";
    if (rows < 1) return "a terrain needs at least 1 row";
    if (std::size_t(rows) > max_terrain_rows)
        return "a terrain has at most " + std::to_string(max_terrain_rows) + " rows (the floating horizon draws each on up to 256 screen columns, "
               "and stops at 20000000 points), not " + std::to_string(rows);
    if (std::size_t(columns) * std::size_t(rows) > max_terrain_samples)
        return "a terrain has at most " + std::to_string(max_terrain_samples) + " samples";
    if (!(elevation >= 0 && elevation <= 90)) return "the elevation is an angle from 0 (level) to 90 degrees (straight down)";
    return {};
}

}  // namespace

void check_terrain(const Terrain& t) {
    if (const std::string p = terrain_problem(t.columns, t.rows, t.elevation); !p.empty()) throw InvalidInput("terrain: " + p);
    if (t.heights.size() != std::size_t(t.columns) * std::size_t(t.rows)) throw InvalidInput("terrain: the heights are not rows × columns");
    if (!(t.dx > 0 && t.dz > 0 && std::isfinite(t.dx) && std::isfinite(t.dz))) throw InvalidInput("terrain: the spacing must be positive");
    for (double h : t.heights)
        if (!(std::abs(h) <= max_terrain_height)) throw InvalidInput("terrain: a height is NaN, infinite or beyond ±1e300");
}

Terrain read_terrain(const TomlReader& r, const toml::table* t) {
    Terrain out;
    if (!t) return out;
    r.only_keys(*t, "terrain", {"spacing", "elevation", "heights", "generate", "columns", "rows", "seed"});
    out.line = int(t->source().begin.line);
    out.elevation = r.number(*t, "elevation", "terrain", 30.0);
    if (const toml::node* s = t->get("spacing")) {
        const glm::dvec4 v = r.vector(*s, "terrain.spacing", 2, 2);
        if (!(v.x > 0 && v.y > 0 && v.x <= 1e6 && v.y <= 1e6)) r.fail(s, "terrain.spacing", "expected two spacings from 0 to 1e6 (dx, dz), above 0");
        out.dx = v.x, out.dz = v.y;
    }
    if (t->get("generate")) {
        const std::string kind = r.text(*t, "generate", "terrain");
        if (kind != "hills") r.fail(t->get("generate"), "terrain.generate", "expected \"hills\"");
        const auto columns = r.integer(*t, "columns", "terrain", 40), rows = r.integer(*t, "rows", "terrain", 24);
        const auto seed = r.integer(*t, "seed", "terrain", 1);
        const auto most = std::int64_t(max_terrain_samples);
        if (columns < 2 || rows < 1 || columns > most || rows > most || columns * rows > most)
            r.fail(t, "terrain", terrain_problem(int(std::min<std::int64_t>(columns, 1 << 30)), int(std::min<std::int64_t>(rows, 1 << 30)), out.elevation));
        if (seed < 0 || seed > 0xffffffffLL) r.fail(t->get("seed"), "terrain.seed", "expected a seed from 0 to 4294967295");
        const double dx = out.dx, dz = out.dz;
        out = hills_terrain(int(columns), int(rows), std::uint32_t(seed), out.elevation);
        out.dx = dx, out.dz = dz, out.line = int(t->source().begin.line);
    } else {
        const toml::array* rows = r.array(*t, "heights", "terrain", true);
        for (std::size_t j = 0; j < rows->size(); ++j) {
            const std::string field = index("terrain.heights", j);
            const toml::array* row = rows->get(j)->as_array();
            if (!row) r.fail(rows->get(j), field, "expected a row of heights, [h0, h1, …]");
            if (j == 0) out.columns = int(std::min<std::size_t>(row->size(), max_terrain_samples));
            if (int(row->size()) != out.columns)
                r.fail(row, field, "has " + std::to_string(row->size()) + " heights where row 0 has " + std::to_string(out.columns));
            for (std::size_t i = 0; i < row->size(); ++i) {
                const auto h = row->get(i)->value<double>();
                if (!h || !(std::abs(*h) <= max_terrain_height))
                    r.fail(row->get(i), index(field, i), "expected a finite height within ±1e300");
                out.heights.push_back(*h);
                if (out.heights.size() > max_terrain_samples)
                    r.fail(row, field, "a terrain has at most " + std::to_string(max_terrain_samples) + " samples");
            }
        }
        out.rows = int(rows->size());
    }
    if (const std::string p = terrain_problem(out.columns, out.rows, out.elevation); !p.empty()) r.fail(t, "terrain", p);
    return out;
}

Terrain hills_terrain(int columns, int rows, std::uint32_t seed, double elevation) {
    Terrain t{.columns = columns, .rows = rows, .elevation = elevation};
    PortableRandom random(seed);
    // A few round hills of random place, height and width, a ridge across the middle, and a little noise
    struct Hill { double x, z, height, width; };
    std::vector<Hill> hills;
    const int count = 3 + random.integer(0, 3);
    for (int k = 0; k < count; ++k) {
        const double x = random.uniform(0, columns - 1);
        const double z = random.uniform(0, rows - 1);
        const double height = random.uniform(2, 6);
        const double width = random.uniform(2, 0.35 * std::max(columns, rows) + 2);
        hills.push_back({x, z, height, width});
    }
    const double ridge_phase = random.uniform(0, 2 * std::numbers::pi);
    t.heights.reserve(std::size_t(columns) * std::size_t(rows));
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            double h = 1.5 * std::sin(0.45 * i + ridge_phase) * std::exp(-std::pow((j - 0.5 * rows) / (0.2 * rows + 1), 2));
            for (const Hill& hill : hills) {
                const double d2 = (i - hill.x) * (i - hill.x) + (j - hill.z) * (j - hill.z);
                h += hill.height * std::exp(-d2 / (hill.width * hill.width));
            }
            const double noise = random.uniform(-0.15, 0.15);
            t.heights.push_back(std::round((h + noise) * 256) / 256);  // dyadic: exact in any arithmetic
        }
    return t;
}

}  // namespace hsr::algo
