// SPDX-License-Identifier: MIT
// span_on_row's spans for one polygon, row after row, without a division per row: the edges' DDA.
//
// Each edge bounds row j's span by a floor: first pixel = −⌊M/D⌋ for a left edge, one past the last = ⌊M/D⌋ + 1
// for a right edge, where D = 256·|dy| and M is the edge function's numerator at the row's centre line. Going down
// one row adds the same 256·dx to M, so the quotient and remainder are stepped as Bresenham steps a line: add the
// step's quotient and remainder, carry one when the remainder reaches D. Exact integer arithmetic, so the spans are
// span_on_row's, bit for bit (tests/core/span_walker_test.cpp holds it to that).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "raster/screen_polygon.h"

namespace hsr::algo {

class SpanWalker {
public:
    // Starts at `row` (within [p.row_begin, p.row_end) for a non-empty answer).
    SpanWalker(const ScreenPolygon& p, int row, Viewport viewport);

    // The current row's span, as span_on_row(p, row(), viewport).
    Span span() const {
        if (direct_) return direct_span();
        if (row_ < polygon_->row_begin || row_ >= polygon_->row_end || status_ != ScreenStatus::drawn) return {0, 0};
        for (std::size_t i = 0; i < horizontal_count_; ++i)  // outside a horizontal edge: nothing on this row
            if (horizontal_[i].dx * (row_centre(row_) - horizontal_[i].a_y) < horizontal_[i].threshold) return {0, 0};
        Span s{0, viewport_.width};
        for (std::size_t i = 0; i < left_count_; ++i) s.begin = std::max(s.begin, int(std::clamp<std::int64_t>(-left_[i].quotient, -1, 1 << 30)));
        for (std::size_t i = 0; i < right_count_; ++i) s.end = std::min(s.end, int(std::clamp<std::int64_t>(right_[i].quotient + 1, -1, 1 << 30)));
        return s;
    }
    int row() const { return row_; }
    void next_row() {
        ++row_;
        for (std::size_t i = 0; i < left_count_; ++i) left_[i].step();
        for (std::size_t i = 0; i < right_count_; ++i) right_[i].step();
    }

private:
    Span direct_span() const;  // span_on_row's own answer, out of line so that span() stays small enough to inline
    struct Edge {  // ⌊M/D⌋ on the current row, kept with its remainder
        std::int64_t quotient, remainder, divisor, quotient_step, remainder_step;
        void step() {
            quotient += quotient_step, remainder += remainder_step;
            if (remainder >= divisor) remainder -= divisor, ++quotient;
        }
    };
    struct Horizontal {  // outside when dx·(row centre − a.y) < threshold
        std::int64_t dx, a_y, threshold;
    };
    static constexpr std::size_t most_edges = 12;  // triangles clipped by the six planes have at most 9

    const ScreenPolygon* polygon_;
    Viewport viewport_;
    int row_;
    ScreenStatus status_;
    bool direct_;  // more edges than room: each row asks span_on_row itself
    std::size_t left_count_ = 0, right_count_ = 0, horizontal_count_ = 0;
    std::array<Edge, most_edges> left_, right_;  // filled up to their counts
    std::array<Horizontal, most_edges> horizontal_;
};

}  // namespace hsr::algo
