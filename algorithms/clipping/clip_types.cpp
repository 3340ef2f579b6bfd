#include "clipping/clip_types.h"

#include <string>

#include "core/numeric.h"

namespace hsr::algo {

void require_finite(const ClipSegment& s) {
    const std::string name = "segment " + std::to_string(s.id);
    require_finite(s.p1, name + " p1");
    require_finite(s.p2, name + " p2");
}

void require_finite(const ClipPolygon& p) {
    for (std::size_t i = 0; i < p.vertices.size(); ++i)
        require_finite(p.vertices[i], [&] { return "polygon " + std::to_string(p.id) + " vertex " + std::to_string(i); });
}

void require_finite(const ClipPoint& p) { require_finite(p.p, "point " + std::to_string(p.id)); }

}  // namespace hsr::algo
