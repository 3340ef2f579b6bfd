// SPDX-License-Identifier: MIT
#include "state/zbuffer_view.h"

#include "core/overloaded.h"

namespace hsr::viz {

using namespace hsr::algo;

ZView initial_view(std::shared_ptr<const std::vector<ScreenPolygon>> polygons, const ZBufferOptions& o) {
    ZView v;
    v.viewport = o.viewport;
    v.format = o.format;
    v.range = o.range;
    v.polygons = std::move(polygons);
    v.far_code = far_code(o.format, o.range);
    const auto n = std::size_t(o.viewport.width) * std::size_t(o.viewport.height);
    v.owner.assign(n, -1);
    v.depth.assign(n, v.far_code);
    return v;
}

void reduce(ZView& v, const ZBufferEvent& event) {
    const auto at = [&](int x, int y) { return std::size_t(y) * std::size_t(v.viewport.width) + std::size_t(x); };
    std::visit(overloaded{
                   [&](const BufferCleared& e) {
                       std::fill(v.owner.begin(), v.owner.end(), -1);
                       std::fill(v.depth.begin(), v.depth.end(), e.far_code);
                   },
                   [&](const PolygonFillStarted& e) {
                       v.polygon = int(e.index);
                       v.span_y = -1, v.pixel_x = v.pixel_y = -1, v.outcome = PixelOutcome::none;
                   },
                   [&](const PolygonSkipped& e) {
                       v.polygon = int(e.index);
                       v.span_y = -1, v.pixel_x = v.pixel_y = -1, v.outcome = PixelOutcome::none;
                   },
                   [&](const SpanStarted& e) {
                       v.span_y = e.y, v.span_begin = e.x_begin, v.span_end = e.x_end;
                       v.pixel_x = v.pixel_y = -1, v.outcome = PixelOutcome::none;
                   },
                   [&](const PixelTested& e) {
                       v.pixel_x = e.x, v.pixel_y = e.y, v.pixel_depth = e.depth;
                       v.incoming = e.incoming, v.stored = e.stored, v.outcome = PixelOutcome::tested;
                       ++v.tested;
                   },
                   [&](const DepthWritten& e) {
                       v.owner[at(e.x, e.y)] = std::int32_t(e.index);
                       v.depth[at(e.x, e.y)] = e.new_code;
                       v.outcome = PixelOutcome::written;
                       ++v.written;
                   },
                   [&](const DepthTestFailed&) { v.outcome = PixelOutcome::failed; },
                   [&](const PolygonFillFinished&) { v.span_y = -1, v.pixel_x = v.pixel_y = -1; },
                   [&](const FillFinished&) {
                       v.done = true, v.polygon = -1, v.span_y = -1, v.pixel_x = v.pixel_y = -1;
                   },
                   [&](const FillStepBoundReached&) { v.bounded = true; },
               },
               event);
}

std::size_t approx_bytes(const ZView& v) {
    return sizeof(ZView) + v.owner.capacity() * sizeof(std::int32_t) + v.depth.capacity() * sizeof(std::uint64_t);
}

}  // namespace hsr::viz
