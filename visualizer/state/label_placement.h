// Where the labels of a view go so that none covers another: each wants the spot to the upper right of its point;
// when that spot is taken, it tries the other corners and then spots a line further away, and takes the first free
// one (if none is free, its own spot). Labels placed first keep their spots: pass the most important first.
#pragma once

#include <vector>

namespace hsr::viz {

struct LabelBox {
    float x, y;           // the point labelled, in pixels
    float width, height;  // of its text
};
struct Placed {
    float left, top;  // of the text
};

std::vector<Placed> place_labels(const std::vector<LabelBox>& labels);

}  // namespace hsr::viz
