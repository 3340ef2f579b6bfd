// SPDX-License-Identifier: MIT
#include "zbuffer/scanline.h"

#include <algorithm>

#include "core/numeric.h"

namespace hsr::algo {
namespace {

// The first row whose centre is strictly below y (sub-pixels), clamped to the viewport. An edge spans the rows
// whose centres lie in (top, bottom]: the fill rule gives a pixel centre on a vertex row to the polygon above.
int first_row_below(std::int64_t y, Viewport vp) {
    return int(std::clamp<std::int64_t>(ceil_div(y + 1 - subpixels / 2, subpixels), 0, vp.height));
}

// The polygon table: per polygon, its in/out flag and what this line's edges told of it.
struct PolygonEntry {
    bool in = false;
    int left = 0, right = 0;  // pixel bounds from its left and right edges on this line
    double row_depth = 0;     // its depth at x = 0 on the current line, stepped by −b/c per line
    int row = -1;             // the line row_depth is for
};

}  // namespace

std::vector<EdgeEntry> edge_table(const std::vector<ScreenPolygon>& polygons, Viewport vp) {
    std::vector<EdgeEntry> table;
    for (std::uint32_t p = 0; p < polygons.size(); ++p) {
        const ScreenPolygon& poly = polygons[p];
        if (poly.status != ScreenStatus::drawn) continue;
        for (std::size_t i = 0, j = poly.vertices.size() - 1; i < poly.vertices.size(); j = i++) {
            const ScreenVertex &a = poly.vertices[j], &b = poly.vertices[i];
            if (a.y == b.y) continue;  // horizontal boundaries are ignored
            const EdgeEntry e{p, a, b, first_row_below(std::min(a.y, b.y), vp), first_row_below(std::max(a.y, b.y), vp),
                              b.y < a.y};
            if (e.first_row < e.end_row) table.push_back(e);
        }
    }
    std::stable_sort(table.begin(), table.end(), [](const EdgeEntry& a, const EdgeEntry& b) { return a.first_row < b.first_row; });
    return table;
}

std::vector<ScanLineEvent> advance_active_edges(const std::vector<EdgeEntry>& et, std::vector<std::uint32_t>& aet, std::size_t& next, int y) {
    std::vector<ScanLineEvent> moved;
    for (std::size_t k = 0; k < aet.size();)
        if (et[aet[k]].end_row <= y) {
            moved.emplace_back(EdgeLeft{aet[k], et[aet[k]].polygon, y});
            aet.erase(aet.begin() + std::ptrdiff_t(k));
        } else {
            ++k;
        }
    for (; next < et.size() && et[next].first_row <= y; ++next) {
        aet.push_back(std::uint32_t(next));
        moved.emplace_back(EdgeEntered{std::uint32_t(next), et[next].polygon, y, edge_x_at_row(et[next].a, et[next].b, y)});
    }
    return moved;
}

Steps<ScanLineEvent, FrameDepth> scan_line(std::vector<ScreenPolygon> polygons, ScanLineOptions o) {
    const int w = o.viewport.width, h = o.viewport.height;
    FrameDepth out{Image(w, h, o.background), std::vector<std::uint32_t>(std::size_t(w) * std::size_t(h)),
                   std::vector<std::int32_t>(std::size_t(w) * std::size_t(h), -1)};
    const std::vector<EdgeEntry> et = edge_table(polygons, o.viewport);
    std::vector<PolygonEntry> pt(polygons.size());
    std::uint32_t drawn = 0;
    for (const auto& p : polygons) drawn += p.status == ScreenStatus::drawn;
    co_yield EdgeTableBuilt{std::uint32_t(et.size()), drawn};

    const auto far = std::uint32_t(far_code(o.format, o.range));
    std::vector<std::uint32_t> line_depth(static_cast<std::size_t>(w));
    std::vector<std::int32_t> line_owner(static_cast<std::size_t>(w));
    std::vector<std::uint32_t> aet;  // indices into the edge table
    std::vector<std::pair<double, std::uint32_t>> sorted;  // the AET by x on the current line
    std::size_t next = 0;            // the first edge of the ET not yet entered
    std::uint64_t crossings = 0, spans = 0;
    for (int y = 0; y < h; ++y) {
        co_yield ScanLineStarted{y};
        // Update the AET: drop the edges that ended, enter the ET's edges that start on this line
        for (const ScanLineEvent& moved : advance_active_edges(et, aet, next, y))
            if (o.tell_crossings) co_yield moved;
        // Sort the AET by where its edges cross this line
        sorted.clear();
        for (std::uint32_t e : aet) sorted.emplace_back(edge_x_at_row(et[e].a, et[e].b, y), e);
        std::sort(sorted.begin(), sorted.end());
        // Walk it left to right, flipping in/out flags; a polygon going out z-tests its span into the line
        std::fill(line_depth.begin(), line_depth.end(), far);
        std::fill(line_owner.begin(), line_owner.end(), -1);
        for (const auto& [x, e] : sorted) {
            if (++crossings > o.max_crossings) {
                out.bounded = true;
                co_yield ScanStepBoundReached{o.max_crossings};
                co_return out;
            }
            const EdgeEntry& edge = et[e];
            PolygonEntry& p = pt[edge.polygon];
            p.in = !p.in;
            (edge.left ? p.left : p.right) = std::clamp(edge_bound_on_row(edge.a, edge.b, y), 0, w);
            if (o.tell_crossings) co_yield EdgeCrossed{e, edge.polygon, y, x, p.in};
            if (p.in) continue;
            const ScreenPolygon& poly = polygons[edge.polygon];
            // The same depth stepping as the z-buffer fill: from the polygon's first line down, then along x
            if (p.row < 0) p.row = poly.row_begin, p.row_depth = poly.plane.at(0, pixel_centre(poly.row_begin));
            for (; p.row < y; ++p.row) p.row_depth += poly.plane.per_y;
            double z = p.row_depth + poly.plane.per_x * pixel_centre(p.left);
            for (int px = p.left; px < p.right; ++px, z += poly.plane.per_x) {
                const auto code = std::uint32_t(code_of_window_depth(o.format, z, o.range, o.perspective));
                const auto k = std::size_t(px);
                // Nearer wins; on a tie the polygon drawn first by the z-buffer (the lower index) does
                if (code < line_depth[k] || (code == line_depth[k] && line_owner[k] > std::int32_t(edge.polygon)))
                    line_depth[k] = code, line_owner[k] = std::int32_t(edge.polygon);
            }
        }
        // Output the line as spans of one owner each
        for (int x0 = 0; x0 < w;) {
            int x1 = x0 + 1;
            while (x1 < w && line_owner[std::size_t(x1)] == line_owner[std::size_t(x0)]) ++x1;
            const std::int32_t owner = line_owner[std::size_t(x0)];
            const SceneId id = owner < 0 ? 0 : polygons[std::size_t(owner)].id;
            const Color c = owner < 0 ? o.background : polygons[std::size_t(owner)].color;
            for (int x = x0; x < x1; ++x) {
                const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
                out.polygon[k] = owner, out.depth[k] = line_depth[std::size_t(x)], out.image.ids[k] = id;
                out.image.rgb[3 * k] = c.r, out.image.rgb[3 * k + 1] = c.g, out.image.rgb[3 * k + 2] = c.b;
            }
            co_yield SpanColored{y, x0, x1, owner, id};
            ++spans;
            x0 = x1;
        }
    }
    co_yield ScanFinished{std::uint32_t(h), spans};
    co_return out;
}

ScanLineOptions scan_line_options(const Scene& scene, Viewport viewport, DepthFormat format) {
    return {.viewport = viewport,
            .format = format,
            .range = {scene.camera.near, scene.camera.far},
            .perspective = scene.camera.projection == Projection::perspective};
}

}  // namespace hsr::algo
