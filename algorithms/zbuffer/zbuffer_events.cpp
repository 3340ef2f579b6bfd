// SPDX-License-Identifier: MIT
#include "zbuffer/zbuffer_events.h"

#include "core/events.h"
#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {
namespace {

std::string num(std::uint64_t v) { return std::to_string(v); }

// What the z-buffer says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying outside_view{"zbuffer.outside_view", "nothing of it is inside the view volume"};
constexpr Saying zero_area{"zbuffer.zero_area", "it has no area on the screen (seen edge-on or smaller than a sub-pixel)"};
constexpr Saying smaller{"zbuffer.smaller", "smaller"};
constexpr Saying larger{"zbuffer.larger", "larger"};
constexpr Saying cleared{"zbuffer.cleared",
                         "Clear: {width}×{height} pixels take the background colour and the far depth (code {far}, {format})."};
constexpr Saying fill_started{"zbuffer.fill_started", "Polygon {id}: its depth changes by −a/c = {per_x} per pixel along x."};
constexpr Saying skipped{"zbuffer.skipped", "Polygon {id} is skipped: {why}."};
constexpr Saying span{"zbuffer.span", "Scan line {y}: pixels {first} to {last} are inside; depth d = {depth} at the first."};
constexpr Saying tested{"zbuffer.tested", "Pixel ({x}, {y}): polygon depth d = {depth} → code {incoming}; the buffer holds {stored}."};
constexpr Saying written{"zbuffer.written", "Nearer: pixel ({x}, {y}) takes the polygon's colour and depth ({old} → {new})."};
constexpr Saying failed{"zbuffer.failed",
                        "Farther or equal: pixel ({x}, {y}) keeps what it has ({incoming} is not nearer than {stored}; {nearer} "
                        "stored values are nearer)."};
constexpr Saying polygon_done{"zbuffer.polygon_done", "Polygon done: {tested} pixels tested, {written} written."};
constexpr Saying done{"zbuffer.done", "Done: {polygons} polygons, {tested} depth tests, {written} writes."};
constexpr Saying bound{"zbuffer.bound", "Stopped: the step bound of {limit} depth tests was reached."};
constexpr Saying all[] = {outside_view, zero_area, smaller, larger, cleared, fill_started, skipped, span, tested, written, failed,
                          polygon_done, done, bound};
}  // namespace say

const Saying& why(ScreenStatus s) { return s == ScreenStatus::outside_view ? say::outside_view : say::zero_area; }

}  // namespace

std::span<const Saying> zbuffer_sayings() { return say::all; }

Phrase phrase(const ZBufferEvent& event, DepthFormat format) {
    const Saying& nearer = smaller_is_nearer(format) ? say::smaller : say::larger;
    const auto i = [](auto v) { return std::to_string(v); };
    return std::visit(
        overloaded{
            [&](const BufferCleared& e) {
                return Phrase(say::cleared, {{"width", i(e.width)}, {"height", i(e.height)}, {"far", num(e.far_code)},
                                             {"format", std::string(to_string(format))}});
            },
            [&](const PolygonFillStarted& e) {
                return Phrase(say::fill_started, {{"id", i(e.id)}, {"per_x", format_number(e.per_x, 1.0)}});  // depths in [0, 1]
            },
            [&](const PolygonSkipped& e) { return Phrase(say::skipped, {{"id", i(e.id)}}, Terms{{"why", &why(e.why)}}); },
            [&](const SpanStarted& e) {
                return Phrase(say::span, {{"y", i(e.y)}, {"first", i(e.x_begin)}, {"last", i(e.x_end - 1)}, {"depth", format_number(e.depth)}});
            },
            [&](const PixelTested& e) {
                return Phrase(say::tested, {{"x", i(e.x)}, {"y", i(e.y)}, {"depth", format_number(e.depth)}, {"incoming", num(e.incoming)},
                                            {"stored", num(e.stored)}});
            },
            [&](const DepthWritten& e) {
                return Phrase(say::written, {{"x", i(e.x)}, {"y", i(e.y)}, {"old", num(e.old_code)}, {"new", num(e.new_code)}});
            },
            [&](const DepthTestFailed& e) {
                return Phrase(say::failed, {{"x", i(e.x)}, {"y", i(e.y)}, {"incoming", num(e.incoming)}, {"stored", num(e.stored)}},
                              Terms{{"nearer", &nearer}});
            },
            [&](const PolygonFillFinished& e) { return Phrase(say::polygon_done, {{"tested", num(e.tested)}, {"written", num(e.written)}}); },
            [&](const FillFinished& e) {
                return Phrase(say::done, {{"polygons", num(e.polygons)}, {"tested", num(e.tested)}, {"written", num(e.written)}});
            },
            [&](const FillStepBoundReached& e) { return Phrase(say::bound, {{"limit", num(e.max_pixel_tests)}}); },
        },
        event);
}

std::string describe(const ZBufferEvent& event, DepthFormat format) { return phrase(event, format).english(); }

}  // namespace hsr::algo
