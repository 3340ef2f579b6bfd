// SPDX-License-Identifier: MIT
#include "zbuffer/zbuffer_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {
namespace {

std::string num(std::uint64_t v) { return std::to_string(v); }
std::string at(int x, int y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

std::string_view why(ScreenStatus s) {
    switch (s) {
        case ScreenStatus::outside_view: return "nothing of it is inside the view volume";
        case ScreenStatus::zero_area: return "it has no area on the screen (seen edge-on or smaller than a sub-pixel)";
        case ScreenStatus::drawn: return "";
    }
    return "";
}

}  // namespace

std::string describe(const ZBufferEvent& event, DepthFormat format) {
    const std::string nearer = smaller_is_nearer(format) ? "smaller" : "larger";
    return std::visit(
        overloaded{
            [&](const BufferCleared& e) {
                return "Clear: " + std::to_string(e.width) + "×" + std::to_string(e.height) +
                       " pixels take the background colour and the far depth (code " + num(e.far_code) + ", " +
                       std::string(to_string(format)) + ").";
            },
            [](const PolygonFillStarted& e) {
                return "Polygon " + std::to_string(e.id) + ": its depth changes by −a/c = " + format_number(e.per_x, 1.0) +  // depths in [0, 1]
                      
                       " per pixel along x.";
            },
            [](const PolygonSkipped& e) {
                return "Polygon " + std::to_string(e.id) + " is skipped: " + std::string(why(e.why)) + ".";
            },
            [](const SpanStarted& e) {
                return "Scan line " + std::to_string(e.y) + ": pixels " + std::to_string(e.x_begin) + " to " +
                       std::to_string(e.x_end - 1) + " are inside; depth d = " + format_number(e.depth) +
                       " at the first.";
            },
            [&](const PixelTested& e) {
                return "Pixel " + at(e.x, e.y) + ": polygon depth d = " + format_number(e.depth) + " → code " +
                       num(e.incoming) + "; the buffer holds " + num(e.stored) + ".";
            },
            [&](const DepthWritten& e) {
                return "Nearer: pixel " + at(e.x, e.y) + " takes the polygon's colour and depth (" + num(e.old_code) +
                       " → " + num(e.new_code) + ").";
            },
            [&](const DepthTestFailed& e) {
                return "Farther or equal: pixel " + at(e.x, e.y) + " keeps what it has (" + num(e.incoming) +
                       " is not nearer than " + num(e.stored) + "; " + nearer + " stored values are nearer).";
            },
            [](const PolygonFillFinished& e) {
                return "Polygon done: " + num(e.tested) + " pixels tested, " + num(e.written) + " written.";
            },
            [](const FillFinished& e) {
                return "Done: " + num(e.polygons) + " polygons, " + num(e.tested) + " depth tests, " +
                       num(e.written) + " writes.";
            },
            [](const FillStepBoundReached& e) {
                return "Stopped: the step bound of " + num(e.max_pixel_tests) + " depth tests was reached.";
            },
        },
        event);
}

}  // namespace hsr::algo
