// SPDX-License-Identifier: MIT
#include "portals/stab3d.h"

#include <optional>

#include <glm/geometric.hpp>

#include "geometry/half_space_cut.h"

namespace hsr::algo {
namespace {

// The plane through p, q and r; nullopt when they are on one line.
std::optional<Plane> plane_through(const Vec3& p, const Vec3& q, const Vec3& r) {
    const Vec3 n = glm::cross(q - p, r - p);
    const double len = glm::length(n);
    if (!(len > 0)) return std::nullopt;
    const Vec3 u = n / len;
    return Plane{u, -glm::dot(u, p)};
}

// Every vertex of `v` on the side `sign` (+1 or −1) of the plane, within tol; and at least one clearly there.
bool all_on_side(const Plane& pl, const std::vector<Vec3>& v, double sign, double tol) {
    bool clear = false;
    for (const Vec3& x : v) {
        const double d = sign * pl.distance(x);
        if (d < -tol) return false;
        clear = clear || d > tol;
    }
    return clear;
}

void add_candidates(const std::vector<Vec3>& edges_of, const std::vector<Vec3>& corners_of, const std::vector<Vec3>& a,
                    const std::vector<Vec3>& b, double tol, std::vector<Plane>& out) {
    for (std::size_t i = 0; i < edges_of.size(); ++i) {
        const Vec3& p = edges_of[i];
        const Vec3& q = edges_of[(i + 1) % edges_of.size()];
        for (const Vec3& r : corners_of) {
            auto pl = plane_through(p, q, r);
            if (!pl) continue;
            if (all_on_side(*pl, a, -1, tol) && all_on_side(*pl, b, +1, tol)) out.push_back(*pl);
            else if (all_on_side(*pl, a, +1, tol) && all_on_side(*pl, b, -1, tol)) out.push_back(Plane{-pl->n, -pl->d});
        }
    }
}

// Sutherland–Hodgman against one plane, keeping what is on its positive side or within tol of it. (Not
// portal_render's clip_poly: that drops slivers with no area to speak of, and here a sliver may be a real band of
// sightlines 1e-9 wide; the test must keep it to stay conservative.)
std::vector<Vec3> clip(const std::vector<Vec3>& poly, const Plane& pl, double tol) {
    return cut_polygon(poly, [&](const Vec3& p) { return pl.distance(p) + tol; }, {.crossing = Crossing::sign_change});
}

}  // namespace

std::vector<Plane> separating_planes(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double tol) {
    std::vector<Plane> out;
    add_candidates(a, b, a, b, tol, out);
    add_candidates(b, a, a, b, tol, out);
    return out;
}

SolidSightlines::SolidSightlines(std::vector<Vec3> first, double tol) : first_(std::move(first)), current_(first_), tol_(tol) {}

bool SolidSightlines::through(const std::vector<Vec3>& next) {
    if (second_) {  // a segment joins any point of the first opening to any point of the second
        second_ = false;
        current_ = next;
        return current_.size() >= 3;
    }
    std::vector<Vec3> part = next;
    const std::vector<Plane> planes = separating_planes(first_, current_, tol_);
    planes_ = planes.size();
    for (const Plane& pl : planes) {
        if (part.size() < 3) break;
        part = clip(part, pl, tol_);
    }
    current_ = std::move(part);
    return current_.size() >= 3;
}

}  // namespace hsr::algo
