// SPDX-License-Identifier: MIT
#include "geometry/polygon_2d.h"

#include <algorithm>

namespace hsr::algo {

double area_about_first_vertex(const std::vector<glm::dvec2>& p) {
    if (p.size() < 3) return 0;
    double twice = 0;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) twice += cross(p[i] - p[0], p[i + 1] - p[0]);
    return std::abs(twice) / 2;
}

std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    std::vector<glm::dvec2> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain, left to right: drop every corner that does not turn left
        while (k >= 2 && orientation(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper chain, right to left
        while (k >= t && orientation(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);  // the last point is the first again
    return h;
}

}  // namespace hsr::algo
