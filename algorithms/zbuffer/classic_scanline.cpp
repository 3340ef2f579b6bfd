// SPDX-License-Identifier: MIT
#include "zbuffer/classic_scanline.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace hsr::algo {
namespace {

// One intersection of the active edge table with the scan line.
struct Intersection {
    int bound;  // the first pixel inside (a left edge) or one past the last (a right edge), clamped to the line
    double x;   // where the edge crosses the line's centre
    bool left;
    std::uint32_t edge;
};

// Sorted by x, as pixels see it: by bound, then a polygon's left edge before its right edge on the same pixel (a
// sliver enters before it leaves, covering nothing), then by x for the narration.
bool before(const Intersection& a, const Intersection& b) {
    return std::tuple(a.bound, !a.left, a.x, a.edge) < std::tuple(b.bound, !b.left, b.x, b.edge);
}

double depth_at(const ScreenPolygon& p, int px, int y) { return p.plane.at(pixel_centre(px), pixel_centre(y)); }

// p is seen before q at pixel px: nearer (smaller window depth), on a tie the lower index, as the z-buffer draws.
bool seen_before(const std::vector<ScreenPolygon>& polygons, std::int32_t p, std::int32_t q, int px, int y) {
    const double dp = depth_at(polygons[std::size_t(p)], px, y), dq = depth_at(polygons[std::size_t(q)], px, y);
    return dp < dq || (dp == dq && p < q);
}

// The first pixel of [from + 1, end) where q is seen before `nearest`, or end. Along a scan line both depths are
// linear in x, so their difference changes sign at most once: where the planes meet, x = x0 + (dq − dn) / (sn − sq).
// The estimate is then checked against the planes at the pixels themselves.
int first_pixel_nearer(const std::vector<ScreenPolygon>& polygons, std::int32_t nearest, std::int32_t q, int from, int end, int y,
                       double& x_meet) {
    const ScreenPolygon &n = polygons[std::size_t(nearest)], &o = polygons[std::size_t(q)];
    const double slope = o.plane.per_x - n.plane.per_x;  // of dq − dn, per pixel
    if (!(slope < 0)) return end;                        // q falls no nearer along the line
    const double gap = depth_at(o, from, y) - depth_at(n, from, y);
    x_meet = pixel_centre(from) + gap / -slope;
    if (!(x_meet - 0.5 < double(end))) return end;
    int k = std::max(from + 1, int(std::ceil(x_meet - 0.5)));
    while (k > from + 1 && seen_before(polygons, q, nearest, k - 1, y)) --k;
    while (k < end && !seen_before(polygons, q, nearest, k, y)) ++k;
    return k;
}

}  // namespace

EdgeFields edge_fields(const EdgeEntry& e) {
    const double dx = double(e.b.x - e.a.x) / double(e.b.y - e.a.y);  // both in sub-pixels: pixels of x per line
    return {edge_x_at_row(e.a, e.b, e.first_row), e.end_row - 1, dx};
}

Steps<ScanLineEvent, FrameDepth> classic_scan_line(std::vector<ScreenPolygon> polygons, ClassicScanLineOptions co) {
    const ScanLineOptions& o = co.line;
    const int w = o.viewport.width, h = o.viewport.height;
    const auto far = std::uint32_t(far_code(o.format, o.range));
    FrameDepth out{Image(w, h, o.background), std::vector<std::uint32_t>(std::size_t(w) * std::size_t(h), far),
                   std::vector<std::int32_t>(std::size_t(w) * std::size_t(h), -1)};
    // Colour pixels [x0, x1) of line y with polygon `owner` (−1: background).
    const auto paint = [&](int y, int x0, int x1, std::int32_t owner) {
        for (int x = x0; x < x1; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
            out.polygon[k] = owner;
            if (owner < 0) continue;
            const ScreenPolygon& p = polygons[std::size_t(owner)];
            out.depth[k] = std::uint32_t(code_of_window_depth(o.format, depth_at(p, x, y), o.range, o.perspective));
            out.image.ids[k] = p.id;
            out.image.rgb[3 * k] = p.color.r, out.image.rgb[3 * k + 1] = p.color.g, out.image.rgb[3 * k + 2] = p.color.b;
        }
    };
    const auto id_of = [&](std::int32_t owner) { return owner < 0 ? SceneId(0) : polygons[std::size_t(owner)].id; };

    const std::vector<EdgeEntry> et = edge_table(polygons, o.viewport);
    std::uint32_t drawn = 0;
    for (const auto& p : polygons) drawn += p.status == ScreenStatus::drawn;
    co_yield EdgeTableBuilt{std::uint32_t(et.size()), drawn};

    std::vector<std::int32_t> in;     // the polygons whose flag is in, in the order they came in
    std::vector<std::uint32_t> aet;   // indices into the edge table
    std::vector<Intersection> line;   // the AET's intersections with the current line, sorted
    std::size_t next = 0;             // the first edge of the ET not yet entered
    std::uint64_t steps = 0, spans = 0;
    for (int y = 0; y < h; ++y) {
        co_yield ScanLineStarted{y};
        for (const ScanLineEvent& moved : advance_active_edges(et, aet, next, y))
            if (o.tell_crossings) co_yield moved;
        line.clear();
        for (std::uint32_t e : aet) {
            const EdgeEntry& edge = et[e];
            line.push_back({std::clamp(edge_bound_on_row(edge.a, edge.b, y), 0, w), edge_x_at_row(edge.a, edge.b, y), edge.left, e});
        }
        std::sort(line.begin(), line.end(), before);
        in.clear();
        // Segment i runs from intersection i to the next (segment −1: from the line's start to the first).
        for (std::ptrdiff_t i = -1; i < std::ptrdiff_t(line.size()); ++i) {
            if (i >= 0) {
                if (++steps > o.max_crossings) {
                    out.bounded = true;
                    co_yield ScanStepBoundReached{o.max_crossings};
                    co_return out;
                }
                const Intersection& at = line[std::size_t(i)];
                const auto polygon = std::int32_t(et[at.edge].polygon);
                std::erase(in, polygon);
                if (at.left) in.push_back(polygon);
                if (o.tell_crossings) co_yield EdgeCrossed{at.edge, std::uint32_t(polygon), y, at.x, at.left, true};
            }
            const int begin = i < 0 ? 0 : line[std::size_t(i)].bound;
            const int end = i + 1 < std::ptrdiff_t(line.size()) ? line[std::size_t(i + 1)].bound : w;
            for (int px = begin; px < end;) {
                if (in.empty()) {  // background up to the next intersection
                    paint(y, px, end, -1);
                    co_yield SpanColored{y, px, end, -1, 0};
                    ++spans;
                    break;
                }
                if (++steps > o.max_crossings) {
                    out.bounded = true;
                    co_yield ScanStepBoundReached{o.max_crossings};
                    co_return out;
                }
                // The nearest polygon in, by the plane equations at this span's first pixel
                std::int32_t nearest = in.front(), second = -1;
                for (std::int32_t p : in)
                    if (p != nearest && seen_before(polygons, p, nearest, px, y)) nearest = p;
                for (std::int32_t p : in)
                    if (p != nearest && (second < 0 || seen_before(polygons, p, second, px, y))) second = p;
                if (second >= 0 && o.tell_crossings)
                    co_yield DepthsCompared{y, pixel_centre(px), std::uint32_t(in.size()), nearest,
                                            depth_at(polygons[std::size_t(nearest)], px, y), second,
                                            depth_at(polygons[std::size_t(second)], px, y)};
                // It stays the nearest up to the next intersection, unless another polygon in pierces it before
                int until = end;
                std::int32_t piercing = -1;
                double x_meet = 0;
                if (co.find_piercings)
                    for (std::int32_t p : in) {
                        if (p == nearest) continue;
                        double meet = 0;
                        const int k = first_pixel_nearer(polygons, nearest, p, px, until, y, meet);
                        if (k < until) until = k, piercing = p, x_meet = meet;
                    }
                if (piercing >= 0 && o.tell_crossings) co_yield PiercingFound{y, x_meet, nearest, piercing, until};
                paint(y, px, until, nearest);
                co_yield SpanColored{y, px, until, nearest, id_of(nearest)};
                ++spans;
                px = until;
            }
        }
    }
    co_yield ScanFinished{std::uint32_t(h), spans};
    co_return out;
}

}  // namespace hsr::algo
