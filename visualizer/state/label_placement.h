// SPDX-License-Identifier: MIT
// Where the labels of a view go so that none covers another, nor another's point: each wants the spot to the upper
// right of its point; when that spot is taken, it tries the other corners and then spots a line further away (up to
// five lines), and takes the first free one. If none is free, the first `always_shown` labels take their own spot anyway (what a small scene or the
// question is about is never hidden); a later one is not shown (a crowd of them, on a scene of thousands of
// polygons, would be an unreadable pile). Labels placed first keep their spots: pass the most important first.
//
// `covered`: parts of the view a canvas draws over (an inset, a picture), where a label would be hidden. No label is
// placed on them; a label whose point lies under one goes just above it, at the point's x.
#pragma once

#include <cstddef>
#include <vector>

namespace hsr::viz {

struct LabelBox {
    float x, y;           // the point labelled, in pixels
    float width, height;  // of its text
};
struct ViewRect {
    float left, top, right, bottom;
};
struct Placed {
    float left, top;    // of the text
    bool shown = true;  // false: no free spot, and past the labels always shown
};

std::vector<Placed> place_labels(const std::vector<LabelBox>& labels, std::size_t always_shown = 12,
                                 const std::vector<ViewRect>& covered = {});

}  // namespace hsr::viz
