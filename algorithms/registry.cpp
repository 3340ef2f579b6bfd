// SPDX-License-Identifier: MIT
#include "registry.h"

#include <array>

namespace hsr::algo {
namespace {

constexpr std::array registry = {
    AlgorithmInfo{"cohen_sutherland", "3D Cohen–Sutherland line clipping", 1, ClipAlgorithm::cohen_sutherland},
    AlgorithmInfo{"liang_barsky", "3D Liang–Barsky line clipping", 2, ClipAlgorithm::liang_barsky},
    AlgorithmInfo{"sutherland_hodgman", "3D Sutherland–Hodgman polygon clipping", 2, ClipAlgorithm::sutherland_hodgman},
    AlgorithmInfo{"bsp_build", "BSP tree: BuildBSP", 3, BspMachine::build},
    AlgorithmInfo{"bsp_traversal", "BSP tree: DisplayBSP, back to front", 3, BspMachine::traversal},
    AlgorithmInfo{"backface_view_vector", "Back-face culling: the view vector", 1, BackfaceTest::view_vector},
    AlgorithmInfo{"backface_plane_equation", "Back-face culling: the plane equation", 1, BackfaceTest::plane_equation},
    AlgorithmInfo{"backface_screen_winding", "Back-face culling: the winding on screen", 2, BackfaceTest::screen_winding},
    AlgorithmInfo{"zbuffer_fill", "Z-buffer fill", 2, ZBufferMachine::fill},
    AlgorithmInfo{"depth_sort", "Depth sort (Newell, Newell and Sancha)", 4, DepthSortMachine::newell},
    AlgorithmInfo{"portal_pvs", "Cells and portals: stab trees and the PVS matrix", 4, PortalMachine::pvs},
    AlgorithmInfo{"portal_render", "Cells and portals: portal_render with narrowing frusta", 4, PortalMachine::render},
    AlgorithmInfo{"cull_bounds", "Bounding volumes and a BVH, built node by node", 2, CullingMachine::bounds},
    AlgorithmInfo{"cull_frustum", "Hierarchical view-frustum culling with clip flags", 2, CullingMachine::frustum},
    AlgorithmInfo{"cull_detail", "Detail culling by projected size", 2, CullingMachine::detail},
    AlgorithmInfo{"cull_occluders", "From-point occlusion culling with planar occluders", 3, CullingMachine::occluders},
    AlgorithmInfo{"cull_hiz", "Hierarchical visibility with a hierarchical z-buffer", 4, CullingMachine::hiz},
    AlgorithmInfo{"portal_render_bbox", "Cells and portals: portal_render with bounding-box frusta", 4, PortalMachine::render_bbox},
    AlgorithmInfo{"z_merge", "Z-merge of two frame and depth buffers", 2, ZMergeMachine::merge},
    AlgorithmInfo{"scan_line", "Scan-line algorithm with a one-line z-buffer", 3, ScanLineMachine::scan_line},
    AlgorithmInfo{"scan_line_classic", "Classic scan-line algorithm: edge and polygon tables, depth only where spans begin", 3,
                  ScanLineMachine::classic},
    AlgorithmInfo{"raycast_brute", "Ray casting: every primitive", 1, Acceleration::none},
    AlgorithmInfo{"raycast_grid", "Ray casting through a regular grid", 3, Acceleration::grid},
    AlgorithmInfo{"raycast_octree", "Ray casting through an octree", 3, Acceleration::octree},
    AlgorithmInfo{"raycast_bvh", "Ray casting through a bounding-volume hierarchy", 3, Acceleration::bvh},
    AlgorithmInfo{"floating_horizon", "The floating horizon for terrain", 2, HorizonMachine::floating_horizon},
    AlgorithmInfo{"roberts", "Roberts' hidden lines: each edge against every convex body", 3, RobertsMachine::hidden_lines},
    AlgorithmInfo{"perspective_transform", "The perspective transform: occluding pairs before and after it", 2,
                  PerspectiveMachine::occluding_pairs},
    AlgorithmInfo{"a_buffer", "The A-buffer: fragment lists with coverage masks, resolved front to back", 3, ABufferMachine::resolve},
    AlgorithmInfo{"general_forms", "Object space and image space: the general forms of hidden-surface elimination", 1,
                  FormsMachine::general_forms},
    AlgorithmInfo{"intersection_test", "IntersectionTest(M): a ray against a hierarchy of bounding volumes (AABB, sphere, OBB, k-DOP, hulls)", 3,
                  IntersectionMachine::hierarchical},
    AlgorithmInfo{"alpha_compositing", "Alpha compositing: premultiplied and straight, over, Porter–Duff", 2, CompositeMachine::alpha},
};

}  // namespace

std::span<const AlgorithmInfo> algorithms() { return registry; }

std::optional<AlgorithmInfo> find_algorithm(std::string_view id) {
    for (const auto& a : registry)
        if (a.id == id) return a;
    return std::nullopt;
}

}  // namespace hsr::algo
