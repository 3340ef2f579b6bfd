// SPDX-License-Identifier: MIT
#include "state/label_placement.h"

#include <algorithm>

namespace hsr::viz {
namespace {

struct Rect {
    float left, top, right, bottom;
    bool overlaps(const Rect& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
};

}  // namespace

std::vector<Placed> place_labels(const std::vector<LabelBox>& labels, std::size_t always_shown, const std::vector<ViewRect>& covered) {
    std::vector<Placed> out;
    std::vector<Rect> taken;
    for (const ViewRect& c : covered) taken.push_back({c.left, c.top, c.right, c.bottom});
    // every label's own point is kept clear of the others' text: a label there would hide what another one names
    constexpr float point = 3;
    std::vector<Rect> points;
    for (const LabelBox& l : labels) points.push_back({l.x - point, l.y - point, l.x + point, l.y + point});
    for (std::size_t n = 0; n < labels.size(); ++n) {
        const LabelBox& l = labels[n];
        const float gap = 6, line = l.height;
        // a point under a covered part: its label goes just above that part (the tries then start there)
        float x = l.x, y = l.y;
        for (const ViewRect& c : covered)
            if (x >= c.left && x <= c.right && y >= c.top && y <= c.bottom) y = c.top - gap;
        // upper right (the usual spot), lower right, upper left, lower left; then the same a line further up or down
        // each time, up to four (the window draws a leader to a label moved off its point)
        std::vector<Placed> tries;
        for (int ring = 0; ring < 5; ++ring) {
            const float up = y - float(ring + 1) * line, down = y + float(ring) * line;
            tries.insert(tries.end(), {{x + gap, up}, {x + gap, down}, {x - gap - l.width, up}, {x - gap - l.width, down}});
        }
        Placed chosen = tries[0];
        chosen.shown = out.size() < always_shown;
        for (const Placed& p : tries) {
            const Rect r{p.left, p.top, p.left + l.width, p.top + l.height};
            bool free = std::none_of(taken.begin(), taken.end(), [&](const Rect& t) { return r.overlaps(t); });
            // its own point it may touch (and another label's at the same place)
            for (std::size_t k = 0; k < points.size() && free; ++k) free = (labels[k].x == l.x && labels[k].y == l.y) || !r.overlaps(points[k]);
            if (free) {
                chosen = p;
                break;
            }
        }
        out.push_back(chosen);
        if (chosen.shown) taken.push_back({chosen.left, chosen.top, chosen.left + l.width, chosen.top + l.height});
    }
    return out;
}

}  // namespace hsr::viz
