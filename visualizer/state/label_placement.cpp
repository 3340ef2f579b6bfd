// SPDX-License-Identifier: MIT
#include "state/label_placement.h"

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
    for (const LabelBox& l : labels) {
        const float gap = 6, line = l.height;
        // a point under a covered part: its label goes just above that part (the tries then start there)
        float x = l.x, y = l.y;
        for (const ViewRect& c : covered)
            if (x >= c.left && x <= c.right && y >= c.top && y <= c.bottom) y = c.top - gap;
        // upper right (the usual spot), lower right, upper left, lower left; then a line further up or down
        const Placed tries[] = {
            {x + gap, y - line}, {x + gap, y}, {x - gap - l.width, y - line}, {x - gap - l.width, y},
            {x + gap, y - 2 * line}, {x + gap, y + line}, {x - gap - l.width, y - 2 * line}, {x - gap - l.width, y + line},
        };
        Placed chosen = tries[0];
        chosen.shown = out.size() < always_shown;
        for (const Placed& p : tries) {
            const Rect r{p.left, p.top, p.left + l.width, p.top + l.height};
            bool free = true;
            for (const Rect& t : taken) free = free && !r.overlaps(t);
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
