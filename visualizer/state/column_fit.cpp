// SPDX-License-Identifier: MIT
#include "state/column_fit.h"

#include <algorithm>
#include <numeric>

namespace hsr::viz {
namespace {

// Max–min fair shares of `room` for asks `want` (the smallest met in full, the others splitting what remains).
template <std::size_t N>
std::array<float, N> fair(const std::array<float, N>& want, float room) {
    std::array<std::size_t, N> order{};
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return want[a] < want[b]; });
    std::array<float, N> got{};
    auto left = std::count_if(want.begin(), want.end(), [](float w) { return w > 0; });
    for (std::size_t i : order) {
        if (want[i] <= 0) continue;
        got[i] = std::max(0.0f, std::min(want[i], room / float(left--)));
        room -= got[i];
    }
    return got;
}

}  // namespace

std::array<float, box_count> ColumnFit::share(const std::array<BoxAsk, box_count>& asks, float height, bool result_first) {
    std::array<float, box_count> h{};
    const auto q = std::size_t(Box::question);
    h[q] = std::min(asks[q].full, height * 0.6f);  // a practice exercise with five long choices needs more than half
    float room = height - h[q];

    // then what the lesson box must show (the chapter's text is the lesson; up to half of what is left)
    const auto lesson = std::size_t(Box::lesson);
    std::array<float, box_count - 1> need{}, extra{};
    for (std::size_t i = 0; i < need.size(); ++i)
        need[i] = std::min(h[q] > 0 && asks[i].least > 0 ? asks[i].least : asks[i].need, asks[i].full);
    h[lesson] = std::min(need[lesson], room / 2);
    room -= h[lesson];
    need[lesson] = 0;
    // at the lesson's end, what it built (the state box: the tree, the matrix, the tables) in full, up to all that is
    // left but the narration's last sentence (at least 70 % of it), then that sentence: the class reads the result;
    // the pseudocode keeps what is left (none: the panel is not drawn, see ColumnFit::keep)
    const auto state = std::size_t(Box::state), narration = std::size_t(Box::narration);
    if (result_first) {
        h[state] = std::min(asks[state].full, std::max(room * 0.7f, room - need[narration]));
        room -= h[state];
        need[state] = 0;
        h[narration] = std::min(need[narration], room);
        room -= h[narration];
        need[narration] = 0;
    }
    // and at the end the pseudocode comes last of all: the lesson box's conclusion is read before it
    const auto pseudocode = std::size_t(Box::pseudocode);
    if (result_first) need[pseudocode] = 0;
    auto first = fair(need, room);
    first[lesson] = h[lesson];
    room += h[lesson];
    if (result_first) first[state] = h[state], first[narration] = h[narration], room += h[state] + h[narration];
    for (std::size_t i = 0; i < need.size(); ++i) {
        h[i] = first[i];
        room -= first[i];
        extra[i] = asks[i].full - first[i];
    }
    if (result_first) {  // the conclusion in the lesson box before the narration's earlier sentences
        extra[pseudocode] = 0;
        const float more = std::clamp(extra[lesson], 0.0f, std::max(room, 0.0f));
        h[lesson] += more;
        room -= more;
        extra[lesson] = 0;
    }
    if (h[q] > 0) {  // a question is open: it asks about what the state box holds, which comes before more narration
        const float more = std::clamp(extra[state], 0.0f, std::max(room, 0.0f));
        h[state] += more;
        room -= more;
        extra[state] = 0;
    }
    const auto second = fair(extra, room);
    for (std::size_t i = 0; i < extra.size(); ++i) {
        h[i] += second[i];
        room -= second[i];
    }
    if (result_first) {  // only when the room left holds what it must show: a sliver of it would be left blank
        const float p = room >= std::min(asks[pseudocode].need, asks[pseudocode].full) ? std::clamp(asks[pseudocode].full - h[pseudocode], 0.0f, room) : 0.0f;
        h[pseudocode] += p;
        room -= p;
    }
    const auto to = asks[std::size_t(Box::state)].full > 0 ? Box::state : Box::narration;
    if (room > 0 && asks[std::size_t(to)].full > 0) h[std::size_t(to)] += room;
    return h;
}

void ColumnFit::arrange(float height, const std::string& lesson, bool result_first) {
    if (lesson != lesson_) {
        lesson_ = lesson;
        // the shares the column had before it was fitted (1280×800: 150, 262, 170, 122): until the boxes are drawn
        const float share[] = {150, 262, 170, 122, 0};
        for (std::size_t i = 0; i < box_count; ++i) asks_[i] = {height * share[i] / 704, height * share[i] / 704};
        drawn_ = {true, true, true, true, false};
        measured_ = {};
    }
    for (std::size_t i = 0; i < box_count; ++i)
        if (!drawn_[i]) asks_[i] = {}, measured_[i] = false;  // not drawn last frame: no room kept for it
    drawn_ = {};
    // at the lesson's end the state and narration boxes show what they hold now, not the most they held on the way
    // (a pair's four lines of figures gone): the room they no longer need goes to the chapter's conclusion
    auto asks = asks_;
    if (result_first)
        for (const Box b : {Box::state, Box::narration})
            if (measured_[std::size_t(b)]) asks[std::size_t(b)] = last_[std::size_t(b)];
    const auto h = share(asks, height, result_first);
    float y = 0;
    moved_ = false;
    for (std::size_t i = 0; i < box_count; ++i) {
        moved_ = moved_ || slots_[i].y != y || slots_[i].h != h[i];
        slots_[i] = {y, h[i]};
        y += h[i];
    }
}

void ColumnFit::keep(Box b) { drawn_[std::size_t(b)] = true; }

void ColumnFit::asked(Box b, BoxAsk ask) {
    if (slots_[std::size_t(b)].h <= 0 && ask.full > 0) moved_ = true;  // drawn out of sight: not settled until placed
    last_[std::size_t(b)] = ask;
    BoxAsk& a = asks_[std::size_t(b)];
    bool& seen = measured_[std::size_t(b)];
    // the boxes that change at every step keep their largest size (a default was only a guess); the lesson text
    // changes with the chapter, the pseudocode never, the question once
    const bool steady = b == Box::state || b == Box::narration;
    a = seen && steady ? BoxAsk{std::max(a.need, ask.need), std::max(a.full, ask.full), std::max(a.least, ask.least)} : ask;
    seen = drawn_[std::size_t(b)] = true;
}

}  // namespace hsr::viz
