// SPDX-License-Identifier: MIT
#include "state/scanline_view.h"

#include <algorithm>

#include "core/overloaded.h"

namespace hsr::viz {

using namespace hsr::algo;

ScanView initial_view(std::shared_ptr<const std::vector<ScreenPolygon>> polygons, Viewport viewport) {
    ScanView v;
    v.viewport = viewport;
    v.edges = std::make_shared<const std::vector<EdgeEntry>>(edge_table(*polygons, viewport));
    v.in.assign(polygons->size(), false);
    v.polygons = std::move(polygons);
    v.owner.assign(std::size_t(viewport.width) * std::size_t(viewport.height), -1);
    return v;
}

void reduce(ScanView& v, const ScanLineEvent& event) {
    std::visit(overloaded{
                   [&](const EdgeTableBuilt&) { v.table_built = true; },
                   [&](const ScanLineStarted& e) {
                       v.line = e.y;
                       v.crossings.clear();
                       v.marks.clear();
                       std::fill(v.in.begin(), v.in.end(), false);
                   },
                   [&](const EdgeEntered& e) { v.active.push_back(e.edge); },
                   [&](const EdgeLeft& e) { std::erase(v.active, e.edge); },
                   [&](const EdgeCrossed& e) {
                       v.crossings.push_back({e.edge, e.x, e.entering});
                       v.in[e.polygon] = e.entering;
                   },
                   [&](const DepthsCompared& e) {
                       v.marks.push_back({e.x, e.nearest, false});
                       ++v.compared;
                   },
                   [&](const PiercingFound& e) {
                       v.marks.push_back({e.x, e.now, true});
                       ++v.piercings;
                   },
                   [&](const SpanColored& e) {
                       for (int x = e.x_begin; x < e.x_end; ++x)
                           v.owner[std::size_t(e.y) * std::size_t(v.viewport.width) + std::size_t(x)] = e.polygon;
                       ++v.spans;
                   },
                   [&](const ScanFinished&) { v.done = true, v.line = -1, v.crossings.clear(), v.marks.clear(); },
                   [&](const ScanStepBoundReached&) { v.bounded = true; },
               },
               event);
}

std::size_t approx_bytes(const ScanView& v) {
    return sizeof(ScanView) + v.owner.capacity() * sizeof(std::int32_t) + v.active.capacity() * sizeof(std::uint32_t) +
           v.crossings.capacity() * sizeof(Crossing) + v.marks.capacity() * sizeof(DepthMark) + v.in.capacity() / 8;
}

}  // namespace hsr::viz
