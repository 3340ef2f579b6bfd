// SPDX-License-Identifier: MIT
// The three clipping algorithms as plain straight-line functions: the same formulas as the machines in clipping/
// (the boundary values, equations (3), the snap onto the plane), with no events, no coroutine frame and no step
// bound, in the precision T (float or double). Two uses: the benchmark that prices being a step-through machine,
// and the report's float column (how far a float clipper lands from the exact answer, next to the double one).
// Homogeneous clip space only (-w ≤ x, y, z ≤ w, w ≥ ε), the setting of perspective scenes.
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "clipping/carried_boundaries.h"
#include "core/numeric.h"

namespace hsr::algo {

template <class T>
using Vec4Of = glm::vec<4, T>;

// The boundary value of plane k (0 … 6 in clipping's order: z max, z min, y max, y min, x max, x min, w min).
template <class T>
T plain_boundary(const Vec4Of<T>& p, int k) {
    switch (k) {
        case 0: return p.w - p.z;
        case 1: return p.w + p.z;
        case 2: return p.w - p.y;
        case 3: return p.w + p.y;
        case 4: return p.w - p.x;
        case 5: return p.w + p.x;
        default: return p.w - T(ClipTolerance::w_epsilon);
    }
}

// p1 + t (p2 − p1), snapped onto plane k.
template <class T>
Vec4Of<T> plain_intersection(int k, const Vec4Of<T>& p1, const Vec4Of<T>& p2, T t) {
    Vec4Of<T> i = p1 + t * (p2 - p1);
    switch (k) {
        case 0: i.z = i.w; break;
        case 1: i.z = -i.w; break;
        case 2: i.y = i.w; break;
        case 3: i.y = -i.w; break;
        case 4: i.x = i.w; break;
        case 5: i.x = -i.w; break;
        default: i.w = T(ClipTolerance::w_epsilon); break;
    }
    return i;
}

template <class T>
using PlainSegment = std::optional<std::pair<Vec4Of<T>, Vec4Of<T>>>;  // empty: rejected

template <class T>
PlainSegment<T> plain_liang_barsky(const Vec4Of<T>& p1, const Vec4Of<T>& p2) {
    constexpr std::array<int, 7> order = {5, 4, 3, 2, 1, 0, 6};  // the lecture's left, right, bottom, top, near, far, then w
    T t_enter = 0, t_leave = 1;
    int enter = 6, leave = 6;
    for (int k : order) {
        const T q = plain_boundary(p1, k);
        const T p = q - plain_boundary(p2, k);
        if (p == 0) {
            if (q < 0) return std::nullopt;
            continue;
        }
        const T ratio = q / p;
        if (p < 0 && ratio > t_enter) t_enter = ratio, enter = k;
        if (p > 0 && ratio < t_leave) t_leave = ratio, leave = k;
        if (t_enter > t_leave) return std::nullopt;
    }
    return std::pair{t_enter > 0 ? plain_intersection(enter, p1, p2, t_enter) : p1,
                     t_leave < 1 ? plain_intersection(leave, p1, p2, t_leave) : p2};
}

template <class T>
unsigned plain_outcode(const Vec4Of<T>& p) {
    unsigned c = 0;
    for (int k = 0; k < 7; ++k)
        if (plain_boundary(p, k) < 0) c |= 1u << k;
    return c;
}

// The loop form of CS_Clip_3D, with the machine's rules: a plane once clipped against is not tested again, and
// every cut is made on the input segment (carried_boundaries.h).
template <class T>
PlainSegment<T> plain_cohen_sutherland(Vec4Of<T> p1, Vec4Of<T> p2) {
    const Vec4Of<T> in1 = p1, in2 = p2;
    T t1 = 0, t2 = 1;
    unsigned allowed = 0x7f;
    for (;;) {
        auto code = [&](T t) {  // mkcode from the input's boundary values, as the machine does
            unsigned c = 0;
            for (int k = 0; k < 7; ++k)
                if (boundary_at(plain_boundary(in1, k), plain_boundary(in2, k), t) < 0) c |= 1u << k;
            return c;
        };
        const unsigned c1 = code(t1) & allowed, c2 = code(t2) & allowed;
        if ((c1 | c2) == 0) return std::pair{p1, p2};
        if ((c1 & c2) != 0) return std::nullopt;
        int k = 0;
        while (((c1 ^ c2) >> k & 1u) == 0) ++k;
        const bool p1_outside = (c1 >> k & 1u) != 0;
        const T t = cut_parameter(plain_boundary(in1, k), plain_boundary(in2, k), t1, t2, p1_outside);
        (p1_outside ? p1 : p2) = plain_intersection(k, in1, in2, t);
        (p1_outside ? t1 : t2) = t;
        allowed = (c1 | c2) & ~(1u << k);
    }
}

template <class T>
std::vector<Vec4Of<T>> plain_sutherland_hodgman(const std::vector<Vec4Of<T>>& input_polygon) {
    using Vertex = CarriedVertex<T>;  // boundary values carried, as the machine does
    std::vector<Vertex> polygon, input;
    for (const Vec4Of<T>& p : input_polygon) {
        Vertex v{p, {}};
        for (int k = 0; k < 7; ++k) v.b[std::size_t(k)] = plain_boundary(p, k);
        polygon.push_back(v);
    }
    for (int k = 0; k < 7 && !polygon.empty(); ++k) {
        std::swap(input, polygon);
        polygon.clear();
        auto crossing = [k](const Vertex& in, const Vertex& out) {  // from the inside end, as the machine does
            return cut_edge(k, in, out, [k](const Vec4Of<T>& from, const Vec4Of<T>& to, T t) {
                return plain_intersection(k, from, to, t);
            });
        };
        for (std::size_t i = 0; i < input.size(); ++i) {
            const Vertex& s = input[i];
            const Vertex& e = input[(i + 1) % input.size()];
            const T bs = s.b[std::size_t(k)], be = e.b[std::size_t(k)];
            if (bs >= 0 && be >= 0) {
                polygon.push_back(e);
            } else if (bs >= 0) {
                polygon.push_back(crossing(s, e));
            } else if (be >= 0) {
                polygon.push_back(crossing(e, s));
                polygon.push_back(e);
            }
        }
    }
    std::vector<Vec4Of<T>> points;
    points.reserve(polygon.size());
    for (const Vertex& v : polygon) points.push_back(v.p);
    return points;
}

}  // namespace hsr::algo
