// SPDX-License-Identifier: MIT
#include "state/lesson.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/numeric.h"
#include "culling/pipeline.h"
#include "scene/input_file.h"
#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "scene/toml_reader.h"
#include "state/memory_budget.h"

namespace hsr::viz {
namespace {

algo::AlgorithmInfo algorithm_named(const algo::TomlReader* r, const toml::node* at, const std::string& id,
                                    const std::string& file) {
    if (auto a = algo::find_algorithm(id)) return *a;
    std::string known;
    for (const auto& a : algo::algorithms()) known += (known.empty() ? "" : ", ") + std::string(a.id);
    const std::string message = "unknown algorithm \"" + id + "\"; expected one of: " + known;
    if (r) r->fail(at, "algorithm", message);
    throw algo::LoadError(file, 0, 0, "algorithm", message);
}

}  // namespace

Lesson load_lesson(const std::string& path, std::optional<std::string> algorithm) {
    return read_lesson(algo::TomlReader(path), std::move(algorithm));
}

Lesson load_lesson_text(const std::string& path, std::string_view text) { return read_lesson(algo::TomlReader(path, text), std::nullopt); }

Lesson read_lesson(const algo::TomlReader& r, std::optional<std::string> algorithm) {
    const std::string& path = r.path();
    const toml::table& root = r.root();
    Lesson lesson;
    lesson.source = path;

    if (!root.contains("algorithm")) {  // a scene file, played as a lesson of its own
        lesson.scene = algo::read_scene(r);
        lesson.title = lesson.scene.name;
        lesson.summary = lesson.scene.description;
        lesson.titles = {{"en", lesson.title}}, lesson.summaries = {{"en", lesson.summary}};
        const bool terrain_only = lesson.scene.terrain.rows > 0 && lesson.scene.polygons.empty() && lesson.scene.segments.empty();
        const std::string fallback = terrain_only                  ? "floating_horizon"
                                     : lesson.scene.polygons.empty() ? "cohen_sutherland"
                                                                     : "sutherland_hodgman";
        // (a scene plays with a clipping machine, or a terrain with the floating horizon, unless --algorithm names another)
        lesson.algorithm = algorithm_named(nullptr, nullptr, algorithm.value_or(fallback), path);
        lesson.difficulty = lesson.algorithm.difficulty;
        return lesson;
    }

    r.only_keys(root, "", {"title", "algorithm", "scene", "difficulty", "prerequisites", "summary", "splitter", "format", "grid", "cull", "occluder", "fusion", "display", "leaf_limit", "voxel", "mask", "volume", "k", "languages", "chapters"});
    lesson.chapters = read_chapters(r, root, lesson.languages);
    lesson.titles = read_texts(r, root.get("title"), "title", lesson.languages);
    if (lesson.titles.empty()) r.fail(&root, "title", "a lesson needs title = \"…\"");
    lesson.title = in_language(lesson.titles, lesson.languages.front(), lesson.languages);
    lesson.summaries = read_texts(r, root.get("summary"), "summary", lesson.languages);
    lesson.summary = in_language(lesson.summaries, lesson.languages.front(), lesson.languages);
    lesson.algorithm = algorithm_named(&r, root.get("algorithm"), algorithm.value_or(r.text(root, "algorithm", "")), path);
    lesson.difficulty = int(r.integer(root, "difficulty", "", 1));
    if (lesson.difficulty < 1 || lesson.difficulty > 5)
        r.fail(root.get("difficulty"), "difficulty", "expected a difficulty from 1 to 5");
    lesson.prerequisites = r.strings(root, "prerequisites", "");
    if (const auto rule = algo::parse_splitter_rule(r.text(root, "splitter", "", "first")))
        lesson.splitter = *rule;
    else
        r.fail(root.get("splitter"), "splitter", "expected " + std::string(algo::splitter_rule_names));
    lesson.cull = r.text(root, "cull", "", lesson.cull);
    const std::string display = r.text(root, "display", "", "back-to-front");
    if (display != "back-to-front" && display != "front-to-back")
        r.fail(root.get("display"), "display", "expected back-to-front or front-to-back, got \"" + algo::printable(display, 60) + "\"");
    lesson.front_to_back = display == "front-to-back";
    try {
        algo::parse_stages(lesson.cull);
    } catch (const algo::InvalidInput& e) {
        r.fail(root.get("cull"), "cull", e.what());
    }
    const std::string format = r.text(root, "format", "", "int24");
    bool known_format = false;
    for (auto f : {algo::DepthFormat::int16, algo::DepthFormat::int24, algo::DepthFormat::int32, algo::DepthFormat::float32,
                   algo::DepthFormat::float32_reversed, algo::DepthFormat::linear24})
        if (format == algo::format_id(f)) lesson.depth_format = f, known_format = true;
    if (!known_format)
        r.fail(root.get("format"), "format", "expected int16, int24, int32, float32, float32-reversed or linear24, got \"" + algo::printable(format, 60) + "\"");
    // the A-buffer's coverage mask: mask × mask sub-samples per pixel
    const std::int64_t mask = r.integer(root, "mask", "", lesson.mask_size);
    if (mask != 1 && mask != 2 && mask != 4 && mask != 8) r.fail(root.get("mask"), "mask", "expected 1, 2, 4 or 8 (sub-samples along each side of a pixel)");
    else lesson.mask_size = int(mask);
    // the intersection test's bounding volume, and a k-DOP's k
    lesson.volume = r.text(root, "volume", "", lesson.volume);
    if (lesson.volume != "aabb" && lesson.volume != "sphere" && lesson.volume != "obb" && lesson.volume != "kdop" && lesson.volume != "hulls")
        r.fail(root.get("volume"), "volume", "expected \"aabb\", \"sphere\", \"obb\", \"kdop\" or \"hulls\"");
    const std::int64_t k = r.integer(root, "k", "", lesson.k);
    if (k != 6 && k != 14 && k != 18 && k != 26) r.fail(root.get("k"), "k", "expected 6, 14, 18 or 26 (the faces of the k-DOP)");
    else lesson.k = int(k);
    // the occluders' shape, and fusion
    lesson.occluder = r.text(root, "occluder", "", lesson.occluder);
    if (lesson.occluder != "planar" && lesson.occluder != "proxy" && lesson.occluder != "solid")
        r.fail(root.get("occluder"), "occluder", "expected \"planar\", \"proxy\" or \"solid\"");
    lesson.fusion = r.boolean(root, "fusion", "", lesson.fusion);
    // the octree's stopping rules (ray casting through an octree)
    const std::int64_t leaf_limit = r.integer(root, "leaf_limit", "", std::int64_t(lesson.octree.max_per_leaf));
    if (leaf_limit < 1 || leaf_limit > 1'000'000) r.fail(root.get("leaf_limit"), "leaf_limit", "expected a whole number from 1 to 1000000");
    else lesson.octree.max_per_leaf = std::size_t(leaf_limit);
    const double voxel = r.number(root, "voxel", "", 0.0);
    if (!(voxel >= 0) || !std::isfinite(voxel)) r.fail(root.get("voxel"), "voxel", "expected a voxel edge ≥ 0 (world units; 0: 8 levels at most)");
    else lesson.octree.voxel = voxel;
    if (root.contains("grid")) {
        const glm::dvec4 g = r.vector(*root.get("grid"), "grid", 2, 2);
        if (g.x < 1 || g.y < 1 || g.x > 256 || g.y > 256 || g.x != std::floor(g.x) || g.y != std::floor(g.y))
            r.fail(root.get("grid"), "grid", "expected [width, height], whole numbers from 1 to 256");
        lesson.grid = {int(g.x), int(g.y)};
    }
    const std::string scene = r.text(root, "scene", "");
    // What the machine needs from its scene, checked before the scene is generated or its hierarchy built (an
    // intersection test without a ray was refused only after 9 to 11 s building the hierarchy): a generated scene
    // is polygons only
    const std::string_view id = lesson.algorithm.id;
    const auto needs = [&](bool generated) -> std::string {
        if (id == "intersection_test" && (generated || lesson.scene.segments.empty()))
            return "the intersection test needs a ray: give the scene a [[segments]] entry (from a through b)";
        if (id == "floating_horizon" && (generated || lesson.scene.terrain.rows == 0))
            return "the floating horizon needs a scene with a [terrain] (heights, or generate = \"hills\")";
        return {};
    };
    bool generated_name = false;
    try {
        generated_name = algo::generated_triangles(scene).has_value();
    } catch (const std::exception&) {  // a count out of range: said below
    }
    if (const std::string why = generated_name ? needs(true) : ""; !why.empty()) r.fail(root.get("scene"), "scene", algo::printable(scene, 60) + ": " + why);
    try {  // a generated scene by name: city:N, field:N, spheres:N
        if (const auto n = algo::generated_triangles(scene))  // refused before it is generated, not half-way
            require_memory(memory_estimate(*n, std::uint64_t(lesson.grid.width) * std::uint64_t(lesson.grid.height)),
                           "the lesson's scene " + scene);
        if (auto generated = algo::generated_scene(scene)) {
            lesson.scene = std::move(*generated);
            return lesson;
        }
    } catch (const std::exception& e) {  // a count out of range, or more than the memory holds
        r.fail(root.get("scene"), "scene", e.what());
    }
    const auto scene_path = (std::filesystem::path(path).parent_path() / scene).lexically_normal();
    try {
        lesson.scene = algo::load_scene(scene_path.string());
    } catch (const algo::LoadError& e) {
        // The scene file itself cannot be read (missing, a folder, a FIFO, too long a name): the lesson's line names it.
        if (e.line == 0) r.fail(root.get("scene"), "scene", algo::printable(scene_path.string()) + ": " + e.message);
        throw;  // an error inside the scene names the scene's own line
    }
    if (const std::string why = needs(false); !why.empty()) r.fail(root.get("scene"), "scene", algo::printable(scene_path.string()) + ": " + why);
    return lesson;
}

algo::Scene grid_scene(const Lesson& lesson) {
    algo::Scene s = lesson.scene;
    s.camera.aspect = double(lesson.grid.width) / double(lesson.grid.height);
    return s;
}

std::string data_dir() {
    if (const char* d = std::getenv("HSRVIZ_DATA"); d && *d) return d;
    // installed (or a copy of the installation moved anywhere): BIN/hsrviz finds BIN/../share/hsrviz
    static const std::string beside_program = [] {
        std::error_code ec;
        const auto program = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (ec) return std::string();
        const auto share = program.parent_path().parent_path() / "share" / "hsrviz";
        return std::filesystem::is_directory(share / "lessons", ec) ? share.string() : std::string();
    }();
    if (!beside_program.empty()) return beside_program;
    return HSR_SOURCE_DIR;  // a run from the build tree
}

std::string default_lesson_path() { return data_dir() + "/lessons/00_tour.toml"; }

std::vector<std::string> shipped_lessons() {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(data_dir() + "/lessons", ec))
        if (e.path().extension() == ".toml") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());  // by their numbers: the course's order
    return out;
}

std::string file_to_open(const std::vector<std::string>& files) {
    const auto toml_file = [](const std::string& f) { return std::filesystem::path(f).extension() == ".toml"; };
    const auto names_algorithm = [](const std::string& f) {  // a line "algorithm = …" (a scene file has none)
        std::ifstream in(f);
        std::string line;
        for (int lines = 0; lines < 10'000 && std::getline(in, line); ++lines) {
            const std::size_t start = line.find_first_not_of(" \t");
            if (start == std::string::npos || line.compare(start, 9, "algorithm") != 0) continue;
            const std::size_t eq = line.find_first_not_of(" \t", start + 9);
            if (eq != std::string::npos && line[eq] == '=') return true;
        }
        return false;
    };
    for (const std::string& f : files)
        if (toml_file(f) && names_algorithm(f)) return f;
    for (const std::string& f : files)
        if (toml_file(f)) return f;
    return files.empty() ? std::string() : files.front();
}

}  // namespace hsr::viz
