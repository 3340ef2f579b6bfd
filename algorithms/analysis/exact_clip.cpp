// SPDX-License-Identifier: MIT
#include "analysis/exact_clip.h"

#include <algorithm>
#include <cmath>

#include "core/numeric.h"

namespace hsr::analysis {
namespace {

ExactPoint exact(const Vec4& p) { return {{mpq_class(p.x), mpq_class(p.y), mpq_class(p.z), mpq_class(p.w)}}; }

mpq_class boundary(const ExactPoint& p, algo::ClipPlane r, ClipSpace s) {
    const mpq_class w = s == ClipSpace::homogeneous ? p.c[3] : mpq_class(1);
    switch (r) {
        case algo::ClipPlane::z_max: return w - p.c[2];
        case algo::ClipPlane::z_min: return w + p.c[2];
        case algo::ClipPlane::y_max: return w - p.c[1];
        case algo::ClipPlane::y_min: return w + p.c[1];
        case algo::ClipPlane::x_max: return w - p.c[0];
        case algo::ClipPlane::x_min: return w + p.c[0];
        case algo::ClipPlane::w_min:
            return s == ClipSpace::homogeneous ? p.c[3] - mpq_class(algo::ClipTolerance::w_epsilon) : mpq_class(1);
    }
    return 0;
}

ExactPoint lerp(const ExactPoint& a, const ExactPoint& b, const mpq_class& t) {
    ExactPoint r;
    for (int i = 0; i < 4; ++i) r.c[i] = a.c[i] + t * (b.c[i] - a.c[i]);
    return r;
}

}  // namespace

ExactSegment exact_clip_segment(const Vec4& p1, const Vec4& p2, ClipSpace s) {
    const ExactPoint e1 = exact(p1), e2 = exact(p2);
    mpq_class t0 = 0, t1 = 1;
    for (int k = 0; k < algo::plane_count(s); ++k) {
        const mpq_class b1 = boundary(e1, algo::all_planes[k], s), b2 = boundary(e2, algo::all_planes[k], s);
        if (b1 < 0 && b2 < 0) return {};
        if (b1 < 0) t0 = std::max(t0, mpq_class(b1 / (b1 - b2)));
        if (b2 < 0) t1 = std::min(t1, mpq_class(b1 / (b1 - b2)));
    }
    if (t0 > t1) return {};
    return {true, lerp(e1, e2, t0), lerp(e1, e2, t1), t0 > 0 || t1 < 1};
}

std::vector<ExactPoint> exact_clip_polygon(const std::vector<Vec4>& polygon, ClipSpace s) {
    std::vector<ExactPoint> out, in;
    for (const auto& v : polygon) out.push_back(exact(v));
    for (int k = 0; k < algo::plane_count(s) && !out.empty(); ++k) {
        const algo::ClipPlane r = algo::all_planes[k];
        std::swap(in, out);
        out.clear();
        for (std::size_t i = 0; i < in.size(); ++i) {
            const ExactPoint& a = in[i];
            const ExactPoint& b = in[(i + 1) % in.size()];
            const mpq_class ba = boundary(a, r, s), bb = boundary(b, r, s);
            if ((ba >= 0) != (bb >= 0)) out.push_back(lerp(a, b, ba / (ba - bb)));
            if (bb >= 0) out.push_back(b);
        }
    }
    return out;
}

double relative_error(const Vec4& a, const ExactPoint& b, double scale) {
    double e = 0;
    for (int i = 0; i < 4; ++i) {
        const mpq_class d = mpq_class(a[i]) - b.c[i];
        e = std::max(e, std::fabs(d.get_d()));
    }
    return e / std::max(1.0, scale);
}

double vertex_set_error(const std::vector<Vec4>& got, const std::vector<ExactPoint>& exact, double scale) {
    double e = 0;
    for (const Vec4& g : got) {
        double best = 1e300;
        for (const ExactPoint& x : exact) best = std::min(best, relative_error(g, x, scale));
        e = std::max(e, best);
    }
    for (const ExactPoint& x : exact) {
        double best = 1e300;
        for (const Vec4& g : got) best = std::min(best, relative_error(g, x, scale));
        e = std::max(e, best);
    }
    return e;
}

}  // namespace hsr::analysis
