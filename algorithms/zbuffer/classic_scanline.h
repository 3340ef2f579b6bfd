// SPDX-License-Identifier: MIT
// The classic scan-line algorithm, as the Brown notes give it: no z-buffer at all, depth compared only where spans
// begin.
//
//   ET entry: x, y_max, Δx, polygon ID      (every non-horizontal edge, by the first scan line it crosses)
//   PT entry: ID, plane equation, colour, in/out flag
//   for each horizontal scan line y
//     AET += the ET's edges starting at y; AET −= the edges that ended; sort the AET by increasing x
//     for each intersection on the scan line, left to right
//       a left edge: its polygon is entering (flag in); a right edge: leaving (flag out)
//       no polygon in: background up to the next intersection
//       else: the nearest polygon in (their plane equations, at this x) is visible;
//             use its colour up to the next intersection
//
// The notes' form assumes polygons that do not pierce each other: then the nearest polygon at a span's start stays
// the nearest up to the next intersection. Two polygons in that pierce each other swap places between
// intersections, so the machine looks for that too (two planes along a line: where their depth difference changes
// sign) and puts an extra intersection there. `find_piercings = false` leaves it out and paints what the notes'
// form paints.
//
// Coverage uses the same exact edge bounds as the z-buffer fill (screen_polygon.h): each intersection is the first
// pixel whose centre is inside a left edge, or one past the last inside a right edge.
#pragma once

#include "zbuffer/scanline.h"

namespace hsr::algo {

// An edge of the edge table in the notes' fields.
struct EdgeFields {
    double x;    // where it crosses its first scan line's centre, pixels
    int y_max;   // the last scan line it crosses
    double dx;   // Δx: what x changes by from one scan line to the next
};
EdgeFields edge_fields(const EdgeEntry& e);

struct ClassicScanLineOptions {
    ScanLineOptions line;        // viewport, depth format (for the codes kept), step bound, …
    bool find_piercings = true;  // the extra intersection where two polygons in pierce each other
};

// The result's depth holds the code of each pixel's window depth in the options' format (for comparison).
Steps<ScanLineEvent, FrameDepth> classic_scan_line(std::vector<ScreenPolygon> polygons, ClassicScanLineOptions options);

}  // namespace hsr::algo
