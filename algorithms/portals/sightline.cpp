#include "portals/sightline.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace hsr::algo {
namespace {

constexpr double max_slope = 1000;

double polygon_area(const std::vector<glm::dvec2>& p) {
    double twice = 0;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) twice += p[j].x * p[i].y - p[i].x * p[j].y;
    return p.size() < 3 ? 0 : std::abs(twice) / 2;
}

}  // namespace

Sightlines::Sightlines(const PortalEnds& first) {
    origin_ = (first.left + first.right) / 2.0;
    along_ = first.left - first.right;
    width_ = glm::length(along_);
    along_ /= width_;
    across_ = {along_.y, -along_.x};  // along is across rotated a quarter turn left: left is +y'
    const double t = width_ / 2;
    polygon_ = {{-max_slope, -t}, {max_slope, -t}, {max_slope, t}, {-max_slope, t}};
    area_ = polygon_area(polygon_);
}

// A point (x, y) in the first portal's frame is left of the line y' = s·x' + t when y − s·x − t > 0: a
// half-plane t + x·s < y of line space (right: t + x·s > y). Sutherland–Hodgman against it.
void Sightlines::keep(double x, double y, bool left) {
    const auto value = [&](glm::dvec2 st) { return left ? y - (st.y + x * st.x) : (st.y + x * st.x) - y; };
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < polygon_.size(); ++i) {
        const glm::dvec2 a = polygon_[i], b = polygon_[(i + 1) % polygon_.size()];
        const double va = value(a), vb = value(b);
        if (va >= 0) out.push_back(a);
        if ((va >= 0) != (vb >= 0)) out.push_back(a + (b - a) * (va / (va - vb)));
    }
    polygon_ = std::move(out);
    area_ = polygon_area(polygon_);
}

bool Sightlines::through(const PortalEnds& next) {
    for (const auto& [p, left] : {std::pair{next.left, true}, std::pair{next.right, false}}) {
        if (polygon_.empty()) break;
        const glm::dvec2 d = p - origin_;
        keep(glm::dot(d, across_), glm::dot(d, along_), left);
    }
    return exist();
}

// "Area" relative to a slope range of 1 and the first portal's width: rounding leaves ~1e-16 of it behind where
// the exact answer is a segment (collinear openings), a real set of sightlines leaves far more.
bool Sightlines::exist() const { return area_ > 1e-12 * width_; }

std::pair<glm::dvec2, glm::dvec2> Sightlines::example() const {
    glm::dvec2 mean(0);
    for (const auto& p : polygon_) mean += p / double(polygon_.size());
    return {origin_ + along_ * mean.y, glm::normalize(across_ + along_ * mean.x)};
}

}  // namespace hsr::algo
