// Drawing a classroom-sized image as a grid of fat pixels (z-buffer and scan-line lessons), with polygon outlines
// in the same pixel coordinates.
#pragma once

#include <vector>

#include <imgui.h>

#include "raster/screen_polygon.h"

namespace hsr::viz {

inline ImU32 rgb(algo::Color c, float alpha = 1) {
    return ImGui::GetColorU32(ImVec4(c.r / 255.f, c.g / 255.f, c.b / 255.f, alpha));
}

// One buffer as width × height cells of `cell` points from `origin`; `fill(x, y)` gives each pixel's colour.
template <class Fill>
void pixel_grid(ImDrawList* d, ImVec2 origin, float cell, algo::Viewport vp, Fill fill) {
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x)
            d->AddRectFilled(ImVec2(origin.x + float(x) * cell, origin.y + float(y) * cell),
                             ImVec2(origin.x + float(x + 1) * cell - 1, origin.y + float(y + 1) * cell - 1), fill(x, y));
}

inline ImVec2 on_grid(ImVec2 origin, float cell, const algo::ScreenVertex& v) {
    return {origin.x + float(v.x) / float(algo::subpixels) * cell, origin.y + float(v.y) / float(algo::subpixels) * cell};
}

inline void outline(ImDrawList* d, ImVec2 origin, float cell, const algo::ScreenPolygon& p, ImU32 colour, float thickness) {
    if (p.status != algo::ScreenStatus::drawn) return;
    std::vector<ImVec2> points;
    for (const auto& q : p.vertices) points.push_back(on_grid(origin, cell, q));
    d->AddPolyline(points.data(), int(points.size()), colour, ImDrawFlags_Closed, thickness);
}

}  // namespace hsr::viz
