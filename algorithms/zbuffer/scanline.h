// SPDX-License-Identifier: MIT
// The scan-line algorithm, as the lectures give it, in its hybrid form with a one-scan-line z-buffer:
//
//   put every non-horizontal edge in the edge table (ET), bucketed by the first scan line it crosses
//   for each scan line y
//     move the ET's edges for y into the active edge table (AET); drop the edges that ended
//     sort the AET by the x where each edge crosses y
//     clear the line's z-buffer; for each edge of the AET, left to right
//       flip its polygon's in/out flag; when the flag goes out, the polygon covers the pixels since it went in:
//       z-test them into the line's z-buffer
//     output the line's colours as spans, then reuse the line buffer for the next line
//
// Polygons are convex (two active edges per line each). Coverage uses the same exact edge bounds as the z-buffer
// fill (screen_polygon.h) and depth the same forward differences, so the image is the z-buffer's, pixel for pixel.
#pragma once

#include "core/steps.h"
#include "zbuffer/scanline_events.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::algo {

struct ScanLineOptions {
    Viewport viewport;
    DepthFormat format = DepthFormat::int24;
    DepthRange range{1, 10};
    bool perspective = true;
    bool tell_crossings = true;  // EdgeEntered, EdgeLeft and EdgeCrossed (off: lines and spans only)
    std::uint64_t max_crossings = std::uint64_t(1) << 36;  // step bound
    Color background{26, 28, 33};
};

// One entry of the edge table.
struct EdgeEntry {
    std::uint32_t polygon;
    ScreenVertex a, b;  // a→b as the polygon walks it (clockwise on screen)
    int first_row, end_row;  // the rows whose centres it spans: [first_row, end_row)
    bool left;               // going up: the polygon is to its right
};

std::vector<EdgeEntry> edge_table(const std::vector<ScreenPolygon>& polygons, Viewport viewport);

// Moves the active edge table (indices into the edge table) to line y: drops the edges that ended, then enters the
// ET's edges that start on it; `next` is the first edge of the ET not yet entered. Returns what it did, as the
// EdgeLeft and EdgeEntered events a machine tells (both scan lines keep their AET this way).
std::vector<ScanLineEvent> advance_active_edges(const std::vector<EdgeEntry>& et, std::vector<std::uint32_t>& aet, std::size_t& next, int y);

// The result's depth holds the code of what each pixel shows (the line buffer's, kept for comparison).
Steps<ScanLineEvent, FrameDepth> scan_line(std::vector<ScreenPolygon> polygons, ScanLineOptions options);

ScanLineOptions scan_line_options(const Scene& scene, Viewport viewport, DepthFormat format);

}  // namespace hsr::algo
