// SPDX-License-Identifier: MIT
// Labels of a view never cover one another while there is room around their points, and the first label given
// keeps the spot a reader expects (to the upper right of its point).
#include "catch.h"
#include "state/label_placement.h"

using namespace hsr::viz;

namespace {

bool overlap(const LabelBox& a, const Placed& pa, const LabelBox& b, const Placed& pb) {
    return pa.left < pb.left + b.width && pb.left < pa.left + a.width && pa.top < pb.top + b.height &&
           pb.top < pa.top + a.height;
}

}  // namespace

TEST_CASE("a lone label sits to the upper right of its point", "[labels]") {
    const auto p = place_labels({{100, 50, 30, 12}});
    REQUIRE(p.size() == 1);
    CHECK(p[0].left > 100);
    CHECK(p[0].top + 12 <= 50);
}

TEST_CASE("labels of points close together do not overlap, and the first keeps its spot", "[labels]") {
    // four face numbers whose points are a few pixels apart: the picture of lesson 06 seen edge-on
    const std::vector<LabelBox> boxes{{200, 100, 24, 14}, {203, 102, 24, 14}, {198, 99, 24, 14}, {201, 104, 24, 14}};
    const auto p = place_labels(boxes);
    REQUIRE(p.size() == boxes.size());
    CHECK(p[0].left == place_labels({boxes[0]})[0].left);
    CHECK(p[0].top == place_labels({boxes[0]})[0].top);
    for (size_t i = 0; i < boxes.size(); ++i)
        for (size_t j = i + 1; j < boxes.size(); ++j) {
            INFO("labels " << i << " and " << j);
            CHECK_FALSE(overlap(boxes[i], p[i], boxes[j], p[j]));
        }
}

TEST_CASE("labels far apart each keep the usual spot", "[labels]") {
    const auto p = place_labels({{10, 100, 20, 12}, {300, 100, 20, 12}});
    CHECK(p[0].left == p[1].left - 290);
    CHECK(p[0].top == p[1].top);
}

TEST_CASE("in a crowd, labels with no free spot are left out after the first few, which are always shown", "[labels]") {
    // 60 polygons' labels at one point (a city of thousands seen from afar): twenty spots around it are free (four
    // corners, five lines up and down)
    const std::vector<LabelBox> crowd(60, LabelBox{400, 300, 30, 14});
    const auto p = place_labels(crowd, 16);
    REQUIRE(p.size() == crowd.size());
    for (std::size_t k = 0; k < 20; ++k) CHECK(p[k].shown);  // the free spots, then the always shown on their own
    for (std::size_t k = 20; k < crowd.size(); ++k) CHECK_FALSE(p[k].shown);
    // those shown on a free spot never overlap one another
    for (std::size_t i = 0; i < 20; ++i)
        for (std::size_t j = i + 1; j < 20; ++j) CHECK_FALSE(overlap(crowd[i], p[i], crowd[j], p[j]));
    // with room around every point, nobody is left out
    std::vector<LabelBox> spread;
    for (int k = 0; k < 60; ++k) spread.push_back({float(40 * (k % 10)), float(40 * (k / 10)), 20, 12});
    for (const Placed& q : place_labels(spread, 16)) CHECK(q.shown);
}

TEST_CASE("no label is placed on a part of the view an inset covers, a point under one is labelled above it", "[labels]") {
    const ViewRect inset{20, 380, 300, 660};
    // the usual spot (upper right) would reach into the inset: another spot is taken
    const LabelBox beside{10, 390, 60, 14};
    const Placed p = place_labels({beside}, 12, {inset})[0];
    CHECK(p.shown);
    const bool clear = p.left >= inset.right || p.left + beside.width <= inset.left || p.top >= inset.bottom || p.top + beside.height <= inset.top;
    CHECK(clear);
    // a point inside the inset ("to the eye" under the screen inset): its label sits just above the inset
    const LabelBox under{150, 500, 200, 14};
    const Placed q = place_labels({under}, 12, {inset})[0];
    CHECK(q.shown);
    CHECK(q.top + under.height <= inset.top);
    CHECK(q.top >= inset.top - 3 * under.height);
    // without the inset, it keeps its usual spot by its point
    CHECK(place_labels({under})[0].top == 500 - 14);
}

TEST_CASE("a label does not cover another label's point (it would hide what that one names)", "[labels]") {
    // a long label placed first, whose usual spot (upper right of its point) runs over a small box's point, then the
    // small box's label
    const std::vector<LabelBox> two = {{150, 110, 120, 12}, {200, 100, 20, 12}};
    const auto p = place_labels(two);
    REQUIRE(p[0].shown);
    const bool covers = p[0].left <= two[1].x && two[1].x <= p[0].left + two[0].width && p[0].top <= two[1].y && two[1].y <= p[0].top + two[0].height;
    CHECK_FALSE(covers);
}
