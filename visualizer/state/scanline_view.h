// SPDX-License-Identifier: MIT
// What a scan-line lesson shows: the edge table, the active edge table on the current line with each edge
// crossed so far (and the in/out flags it flipped), and the image filled line by line.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "zbuffer/classic_scanline.h"
#include "zbuffer/scanline.h"

namespace hsr::viz {

struct Crossing {
    std::uint32_t edge;
    double x;
    bool entering;
};

// Classic scan line: where, on the current line, the planes of the polygons in were compared, or two of them were
// found to pierce each other (the extra intersection).
struct DepthMark {
    double x;
    std::int32_t nearest;  // the polygon seen from there on
    bool piercing;
};

struct ScanView {
    algo::Viewport viewport;
    std::shared_ptr<const std::vector<algo::ScreenPolygon>> polygons;  // never changed
    std::shared_ptr<const std::vector<algo::EdgeEntry>> edges;         // the edge table, never changed
    std::vector<std::int32_t> owner;     // polygon index per pixel, −1 background (lines done so far)
    int line = -1;                       // the current scan line
    std::vector<std::uint32_t> active;   // the active edge table, as entered
    std::vector<Crossing> crossings;     // this line's, left to right
    std::vector<bool> in;                // per polygon: its in/out flag
    bool classic = false;                // the classic machine (no line z-buffer)
    std::vector<DepthMark> marks;        // classic: this line's depth comparisons and piercings
    std::uint64_t compared = 0, piercings = 0;  // classic: so far
    std::uint64_t spans = 0;
    bool table_built = false;            // the edge table has been built (its rows are shown from then on)
    bool done = false, bounded = false;
};

ScanView initial_view(std::shared_ptr<const std::vector<algo::ScreenPolygon>> polygons, algo::Viewport viewport);
void reduce(ScanView& view, const algo::ScanLineEvent& event);
std::size_t approx_bytes(const ScanView& view);

}  // namespace hsr::viz
