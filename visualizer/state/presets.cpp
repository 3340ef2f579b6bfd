#include "state/presets.h"

#include <algorithm>
#include <filesystem>
#include <random>

#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "scene/random_scene.h"
#include "scene/save_scene.h"

namespace hsr::viz {
namespace {

using algo::Family;

// The renderer name [expect.image] and [expect.rejects] use for a family ("" for none).
std::string renderer_of(Family f) {
    switch (f) {
        case Family::zbuffer: return "zbuffer";
        case Family::scanline: return "scanline";
        case Family::bsp: return "bsp";
        case Family::depth_sort: return "depth-sort";
        case Family::raycast: return "raycast";
        default: return "";
    }
}

bool speaks_to(const algo::Scene& s, const algo::AlgorithmInfo& a) {
    const algo::Expect& e = s.expect;
    const Family f = a.family;
    switch (f) {
        case Family::clipping:  // Sutherland–Hodgman clips the polygons, the segment clippers the segments
            return !e.clip.empty() && !(a.id == "sutherland_hodgman" ? s.polygons.empty() : s.segments.empty());
        case Family::backface: return !e.cull.empty();
        case Family::portals: return !e.pvs.empty();
        case Family::raycast:  // the reference every image is measured against
            if (!e.image.empty()) return true;
            break;
        case Family::bsp:
            if (!e.bsp.empty()) return true;
            break;
        default: break;
    }
    const std::string r = renderer_of(f);
    if (r.empty()) return false;
    return std::any_of(e.image.begin(), e.image.end(), [&](const algo::ExpectImage& x) { return x.algorithm == r; }) ||
           std::any_of(e.rejects.begin(), e.rejects.end(), [&](const algo::ExpectRejects& x) { return x.algorithm == r; });
}

// Okabe–Ito, as the shipped scenes colour their primitives
algo::Color colour(int k) {
    static constexpr algo::Color palette[] = {{230, 159, 0}, {86, 180, 233}, {0, 158, 115}, {240, 228, 66}, {0, 114, 178}, {213, 94, 0}, {204, 121, 167}};
    return palette[std::size_t(k) % std::size(palette)];
}

// Random segments in the plane z = 0 (a 2D BSP lesson), seen from above.
algo::Scene random_segments_2d(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-5, 5), len(1, 4), angle(0, 6.283185307179586);
    algo::Scene s;
    s.name = "Random segments (seed " + std::to_string(seed) + ")";
    s.camera.eye = {0.5, -0.5, 0};
    for (int k = 0; k < 7; ++k) {
        const double x = u(rng), y = u(rng), l = len(rng), a = angle(rng);
        s.segments.push_back({k + 1, colour(k), {x, y, 0, 1}, {x + l * std::cos(a), y + l * std::sin(a), 0, 1}});
    }
    return s;
}

// Segments and triangles around and across a perspective camera's view volume, some behind the eye.
algo::Scene random_clipping(std::uint32_t seed) {
    algo::Scene s = algo::random_triangles({.count = 6, .seed = seed, .size = 4});
    std::mt19937 rng(seed + 1000);
    std::uniform_real_distribution<double> u(-8, 8), z(-12, 12);
    for (int k = 0; k < 6; ++k)
        s.segments.push_back({int(s.polygons.size()) + k + 1, colour(k), {u(rng), u(rng), z(rng), 1}, {u(rng), u(rng), z(rng), 1}});
    return s;
}

}  // namespace

std::vector<Preset> extreme_presets(const algo::AlgorithmInfo& algorithm, const std::string& dir) {
    std::vector<Preset> out;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return out;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
        if (e.path().extension() != ".toml") continue;
        try {
            const algo::Scene s = algo::load_scene(e.path().string());
            if (speaks_to(s, algorithm)) out.push_back({s.name, e.path().string(), s.promise});
        } catch (const std::exception&) {  // a broken case is the catalogue test's to report, not the menu's
        }
    }
    std::sort(out.begin(), out.end(), [](const Preset& a, const Preset& b) { return a.name < b.name; });
    return out;
}

bool has_random_scene(const algo::AlgorithmInfo& algorithm) { return algorithm.family != Family::zmerge; }

std::optional<std::string> random_scene_toml(const algo::AlgorithmInfo& algorithm, bool two_d, std::uint32_t seed) {
    algo::Scene s;
    switch (algorithm.family) {
        case Family::clipping: s = random_clipping(seed); break;
        case Family::bsp: s = two_d ? random_segments_2d(seed) : algo::random_triangles({.count = 12, .seed = seed, .size = 3}); break;
        case Family::zbuffer:
        case Family::scanline:
        case Family::raycast:
        case Family::depth_sort:
        case Family::backface: s = algo::random_triangles({.count = 12, .seed = seed, .size = 3}); break;
        case Family::portals: s = algo::cell_maze({.rows = 4, .cols = 4, .seed = seed}); break;
        case Family::culling: s = algo::city_scene({.triangles = 3000, .seed = seed}); break;
        case Family::zmerge: return std::nullopt;
    }
    if (s.name.find("seed") == std::string::npos) s.name += " (seed " + std::to_string(seed) + ")";
    return algo::scene_toml(s);
}

}  // namespace hsr::viz
