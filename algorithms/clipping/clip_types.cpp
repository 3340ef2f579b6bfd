// SPDX-License-Identifier: MIT
#include "clipping/clip_types.h"

#include <string>

#include "core/numeric.h"

namespace hsr::algo {

void require_clippable(const ClipSegment& s) {
    const std::string name = "segment " + std::to_string(s.id);
    require_clippable(s.p1, name + " p1");
    require_clippable(s.p2, name + " p2");
}

void require_clippable(const ClipPolygon& p) {
    for (std::size_t i = 0; i < p.vertices.size(); ++i)
        if (!clippable(p.vertices[i]))
            require_clippable(p.vertices[i], "polygon " + std::to_string(p.id) + " vertex " + std::to_string(i));
}

void require_clippable(const ClipPoint& p) { require_clippable(p.p, "point " + std::to_string(p.id)); }

}  // namespace hsr::algo
