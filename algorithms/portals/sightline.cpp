// SPDX-License-Identifier: MIT
#include "portals/sightline.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/half_space_cut.h"
#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {

constexpr double max_slope = 1000;

}  // namespace

Sightlines::Sightlines(const PortalEnds& first) {
    origin_ = (first.left + first.right) / 2.0;
    along_ = first.left - first.right;
    width_ = glm::length(along_);
    along_ /= width_;
    across_ = {along_.y, -along_.x};  // along is across rotated a quarter turn left: left is +y'
    const double t = width_ / 2;
    polygon_ = {{-max_slope, -t}, {max_slope, -t}, {max_slope, t}, {-max_slope, t}};
    area_ = area_about_first_vertex(polygon_);
}

// A point (x, y) in the first portal's frame is left of the line y' = s·x' + t when y − s·x − t > 0: a
// half-plane t + x·s < y of line space (right: t + x·s > y). Sutherland–Hodgman against it.
void Sightlines::keep(double x, double y, bool left) {
    const auto value = [&](glm::dvec2 st) { return left ? y - (st.y + x * st.x) : (st.y + x * st.x) - y; };
    polygon_ = cut_polygon(polygon_, value, {.crossing = Crossing::sign_change});
    area_ = area_about_first_vertex(polygon_);  // a sliver of line space far from (0, 0) may be 1e-9 wide
}

bool Sightlines::through(const PortalEnds& next) {
    for (const auto& [p, left] : {std::pair{next.left, true}, std::pair{next.right, false}}) {
        if (polygon_.empty()) break;
        const glm::dvec2 d = p - origin_;
        keep(glm::dot(d, across_), glm::dot(d, along_), left);
    }
    return exist();
}

// The exact answer is either an open set of lines (a polygon with area) or a degenerate one: one grazing line (a
// point of line space) or the lines through one point (a segment). Rounding leaves a degenerate set as a sliver
// about 1e-16 of its coordinates thick. So the test is on thickness (area over diameter) against the size of the
// numbers, not on area: a real band of lines through openings 1e-9 wide is some 1e-10 thick and is kept.
bool Sightlines::exist() const {
    if (polygon_.size() < 3) return false;
    double diameter = 0, size = width_;
    for (const glm::dvec2& a : polygon_) {
        size = std::max({size, std::abs(a.x), std::abs(a.y)});
        for (const glm::dvec2& b : polygon_) diameter = std::max(diameter, glm::length(a - b));
    }
    return diameter > 0 && area_ / diameter > 1e-12 * size;
}

std::pair<glm::dvec2, glm::dvec2> Sightlines::example() const {
    glm::dvec2 mean(0);
    for (const auto& p : polygon_) mean += p / double(polygon_.size());
    return {origin_ + along_ * mean.y, glm::normalize(across_ + along_ * mean.x)};
}

}  // namespace hsr::algo
