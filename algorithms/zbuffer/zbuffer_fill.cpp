// SPDX-License-Identifier: MIT
#include "zbuffer/zbuffer_fill.h"

#include "zbuffer/z_merge.h"
#include "zbuffer/binned_fill.h"
#include "zbuffer/depth_test_row.h"

#include <algorithm>

#include "core/numeric.h"
#include "core/parallel.h"

namespace hsr::algo {
namespace {

// The depth test along one span, with no events: the loop of the machine below when no view asks for pixels. It
// lives outside the coroutine so that its variables stay in registers, not in the coroutine's frame. Returns false
// when the step bound stopped it (at the same pixel the machine's own loop would stop).
bool fill_span(FrameDepth& out, const ScreenPolygon& p, std::int32_t index, int y, Span span, double z, const ZBufferOptions& o,
               double levels, std::uint64_t& tested, std::uint64_t& written) {
    // the pixels the step bound still allows: the loop then needs no test of its own
    const std::uint64_t left = o.max_pixel_tests - out.tested;
    const int end = std::uint64_t(span.end - span.begin) > left ? span.begin + int(left) : span.end;
    const std::size_t row = std::size_t(y) * std::size_t(o.viewport.width);
    const std::uint64_t wrote = depth_test_row(out.depth.data() + row, out.polygon.data() + row, span.begin, end, z, p.plane.per_x, index, o, levels);
    const auto n = std::uint64_t(end - span.begin);
    tested += n, out.tested += n, written += wrote, out.written += wrote;
    return end == span.end;
}

// The image from the polygon buffer: each pixel the colour and id of the polygon it holds. (From a table of just
// those, small enough to stay in the cache, and in chunks of rows on every core for large frames.)
void resolve_image(FrameDepth& out, const std::vector<ScreenPolygon>& polygons) {
    struct Look {
        SceneId id;
        Color color;
    };
    std::vector<Look> looks(polygons.size());
    for (std::size_t i = 0; i < polygons.size(); ++i) looks[i] = {polygons[i].id, polygons[i].color};
    for_each_chunk(out.polygon.size(), std::size_t(1) << 16, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
            if (out.polygon[k] < 0) continue;
            const Look& p = looks[std::size_t(out.polygon[k])];
            out.image.ids[k] = p.id;
            out.image.rgb[3 * k] = p.color.r, out.image.rgb[3 * k + 1] = p.color.g, out.image.rgb[3 * k + 2] = p.color.b;
        }
    });
}

}  // namespace

Steps<ZBufferEvent, FrameDepth> zbuffer_fill(std::vector<ScreenPolygon> polygons, ZBufferOptions o) {
    const bool per_pixel = o.detail == EventDetail::pixel;
    const int w = o.viewport.width, h = o.viewport.height;
    const double levels = window_depth_levels(o.format);
    // Initialise: every depth at the far plane, every colour the background
    FrameDepth out = cleared_buffers(o);
    co_yield BufferCleared{w, h, far_code(o.format, o.range)};

    // Drained with polygon-level events: the same fill tile by tile on every core (binned_fill.h); the loop below
    // then only tells each polygon's counts
    PolygonCounts counts;
    const bool filled = o.detail == EventDetail::polygon && binned_fill(out, polygons, o, counts);

    for (std::uint32_t index = 0; index < polygons.size(); ++index) {
        const ScreenPolygon& p = polygons[index];
        if (p.status != ScreenStatus::drawn) {
            co_yield PolygonSkipped{index, p.id, p.status};
            continue;
        }
        co_yield PolygonFillStarted{index, p.id, p.plane.per_x};
        if (filled) {
            co_yield PolygonFillFinished{index, counts.tested[index], counts.written[index]};
            continue;
        }
        std::uint64_t tested = 0, written = 0;
        // For each scan line the polygon covers: its span, and the depth at the span's first pixel
        double row_depth = p.plane.at(0, pixel_centre(p.row_begin));  // d at x = 0, stepped by −b/c per row
        for (int y = p.row_begin; y < p.row_end; ++y, row_depth += p.plane.per_y) {
            const Span span = span_on_row(p, y, o.viewport);
            if (span.end <= span.begin) continue;
            double z = row_depth + p.plane.per_x * pixel_centre(span.begin);
            if (o.detail != EventDetail::polygon) co_yield SpanStarted{index, y, span.begin, span.end, z};
            if (!per_pixel) {
                if (!fill_span(out, p, std::int32_t(index), y, span, z, o, levels, tested, written)) {
                    out.bounded = true;
                    co_yield FillStepBoundReached{o.max_pixel_tests};
                    resolve_image(out, polygons);
                    co_return out;
                }
                continue;
            }
            for (int x = span.begin; x < span.end; ++x, z += p.plane.per_x) {
                if (out.tested == o.max_pixel_tests) {
                    out.bounded = true;
                    co_yield FillStepBoundReached{o.max_pixel_tests};
                    resolve_image(out, polygons);
                    co_return out;
                }
                const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
                const std::uint64_t incoming = depth_code(z, o, levels);
                const std::uint64_t stored = out.depth[k];
                ++tested, ++out.tested;
                if (per_pixel) co_yield PixelTested{x, y, z, incoming, stored, incoming < stored};
                // The depth test: nearer than what the buffer holds?
                if (incoming < stored) {
                    if (per_pixel) co_yield DepthWritten{x, y, index, out.polygon[k], stored, incoming};
                    out.depth[k] = std::uint32_t(incoming);
                    out.polygon[k] = std::int32_t(index);
                    ++written, ++out.written;
                } else if (per_pixel) {
                    co_yield DepthTestFailed{x, y, incoming, stored};
                }
            }
        }
        co_yield PolygonFillFinished{index, tested, written};
    }
    co_yield FillFinished{polygons.size(), out.tested, out.written};
    resolve_image(out, polygons);
    co_return out;
}

FrameDepth cleared_buffers(const ZBufferOptions& o) {
    FrameDepth out{Image(o.viewport.width, o.viewport.height, o.background), {}, {}};
    out.depth.assign(std::size_t(o.viewport.width) * std::size_t(o.viewport.height), std::uint32_t(far_code(o.format, o.range)));
    out.polygon.assign(out.depth.size(), -1);
    return out;
}

std::uint64_t fill_polygon(FrameDepth& out, const ScreenPolygon& p, std::int32_t index, const ZBufferOptions& o) {
    if (p.status != ScreenStatus::drawn) return 0;
    std::uint64_t written = 0;
    double row_depth = p.plane.at(0, pixel_centre(p.row_begin));
    for (int y = p.row_begin; y < p.row_end; ++y, row_depth += p.plane.per_y) {
        const Span span = span_on_row(p, y, o.viewport);
        double z = row_depth + p.plane.per_x * pixel_centre(span.begin);
        for (int x = span.begin; x < span.end; ++x, z += p.plane.per_x) {
            const std::size_t k = std::size_t(y) * std::size_t(o.viewport.width) + std::size_t(x);
            const std::uint64_t incoming = code_of_window_depth(o.format, z, o.range, o.perspective);
            ++out.tested;
            if (incoming >= out.depth[k]) continue;
            out.depth[k] = std::uint32_t(incoming), out.polygon[k] = index, out.image.ids[k] = p.id;
            out.image.rgb[3 * k] = p.color.r, out.image.rgb[3 * k + 1] = p.color.g, out.image.rgb[3 * k + 2] = p.color.b;
            ++written, ++out.written;
        }
    }
    return written;
}

ZBufferOptions zbuffer_options(const Scene& scene, Viewport viewport, DepthFormat format, EventDetail detail) {
    return {.viewport = viewport,
            .format = format,
            .range = {scene.camera.near, scene.camera.far},
            .perspective = scene.camera.projection == Projection::perspective,
            .detail = detail};
}

FrameDepth z_merge(const FrameDepth& a, const FrameDepth& b) { return z_merge_steps(a, b).run_to_end(); }

}  // namespace hsr::algo
