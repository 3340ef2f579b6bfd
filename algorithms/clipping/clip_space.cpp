// SPDX-License-Identifier: MIT
#include "clipping/clip_space.h"

#include "core/numeric.h"

namespace hsr::algo {

std::string to_string(Outcode c) {
    std::string s;
    for (int k = 0; k < 6; ++k) s += c.has(all_planes[k]) ? '1' : '0';
    if (c.has(ClipPlane::w_min)) s += "+w";
    return s;
}

std::string_view plane_inequality(ClipPlane p, ClipSpace s) {
    const bool h = s == ClipSpace::homogeneous;
    switch (p) {
        case ClipPlane::z_max: return h ? "z ≤ w" : "z ≤ 1";
        case ClipPlane::z_min: return h ? "z ≥ −w" : "z ≥ −1";
        case ClipPlane::y_max: return h ? "y ≤ w" : "y ≤ 1";
        case ClipPlane::y_min: return h ? "y ≥ −w" : "y ≥ −1";
        case ClipPlane::x_max: return h ? "x ≤ w" : "x ≤ 1";
        case ClipPlane::x_min: return h ? "x ≥ −w" : "x ≥ −1";
        case ClipPlane::w_min: return "w ≥ ε";
    }
    return "?";
}

std::string_view plane_name(ClipPlane p) {
    switch (p) {
        case ClipPlane::z_max: return "z max";
        case ClipPlane::z_min: return "z min";
        case ClipPlane::y_max: return "y max";
        case ClipPlane::y_min: return "y min";
        case ClipPlane::x_max: return "x max";
        case ClipPlane::x_min: return "x min";
        case ClipPlane::w_min: return "w min";
    }
    return "?";
}

double boundary_value(const Vec4& p, ClipPlane r, ClipSpace s) {
    const double w = s == ClipSpace::homogeneous ? p.w : 1.0;  // the cube's limits are the constants ±1
    switch (r) {
        case ClipPlane::z_max: return w - p.z;
        case ClipPlane::z_min: return w + p.z;
        case ClipPlane::y_max: return w - p.y;
        case ClipPlane::y_min: return w + p.y;
        case ClipPlane::x_max: return w - p.x;
        case ClipPlane::x_min: return w + p.x;
        case ClipPlane::w_min: return s == ClipSpace::homogeneous ? p.w - ClipTolerance::w_epsilon : 1.0;
    }
    return 0.0;
}

Outcode outcode(const Vec4& p, ClipSpace s) {
    Outcode c;
    for (int k = 0; k < plane_count(s); ++k)
        if (boundary_value(p, all_planes[k], s) < 0) c.bits |= Outcode::mask(all_planes[k]);
    return c;
}

double intersection_parameter(double bc1, double bc2) { return bc1 / (bc1 - bc2); }

Vec4 intersect_plane_line(ClipPlane r, ClipSpace s, const Vec4& p1, const Vec4& p2, double t) {
    Vec4 i = p1 + t * (p2 - p1);
    const double w = s == ClipSpace::homogeneous ? i.w : 1.0;
    // Snap onto R: the coordinate the plane constrains takes the plane's value exactly.
    switch (r) {
        case ClipPlane::z_max: i.z = w; break;
        case ClipPlane::z_min: i.z = -w; break;
        case ClipPlane::y_max: i.y = w; break;
        case ClipPlane::y_min: i.y = -w; break;
        case ClipPlane::x_max: i.x = w; break;
        case ClipPlane::x_min: i.x = -w; break;
        case ClipPlane::w_min: i.w = ClipTolerance::w_epsilon; break;
    }
    return i;
}

}  // namespace hsr::algo
