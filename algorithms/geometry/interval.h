// SPDX-License-Identifier: MIT
// Intervals of a line's parameter: the part [enter, exit] of a ray o + t·d inside a box, a slab or a volume, found
// by narrowing an interval one slab at a time (the slab test; Liang–Barsky's idea, in clipping/, is the same walk
// for a segment against the view volume's planes).
#pragma once

#include <algorithm>
#include <utility>

namespace hsr::algo {

struct Interval {
    double enter, exit;  // t where the ray comes in and goes out (ray units: multiples of its direction)
};

// The slab test along one direction: narrow t to where lo ≤ o + t·d ≤ hi, with o and d the ray's origin and
// direction measured along it. False when nothing is left (t is then not to be used). A ray parallel to the slab
// (d = 0) is inside it everywhere or nowhere.
inline bool narrow_to_slab(Interval& t, double lo, double hi, double o, double d) {
    if (d == 0) return o >= lo && o <= hi;
    double near = (lo - o) / d, far = (hi - o) / d;
    if (near > far) std::swap(near, far);
    t.enter = std::max(t.enter, near), t.exit = std::min(t.exit, far);
    return t.enter <= t.exit;
}

}  // namespace hsr::algo
