// SPDX-License-Identifier: MIT
#include "state/presets.h"

#include <algorithm>
#include <filesystem>

#include "core/portable_random.h"
#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "scene/random_scene.h"
#include "scene/save_scene.h"
#include "state/families.h"
#include "core/okabe_ito.h"

namespace hsr::viz {
namespace {

// Okabe–Ito, as the shipped scenes colour their primitives
algo::Color colour(int k) {
    return algo::okabe_ito::as<algo::Color>(algo::okabe_ito::series[std::size_t(k) % algo::okabe_ito::series.size()]);
}

const FamilyFacts& facts_of(const algo::AlgorithmInfo& algorithm) {
    return *with_family(algorithm, [](auto family) { return &decltype(family)::Session::facts; });
}

}  // namespace

bool expects_from_renderer(const algo::Scene& s, std::string_view r) {
    const algo::Expect& e = s.expect;
    return std::any_of(e.image.begin(), e.image.end(), [&](const algo::ExpectImage& x) { return x.algorithm == r; }) ||
           std::any_of(e.rejects.begin(), e.rejects.end(), [&](const algo::ExpectRejects& x) { return x.algorithm == r; });
}

std::optional<algo::Scene> random_triangle_scene(std::uint32_t seed, bool) {
    return algo::random_triangles({.count = 12, .seed = seed, .size = 3});
}

algo::Scene random_segment_scene_2d(std::uint32_t seed) {
    algo::PortableRandom rng(seed);
    algo::Scene s;
    s.name = "Random segments (seed " + std::to_string(seed) + ")";
    s.camera.eye = {0.5, -0.5, 0};
    for (int k = 0; k < 7; ++k) {
        const double x = rng.uniform(-5, 5), y = rng.uniform(-5, 5), l = rng.uniform(1, 4), a = rng.uniform(0, 6.283185307179586);
        s.segments.push_back({k + 1, colour(k), {x, y, 0, 1}, {x + l * std::cos(a), y + l * std::sin(a), 0, 1}});
    }
    return s;
}

std::optional<algo::Scene> random_clipping_scene(std::uint32_t seed, bool) {
    algo::Scene s = algo::random_triangles({.count = 6, .seed = seed, .size = 4});
    algo::PortableRandom rng(seed + 1000);
    const auto u = [&] { return rng.uniform(-8, 8); };
    const auto z = [&] { return rng.uniform(-12, 12); };
    for (int k = 0; k < 6; ++k) {
        const algo::Vec4 a{u(), u(), z(), 1}, b{u(), u(), z(), 1};  // (braced lists: evaluated left to right)
        s.segments.push_back({int(s.polygons.size()) + k + 1, colour(k), a, b});
    }
    return s;
}

std::optional<algo::Scene> no_random_scene(std::uint32_t, bool) { return std::nullopt; }

std::vector<Preset> extreme_presets(const algo::AlgorithmInfo& algorithm, const std::string& dir) {
    std::vector<Preset> out;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return out;
    const FamilyFacts& facts = facts_of(algorithm);
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
        if (e.path().extension() != ".toml") continue;
        try {
            const algo::Scene s = algo::load_scene(e.path().string());
            if (facts.speaks_to(s, algorithm)) out.push_back({s.name, e.path().string(), s.promise});
        } catch (const std::exception&) {  // a broken case is the catalogue test's to report, not the menu's
        }
    }
    std::sort(out.begin(), out.end(), [](const Preset& a, const Preset& b) { return a.name < b.name; });
    return out;
}

bool has_random_scene(const algo::AlgorithmInfo& algorithm) { return facts_of(algorithm).random_scene != &no_random_scene; }

std::optional<std::string> random_scene_toml(const algo::AlgorithmInfo& algorithm, bool two_d, std::uint32_t seed) {
    std::optional<algo::Scene> s = facts_of(algorithm).random_scene(seed, two_d);
    if (!s) return std::nullopt;
    if (s->name.find("seed") == std::string::npos) s->name += " (seed " + std::to_string(seed) + ")";
    return algo::scene_toml(*s);
}

std::vector<analysis::Measurement> family_report(const algo::AlgorithmInfo& algorithm, const std::string& scenes_dir,
                                                 analysis::Progress* progress) {
    return facts_of(algorithm).measure({.quick = true, .repeats = 3, .scenes_dir = scenes_dir, .progress = progress});
}

}  // namespace hsr::viz
