#include "registry.h"

#include <array>

#include "clipping/clip_scene.h"
#include "culling/backface.h"
#include "raycast/raycast_events.h"

namespace hsr::algo {
namespace {

constexpr std::array registry = {
    AlgorithmInfo{"cohen_sutherland", "3D Cohen–Sutherland line clipping", 1, Family::clipping,
                  int(ClipAlgorithm::cohen_sutherland)},
    AlgorithmInfo{"liang_barsky", "3D Liang–Barsky line clipping", 2, Family::clipping,
                  int(ClipAlgorithm::liang_barsky)},
    AlgorithmInfo{"sutherland_hodgman", "3D Sutherland–Hodgman polygon clipping", 2, Family::clipping,
                  int(ClipAlgorithm::sutherland_hodgman)},
    AlgorithmInfo{"bsp_build", "BSP tree: BuildBSP", 3, Family::bsp, 0},
    AlgorithmInfo{"bsp_traversal", "BSP tree: DisplayBSP, back to front", 3, Family::bsp, 1},
    AlgorithmInfo{"backface_view_vector", "Back-face culling: the view vector", 1, Family::backface,
                  int(BackfaceTest::view_vector)},
    AlgorithmInfo{"backface_plane_equation", "Back-face culling: the plane equation", 1, Family::backface,
                  int(BackfaceTest::plane_equation)},
    AlgorithmInfo{"backface_screen_winding", "Back-face culling: the winding on screen", 2, Family::backface,
                  int(BackfaceTest::screen_winding)},
    AlgorithmInfo{"zbuffer_fill", "Z-buffer fill", 2, Family::zbuffer, 0},
    AlgorithmInfo{"depth_sort", "Depth sort (Newell, Newell and Sancha)", 4, Family::depth_sort, 0},
    AlgorithmInfo{"portal_pvs", "Cells and portals: stab trees and the PVS matrix", 4, Family::portals, 0},
    AlgorithmInfo{"portal_render", "Cells and portals: portal_render with narrowing frusta", 4, Family::portals, 1},
    AlgorithmInfo{"cull_bounds", "Bounding volumes and a BVH, built node by node", 2, Family::culling, 0},
    AlgorithmInfo{"cull_frustum", "Hierarchical view-frustum culling with clip flags", 2, Family::culling, 1},
    AlgorithmInfo{"cull_detail", "Detail culling by projected size", 2, Family::culling, 2},
    AlgorithmInfo{"cull_occluders", "From-point occlusion culling with planar occluders", 3, Family::culling, 3},
    AlgorithmInfo{"cull_hiz", "Hierarchical visibility with a hierarchical z-buffer", 4, Family::culling, 4},
    AlgorithmInfo{"portal_render_bbox", "Cells and portals: portal_render with bounding-box frusta", 4, Family::portals, 2},
    AlgorithmInfo{"z_merge", "Z-merge of two frame and depth buffers", 2, Family::zmerge, 0},
    AlgorithmInfo{"scan_line", "Scan-line algorithm with a one-line z-buffer", 3, Family::scanline, 0},
    AlgorithmInfo{"raycast_brute", "Ray casting: every primitive", 1, Family::raycast, int(Acceleration::none)},
    AlgorithmInfo{"raycast_grid", "Ray casting through a regular grid", 3, Family::raycast, int(Acceleration::grid)},
    AlgorithmInfo{"raycast_octree", "Ray casting through an octree", 3, Family::raycast, int(Acceleration::octree)},
};

}  // namespace

std::span<const AlgorithmInfo> algorithms() { return registry; }

std::optional<AlgorithmInfo> find_algorithm(std::string_view id) {
    for (const auto& a : registry)
        if (a.id == id) return a;
    return std::nullopt;
}

}  // namespace hsr::algo
