// SPDX-License-Identifier: MIT
#include "geometry/exact_collinear.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hsr::algo {
namespace {

// Error-free transformations (Knuth, Dekker; Shewchuk, "Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", 1997): a + b and a · b as a rounded result plus the exact rounding error.
void two_sum(double a, double b, double& sum, double& error) {
    sum = a + b;
    const double b_virtual = sum - a, a_virtual = sum - b_virtual;
    error = (a - a_virtual) + (b - b_virtual);
}
void two_product(double a, double b, double& product, double& error) {
    product = a * b;
    error = std::fma(a, b, -product);
}

// The exact sum of the terms as a nonoverlapping expansion (Shewchuk's Grow-Expansion, zeros dropped): it is zero
// exactly when no component is left.
bool sums_to_zero(const std::vector<double>& terms) {
    std::vector<double> expansion;
    for (double q : terms) {
        std::vector<double> grown;
        for (double e : expansion) {
            double sum = 0, error = 0;
            two_sum(q, e, sum, error);
            if (error != 0) grown.push_back(error);
            q = sum;
        }
        if (q != 0) grown.push_back(q);
        expansion = std::move(grown);
    }
    return expansion.empty();
}

// (b − a)(c − d) − (e − f)(g − h) == 0, exactly: each difference is two doubles, each product of two of them four.
bool difference_of_products_is_zero(double a, double b, double c, double d, double e, double f, double g, double h) {
    std::vector<double> terms;
    const auto add_product = [&](double p, double q, double r, double s, double sign) {
        double u[2], v[2];
        two_sum(p, -q, u[0], u[1]);
        two_sum(r, -s, v[0], v[1]);
        for (double x : u)
            for (double y : v) {
                double product = 0, error = 0;
                two_product(x, y, product, error);
                terms.push_back(sign * product), terms.push_back(sign * error);
            }
    };
    add_product(b, a, c, d, 1);
    add_product(e, f, g, h, -1);
    return sums_to_zero(terms);
}

}  // namespace

bool collinear_exactly(std::span<const Vec3> points) {
    if (points.empty()) return true;
    // a power of two brings the largest coordinate near 1: exact, and the products stay far from overflow
    double largest = 0;
    for (const Vec3& p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    if (!std::isfinite(largest)) return false;  // not ours to decide: the scene's reader refuses it
    const double k = largest > 0 ? std::ldexp(1.0, -std::ilogb(largest)) : 1.0;
    const Vec3 a = points[0] * k;
    const auto other = std::find_if(points.begin(), points.end(), [&](const Vec3& p) { return p * k != a; });
    if (other == points.end()) return true;  // all at one point
    const Vec3 b = *other * k;
    for (const Vec3& p : points) {
        const Vec3 c = p * k;
        // c on the line through a and b: (b − a) × (c − a) = 0, each component a 2D orientation
        if (!difference_of_products_is_zero(a.x, b.x, c.y, a.y, b.y, a.y, c.x, a.x)) return false;
        if (!difference_of_products_is_zero(a.y, b.y, c.z, a.z, b.z, a.z, c.y, a.y)) return false;
        if (!difference_of_products_is_zero(a.z, b.z, c.x, a.x, b.x, a.x, c.z, a.z)) return false;
    }
    return true;
}

}  // namespace hsr::algo
