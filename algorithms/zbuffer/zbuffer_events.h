// SPDX-License-Identifier: MIT
// What the z-buffer fill tells as it runs. Pixels are (x, y) with y down; depths are the format's codes (they grow
// with distance in every format, see depth_format.h) and the window depth d they came from.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>

#include "core/phrase.h"
#include "scene/scene.h"
#include "zbuffer/depth_format.h"
#include "raster/screen_polygon.h"

namespace hsr::algo {

// How much a fill tells: every pixel, each span, or each polygon only (a full-size run need not record millions).
enum class EventDetail : std::uint8_t { polygon, span, pixel };

struct BufferCleared {
    static constexpr std::string_view kind = "BufferCleared";
    int width, height;
    std::uint64_t far_code;  // every depth starts here; every colour is the background
    bool operator==(const BufferCleared&) const = default;
};
struct PolygonFillStarted {
    static constexpr std::string_view kind = "PolygonFillStarted";
    std::uint32_t index;  // into the projected polygons
    SceneId id;
    double per_x;  // −a/c: the forward difference of depth along x
    bool operator==(const PolygonFillStarted&) const = default;
};
struct PolygonSkipped {
    static constexpr std::string_view kind = "PolygonSkipped";
    std::uint32_t index;
    SceneId id;
    ScreenStatus why;  // outside the view volume, or no area left on the screen
    bool operator==(const PolygonSkipped&) const = default;
};
struct SpanStarted {
    static constexpr std::string_view kind = "SpanStarted";
    std::uint32_t index;
    int y, x_begin, x_end;  // pixels [x_begin, x_end) of row y
    double depth;           // d at the first pixel's centre
    bool operator==(const SpanStarted&) const = default;
};
struct PixelTested {
    static constexpr std::string_view kind = "PixelTested";
    int x, y;
    double depth;             // the polygon's d here
    std::uint64_t incoming;   // its code
    std::uint64_t stored;     // the code in the buffer
    bool passes;              // the depth test's outcome: incoming nearer than stored (DepthWritten follows)
    bool operator==(const PixelTested&) const = default;
};
struct DepthWritten {
    static constexpr std::string_view kind = "DepthWritten";
    int x, y;
    std::uint32_t index;        // the polygon now seen here
    std::int32_t old_index;     // the one seen before, −1 for background: a view steps back in O(1)
    std::uint64_t old_code, new_code;
    bool operator==(const DepthWritten&) const = default;
};
struct DepthTestFailed {
    static constexpr std::string_view kind = "DepthTestFailed";
    int x, y;
    std::uint64_t incoming, stored;
    bool operator==(const DepthTestFailed&) const = default;
};
struct PolygonFillFinished {
    static constexpr std::string_view kind = "PolygonFillFinished";
    std::uint32_t index;
    std::uint64_t tested, written;
    bool operator==(const PolygonFillFinished&) const = default;
};
struct FillFinished {
    static constexpr std::string_view kind = "FillFinished";
    std::uint64_t polygons, tested, written;
    bool operator==(const FillFinished&) const = default;
};
struct FillStepBoundReached {
    static constexpr std::string_view kind = "FillStepBoundReached";
    std::uint64_t max_pixel_tests;
    bool operator==(const FillStepBoundReached&) const = default;
};

using ZBufferEvent = std::variant<BufferCleared, PolygonFillStarted, PolygonSkipped, SpanStarted, PixelTested,
                                  DepthWritten, DepthTestFailed, PolygonFillFinished, FillFinished, FillStepBoundReached>;

// What an event says, as a template with named values (core/phrase.h), and in English; `format` says how to read
// the depth codes.
Phrase phrase(const ZBufferEvent& e, DepthFormat format);
std::string describe(const ZBufferEvent& e, DepthFormat format);
std::span<const Saying> zbuffer_sayings();  // every template the z-buffer says

}  // namespace hsr::algo
