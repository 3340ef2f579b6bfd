// SPDX-License-Identifier: MIT
#include "zbuffer/binned_fill.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "core/parallel.h"
#include "raster/span_walker.h"
#include "zbuffer/depth_test_row.h"

namespace hsr::algo {
namespace {

constexpr int tile_w = 1024, tile_h = 64;  // bands of rows: fewer spans to find twice than small tiles

struct Bins {
    int columns = 0, rows = 0;
    std::vector<std::vector<std::uint32_t>> polygons;  // per tile, in polygon order
};

// The pixel columns a polygon's spans can reach: its vertices' extent, widened by a pixel.
std::pair<int, int> column_range(const ScreenPolygon& p, int width) {
    std::int64_t lo = p.vertices[0].x, hi = lo;
    for (const auto& v : p.vertices) lo = std::min(lo, v.x), hi = std::max(hi, v.x);
    return {int(std::clamp<std::int64_t>(lo / subpixels - 1, 0, width)), int(std::clamp<std::int64_t>(hi / subpixels + 2, 0, width))};
}

// One tile: each of its polygons over the tile's rows and columns, as zbuffer_fill's loop does it.
void fill_tile(FrameDepth& out, const std::vector<ScreenPolygon>& polygons, const std::vector<std::uint32_t>& list, const ZBufferOptions& o,
               double levels, int tx, int ty, std::uint64_t* tested, std::uint64_t* written) {
    const int x0 = tx * tile_w, x1 = std::min(o.viewport.width, x0 + tile_w);
    const int y0 = ty * tile_h, y1 = std::min(o.viewport.height, y0 + tile_h);
    for (std::size_t n = 0; n < list.size(); ++n) {
        // the polygons are far apart in memory: ask for the ones a few places ahead (and their vertices) now
        if (n + 8 < list.size()) __builtin_prefetch(&polygons[list[n + 8]]);
        if (n + 4 < list.size()) __builtin_prefetch(polygons[list[n + 4]].vertices.data());
        const std::uint32_t index = list[n];
        const ScreenPolygon& p = polygons[index];
        // the row depth by the same additions as the machine: from the polygon's first row
        double row_depth = p.plane.at(0, pixel_centre(p.row_begin));
        int y = p.row_begin;
        for (; y < y0; ++y) row_depth += p.plane.per_y;
        std::uint64_t tested_here = 0, written_here = 0;
        for (SpanWalker walk(p, y, o.viewport); y < std::min(p.row_end, y1); ++y, row_depth += p.plane.per_y, walk.next_row()) {
            const Span span = walk.span();
            const int begin = std::max(span.begin, x0), end = std::min(span.end, x1);
            if (end <= begin) continue;
            double z = row_depth + p.plane.per_x * pixel_centre(span.begin);
            for (int x = span.begin; x < begin; ++x) z += p.plane.per_x;  // the span's own steps up to the tile
            const std::size_t row = std::size_t(y) * std::size_t(o.viewport.width);
            written_here += depth_test_row(out.depth.data() + row, out.polygon.data() + row, begin, end, z, p.plane.per_x,
                                           std::int32_t(index), o, levels);
            tested_here += std::uint64_t(end - begin);
        }
        tested[index] += tested_here, written[index] += written_here;
    }
}

}  // namespace

bool binned_fill(FrameDepth& out, const std::vector<ScreenPolygon>& polygons, const ZBufferOptions& o, PolygonCounts& counts) {
    // An upper bound on the pixel tests: each polygon's rows times its columns. Within the step bound, or not at all.
    Bins bins{(o.viewport.width + tile_w - 1) / tile_w, (o.viewport.height + tile_h - 1) / tile_h, {}};
    bins.polygons.resize(std::size_t(bins.columns) * std::size_t(bins.rows));
    std::uint64_t most = 0;
    for (std::uint32_t i = 0; i < polygons.size(); ++i) {
        const ScreenPolygon& p = polygons[i];
        if (p.status != ScreenStatus::drawn || p.row_end <= p.row_begin) continue;
        const auto [c0, c1] = column_range(p, o.viewport.width);
        most += std::uint64_t(p.row_end - p.row_begin) * std::uint64_t(std::max(0, c1 - c0));
        if (c1 <= c0) continue;
        for (int ty = p.row_begin / tile_h; ty <= (p.row_end - 1) / tile_h; ++ty)
            for (int tx = c0 / tile_w; tx <= (c1 - 1) / tile_w; ++tx) bins.polygons[std::size_t(ty * bins.columns + tx)].push_back(i);
    }
    if (most > o.max_pixel_tests - out.tested) return false;

    const unsigned threads = worker_count();
    std::vector<std::vector<std::uint64_t>> tested(threads, std::vector<std::uint64_t>(polygons.size())), written = tested;
    std::atomic<std::size_t> next{0};
    const double levels = window_depth_levels(o.format);
    const auto work = [&](unsigned t) {
        for (std::size_t k; (k = next.fetch_add(1)) < bins.polygons.size();)
            fill_tile(out, polygons, bins.polygons[k], o, levels, int(k % std::size_t(bins.columns)), int(k / std::size_t(bins.columns)),
                      tested[t].data(), written[t].data());
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& t : pool) t.join();

    counts.tested.assign(polygons.size(), 0), counts.written.assign(polygons.size(), 0);
    for (unsigned t = 0; t < threads; ++t)
        for (std::size_t i = 0; i < polygons.size(); ++i) counts.tested[i] += tested[t][i], counts.written[i] += written[t][i];
    for (std::size_t i = 0; i < polygons.size(); ++i) out.tested += counts.tested[i], out.written += counts.written[i];
    return true;
}

}  // namespace hsr::algo
