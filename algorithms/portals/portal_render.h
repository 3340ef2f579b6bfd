// SPDX-License-Identifier: MIT
// Runtime, the lecture's portal_render:
//
//   main():                         determine cell c of the viewpoint using the BSP tree
//                                   determine the PVS of cell c using the PVS matrix
//                                   f = the original view frustum; portal_render(c, f, PVS)
//   portal_render(c, f, PVS):       for each polygon R in c:
//                                     if R is a portal to c' in the PVS: f' = clip_frustum(f, R)
//                                                                        if f' is not empty: portal_render(c', f', PVS)
//                                     else if R is not a portal: if not back_face(R): R' = clip_poly(f, R)
//                                                                                     if R' is not empty: render(R')
//
// clip_frustum(f, R) is the intersection of f and the volume formed by the viewpoint and the portal: R is clipped
// by f's planes, and each edge of what is left makes a plane through the eye. The bounding-box variant (the
// lecture's fix for "odd convex shapes") replaces that by the four planes of its bounding rectangle on the screen.
#pragma once

#include <cstdint>
#include <vector>

#include "core/steps.h"
#include "culling/view_frustum.h"
#include "portals/cell_bsp.h"
#include "portals/cell_model.h"
#include "portals/pvs.h"

namespace hsr::algo {

struct PortalRenderOptions {
    bool bounding_box_frusta = false;
    std::uint32_t max_depth = 64;                 // portals passed on one path
    std::uint64_t max_visits = std::uint64_t(1) << 20;  // cells visited in all
};

struct PortalRenderResult {
    std::int32_t eye_cell = -1;
    std::vector<std::uint8_t> drawn;  // per polygon of the model: 1 when some part of it was drawn
    std::uint32_t visits = 0, draws = 0, culled_back_face = 0, culled_frustum = 0, portals_passed = 0;
    bool bounded = false;
};

// The cross-section of a frustum (its side planes, all through the camera's eye; near and far are ignored) with
// the plane `distance` ahead of the eye along the view direction: a convex polygon, for drawing the frustum as
// rays from the eye through its corners. Empty when the frustum is.
std::vector<Vec3> frustum_section(const std::vector<Plane>& frustum, const Camera& camera, double distance);

// Model, tree and PVS must outlive the machine. The camera must be a perspective one (else InvalidInput).
Steps<PortalEvent, PortalRenderResult> portal_render(const CellModel* model, const CellBsp* bsp, const Pvs* pvs,
                                                      Camera camera, PortalRenderOptions options = {});

}  // namespace hsr::algo
