// SPDX-License-Identifier: MIT
// A lesson file (lessons/NN_topic.toml) names an algorithm and a scene:
//
//   title = "3D Cohen–Sutherland line clipping"   # or { en = "…", de = "…" }, as the narration (chapters.h)
//   algorithm = "cohen_sutherland"          # an id of algorithms/registry.cpp
//   scene = "../assets/scenes/cs_segments.toml"   # relative to the lesson file
//   difficulty = 1                           # 1 … 5
//   prerequisites = []                       # lesson file names
//   summary = "…"                            # or { en = "…", de = "…" }
//   splitter = "balanced"                  # BSP lessons only
//   format = "int16"                       # z-buffer lessons: the depth format (depth_format.h's format_id)
//   grid = [32, 24]                        # z-buffer lessons: the viewport, in fat pixels
//   cull = "back-face,frustum"             # culling lessons: the stages the scene needs
//   occluder = "solid", fusion = true      # occluder lessons: planar, proxy or solid occluders; fused or one at a time
//   leaf_limit = 4, voxel = 0.5            # octree ray-casting lessons: the octree's stopping rules
//   mask = 4                               # A-buffer lessons: 4 × 4 sub-samples per pixel (1, 2, 4 or 8)
//   display = "front-to-back"              # depth-sort lessons: draw the sorted list nearest first, on the grid,
//                                          # each pixel once, and stop when the screen is full (else back to front);
//                                          # BSP lessons: DisplayBSP visits the eye's side first
//   languages = ["en", "de"]  [[chapters]] …   # narration, pauses and questions: state/chapters.h
//
// A scene file given where a lesson is expected plays as a lesson of its own, with the algorithm the caller names
// (or the one that fits its geometry: Sutherland–Hodgman for polygons, Cohen–Sutherland otherwise).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bsp/bsp_events.h"
#include "registry.h"
#include "state/chapters.h"
#include "raster/screen_polygon.h"
#include "raycast/spatial.h"
#include "scene/scene.h"
#include "scene/toml_reader.h"
#include "zbuffer/depth_format.h"

namespace hsr::viz {

struct Lesson {
    std::string source;  // the lesson (or scene) file
    std::string title;    // in the first language (the command line, the course list)
    std::string summary;
    Texts titles, summaries;  // by language (the window shows the student's)
    algo::AlgorithmInfo algorithm;
    int difficulty = 1;
    std::vector<std::string> prerequisites;
    algo::SplitterRule splitter = algo::SplitterRule::first;  // BSP lessons
    algo::DepthFormat depth_format = algo::DepthFormat::int24;  // z-buffer lessons
    algo::Viewport grid{32, 24};                                // z-buffer lessons: pixels across and down
    std::string cull = "back-face,frustum,detail,occluders,hiz";  // culling lessons: the stages the scene needs
    std::string occluder = "planar";  // occluder lessons: planar, proxy or solid (culling/occluders.h)
    bool fusion = false;              // … and whether the occluders are fused
    algo::OctreeOptions octree;  // octree ray-casting lessons: leaf_limit = N (max_per_leaf), voxel = edge
    int mask_size = 4;           // A-buffer lessons: mask = N, the coverage mask's N × N sub-samples per pixel
    std::string volume = "aabb";  // intersection-test lessons: aabb, sphere, obb, kdop (with k) or hulls
    int k = 14;                  // … and a k-DOP's k: 6, 14, 18 or 26
    bool front_to_back = false;  // depth-sort and BSP lessons: display = "front-to-back", the notes' optimisation of the display
    std::vector<std::string> languages{"en"};                  // of the narration; the first is the default
    std::vector<Chapter> chapters;                             // state/chapters.h
    algo::Scene scene;
};

// Which of its family's machines the lesson plays (M is the family's type in algo::Machine).
template <class M>
M machine_of(const Lesson& lesson) {
    return std::get<M>(lesson.algorithm.machine);
}

// The lesson's scene with its camera's aspect set to the lesson's grid (the pixel lessons render into it).
algo::Scene grid_scene(const Lesson& lesson);

// Loads a lesson or a scene file; throws algo::LoadError naming file, line, column and field.
Lesson load_lesson(const std::string& path, std::optional<std::string> algorithm = std::nullopt);
// The same from text, as if read from `path` (for tests and the fuzzer).
Lesson load_lesson_text(const std::string& path, std::string_view text);
Lesson read_lesson(const algo::TomlReader& reader, std::optional<std::string> algorithm);

// Where lessons/ and assets/ are: $HSRVIZ_DATA when set (a teacher's own copy wins); else beside the program as
// installed (BIN/../share/hsrviz, wherever the installation was put); else the source tree the program was built from.
std::string data_dir();
std::string default_lesson_path();
// The lessons in data_dir()/lessons, in the course's order (by file name: NN_topic.toml).
std::vector<std::string> shipped_lessons();

// Of files dropped on the window (or picked) together, the one to open: the lesson among them (a .toml file with an
// `algorithm = …` line: its scene and meshes came with it), else the first .toml (a scene), else the first.
std::string file_to_open(const std::vector<std::string>& files);

}  // namespace hsr::viz
