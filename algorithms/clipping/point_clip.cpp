// SPDX-License-Identifier: MIT
#include "clipping/point_clip.h"

namespace hsr::algo {
namespace {

Steps<ClipEvent, bool> clip_point_machine(ClipPoint point, ClipOptions o) {
    const Outcode c = outcode(point.p, o.space);
    co_yield PointClassified{point.id, c, point.p};
    co_return c.inside();
}

}  // namespace

Steps<ClipEvent, bool> clip_point(ClipPoint point, ClipOptions options) {
    require_clippable(point);
    return clip_point_machine(point, options);
}

}  // namespace hsr::algo
