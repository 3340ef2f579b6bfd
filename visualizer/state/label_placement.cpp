// SPDX-License-Identifier: MIT
#include "state/label_placement.h"

namespace hsr::viz {
namespace {

struct Rect {
    float left, top, right, bottom;
    bool overlaps(const Rect& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
};

}  // namespace

std::vector<Placed> place_labels(const std::vector<LabelBox>& labels, std::size_t always_shown) {
    std::vector<Placed> out;
    std::vector<Rect> taken;
    for (const LabelBox& l : labels) {
        const float gap = 6, line = l.height;
        // upper right (the usual spot), lower right, upper left, lower left; then a line further up or down
        const Placed tries[] = {
            {l.x + gap, l.y - line}, {l.x + gap, l.y}, {l.x - gap - l.width, l.y - line}, {l.x - gap - l.width, l.y},
            {l.x + gap, l.y - 2 * line}, {l.x + gap, l.y + line}, {l.x - gap - l.width, l.y - 2 * line}, {l.x - gap - l.width, l.y + line},
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
