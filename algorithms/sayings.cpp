// SPDX-License-Identifier: MIT
#include "sayings.h"

#include "abuffer/abuffer_events.h"
#include "bsp/bsp_events.h"
#include "clipping/clip_events.h"
#include "forms/forms_events.h"
#include "volumes/intersection_events.h"
#include "culling/backface.h"
#include "culling/culling_events.h"
#include "culling/hiz.h"
#include "culling/occluders.h"
#include "depth_sort/depth_sort_events.h"
#include "compositing/composite_events.h"
#include "horizon/horizon_events.h"
#include "perspective/transform_events.h"
#include "roberts/roberts_events.h"
#include "portals/portal_events.h"
#include "raycast/raycast_events.h"
#include "zbuffer/scanline_events.h"
#include "zbuffer/z_merge.h"
#include "zbuffer/zbuffer_events.h"

namespace hsr::algo {

std::vector<std::span<const Saying>> machine_sayings() {
    return {backface_sayings(), bsp_sayings(),      clipping_sayings(), culling_sayings(),  depth_sort_sayings(), hiz_sayings(),
            occluder_sayings(), portal_sayings(),   ray_cast_sayings(), scanline_sayings(), zbuffer_sayings(),    zmerge_sayings(),
            horizon_sayings(), composite_sayings(), roberts_sayings(), transform_sayings(), abuffer_sayings(), forms_sayings(), intersection_sayings()};
}

}  // namespace hsr::algo
