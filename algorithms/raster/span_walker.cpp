// SPDX-License-Identifier: MIT
#include "raster/span_walker.h"

#include "core/numeric.h"

namespace hsr::algo {

// The arrays are left unset past their counts: the walker is made once per polygon and band of rows.
// NOLINTNEXTLINE(cppcoreguidelines-pro-type-member-init)
SpanWalker::SpanWalker(const ScreenPolygon& p, int row, Viewport viewport)
    : polygon_(&p), viewport_(viewport), row_(row), status_(p.status), direct_(p.vertices.size() > most_edges) {
    if (direct_) return;
    const std::int64_t centre = row_centre(row);
    for (std::size_t i = 0, j = p.vertices.size() - 1; i < p.vertices.size(); j = i++) {
        const ScreenVertex &a = p.vertices[j], &b = p.vertices[i];
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
        const std::int64_t t = fill_rule_threshold(dx, dy);
        if (dy == 0) {
            horizontal_[horizontal_count_++] = {dx, a.y, t};
            continue;
        }
        // E at the pixel centre p.x of this row is k − dy·p.x; M = k − t − 128·dy is what both bounds divide
        const std::int64_t k = dx * (centre - a.y) + dy * a.x;
        const std::int64_t m = k - t - subpixels / 2 * dy, step = subpixels * dx, divisor = subpixels * (dy < 0 ? -dy : dy);
        const std::int64_t quotient = floor_div(m, divisor), quotient_step = floor_div(step, divisor);
        (dy < 0 ? left_[left_count_++] : right_[right_count_++]) =
            {quotient, m - quotient * divisor, divisor, quotient_step, step - quotient_step * divisor};
    }
}

Span SpanWalker::direct_span() const { return span_on_row(*polygon_, row_, viewport_); }

}  // namespace hsr::algo
