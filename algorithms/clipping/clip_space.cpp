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

EquationThree equation_three(ClipPlane r, ClipSpace s, const Vec4& p1, const Vec4& p2) {
    const bool h = s == ClipSpace::homogeneous;
    const double w1 = h ? p1.w : 1.0, w2 = h ? p2.w : 1.0;
    // lower planes (left, bottom, near): t = (a1 + w1) / ((a1 − a2) + (w1 − w2));
    // upper planes (right, top, far):   t = (a1 − w1) / ((a1 − a2) + (w2 − w1))
    const auto lower = [&](double a1, double a2, std::string_view f) { return EquationThree{f, a1 + w1, (a1 - a2) + (w1 - w2)}; };
    const auto upper = [&](double a1, double a2, std::string_view f) { return EquationThree{f, a1 - w1, (a1 - a2) + (w2 - w1)}; };
    switch (r) {
        case ClipPlane::x_min: return lower(p1.x, p2.x, h ? "(x1 + w1) / ((x1 − x2) + (w1 − w2))" : "(x1 + 1) / (x1 − x2)");
        case ClipPlane::x_max: return upper(p1.x, p2.x, h ? "(x1 − w1) / ((x1 − x2) + (w2 − w1))" : "(x1 − 1) / (x1 − x2)");
        case ClipPlane::y_min: return lower(p1.y, p2.y, h ? "(y1 + w1) / ((y1 − y2) + (w1 − w2))" : "(y1 + 1) / (y1 − y2)");
        case ClipPlane::y_max: return upper(p1.y, p2.y, h ? "(y1 − w1) / ((y1 − y2) + (w2 − w1))" : "(y1 − 1) / (y1 − y2)");
        case ClipPlane::z_min: return lower(p1.z, p2.z, h ? "(z1 + w1) / ((z1 − z2) + (w1 − w2))" : "(z1 + 1) / (z1 − z2)");
        case ClipPlane::z_max: return upper(p1.z, p2.z, h ? "(z1 − w1) / ((z1 − z2) + (w2 − w1))" : "(z1 − 1) / (z1 − z2)");
        case ClipPlane::w_min:  // not in the notes: w = ε, the plane that keeps the divide away from the eye
            return {"(w1 − ε) / (w1 − w2)", h ? p1.w - ClipTolerance::w_epsilon : 1.0, w1 - w2};
    }
    return {};
}

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
