// SPDX-License-Identifier: MIT
#include "depth_sort/depth_sort.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>

#include "clipping/sutherland_hodgman.h"
#include "depth_sort/front_to_back.h"
#include "core/numeric.h"
#include "raster/screen_polygon.h"

namespace hsr::algo {
namespace {

const Tolerance tol = Tolerance::for_extent(2);  // the canonical view volume is 2 units across

struct Extents {
    double min_x, max_x, min_y, max_y, min_z, max_z;
    Plane plane;
    bool has_plane;
};

Extents extents_of(const SortPolygon& p) {
    Extents e{1e300, -1e300, 1e300, -1e300, 1e300, -1e300, {}, false};
    for (const Vec3& v : p.vertices) {
        e.min_x = std::min(e.min_x, v.x), e.max_x = std::max(e.max_x, v.x);
        e.min_y = std::min(e.min_y, v.y), e.max_y = std::max(e.max_y, v.y);
        e.min_z = std::min(e.min_z, v.z), e.max_z = std::max(e.max_z, v.z);
    }
    e.has_plane = plane_of(p.vertices, e.plane);
    return e;
}

// The side of a plane the viewpoint (at z = −∞) is on: +1 front, −1 back, 0 when the plane holds the view rays.
int viewer_side(const Extents& e) {
    if (!e.has_plane || std::abs(e.plane.n.z) <= tol.epsilon) return 0;
    return e.plane.n.z < 0 ? 1 : -1;
}

// Tests 3 and 4 (and their swapped forms): does every vertex of `polygon` lie on `want` side of the plane (+1 the
// viewer's, −1 the other), or on it? The counts become the event's numbers.
TestTried plane_test(OrderTest test, const std::vector<Vec3>& polygon, const Extents& of_plane, bool viewer_half) {
    const int v = viewer_side(of_plane);
    double far_side = 0, near_side = 0, on = 0;
    for (const Vec3& p : polygon) {
        const Side s = classify(of_plane.plane, p, tol);
        if (s == Side::on) ++on;
        else if ((s == Side::front ? 1 : -1) == v) ++near_side;
        else ++far_side;
    }
    const bool passed = v != 0 && (viewer_half ? far_side == 0 : near_side == 0);
    return {test, passed, far_side, near_side, on, double(v)};
}

double projected_area(const std::vector<Vec3>& p) {
    double twice = 0;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) twice += p[j].x * p[i].y - p[i].x * p[j].y;
    return std::abs(twice) / 2;
}

// Test 5: do the projections onto the screen (x, y) overlap? Separating axes of two convex polygons; touching
// counts as not overlapping, and so does a polygon seen edge-on (its projection covers nothing).
bool projections_overlap(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    if (projected_area(a) <= tol.epsilon || projected_area(b) <= tol.epsilon) return false;
    for (const auto* poly : {&a, &b})
        for (std::size_t i = 0, j = poly->size() - 1; i < poly->size(); j = i++) {
            const glm::dvec2 axis((*poly)[i].y - (*poly)[j].y, (*poly)[j].x - (*poly)[i].x);
            if (axis.x == 0 && axis.y == 0) continue;
            double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
            for (const Vec3& p : a) a0 = std::min(a0, axis.x * p.x + axis.y * p.y), a1 = std::max(a1, axis.x * p.x + axis.y * p.y);
            for (const Vec3& p : b) b0 = std::min(b0, axis.x * p.x + axis.y * p.y), b1 = std::max(b1, axis.x * p.x + axis.y * p.y);
            const double slack = tol.epsilon * (std::abs(axis.x) + std::abs(axis.y));
            if (a1 <= b0 + slack || b1 <= a0 + slack) return false;
        }
    return true;
}

// Does the plane of one polygon cut another (vertices on both sides, beyond the tolerance)?
bool cuts(const Extents& of_plane, const SortPolygon& polygon) {
    return of_plane.has_plane && classify(of_plane.plane, polygon.vertices, tol) == PolygonSide::spanning;
}


// In a cycle of polygons each to be drawn before the next, one whose plane cuts another whose projection it
// overlaps: (the one cut, the one cutting). None when no plane of the cycle cuts another member.
std::optional<std::pair<std::uint32_t, std::uint32_t>> cut_in_cycle(const std::vector<std::uint32_t>& cycle,
                                                                   const std::vector<SortPolygon>& polygons,
                                                                   const std::vector<Extents>& ext) {
    for (const std::uint32_t a : cycle)
        for (const std::uint32_t b : cycle)
            if (a != b && cuts(ext[b], polygons[a]) && projections_overlap(polygons[a].vertices, polygons[b].vertices))
                return std::pair{a, b};
    return std::nullopt;
}

// The plane along the view rays (n.z = 0) through the middle of a polygon's projection, square to the line
// between its two vertices farthest apart on the screen: it cuts the polygon across its length.
Plane across_plane(const SortPolygon& p) {
    glm::dvec2 a(0), b(0), centre(0);
    for (const Vec3& u : p.vertices) {
        centre += glm::dvec2(u) / double(p.vertices.size());
        for (const Vec3& v : p.vertices)
            if (glm::distance(glm::dvec2(u), glm::dvec2(v)) > glm::distance(a, b)) a = u, b = v;
    }
    const glm::dvec2 along = b - a;
    if (along == glm::dvec2(0)) return {};
    const Vec3 n = glm::normalize(Vec3(along, 0));
    return {n, -glm::dot(n, Vec3(centre, 0))};
}

// Tests 1, 2, 3, 4, 5 in order of cost: may R be drawn before Q?
std::array<TestTried, 5> r_before_q_tests(const SortPolygon& r, const Extents& er, const SortPolygon& q, const Extents& eq) {
    return {{
        {OrderTest::x_extents, er.max_x <= eq.min_x || eq.max_x <= er.min_x, er.min_x, er.max_x, eq.min_x, eq.max_x},
        {OrderTest::y_extents, er.max_y <= eq.min_y || eq.max_y <= er.min_y, er.min_y, er.max_y, eq.min_y, eq.max_y},
        plane_test(OrderTest::r_behind_q, r.vertices, eq, false),
        plane_test(OrderTest::q_in_front_of_r, q.vertices, er, true),
        {OrderTest::projections, false, 0, 0, 0, 0},  // filled in only if reached: it is the costly one
    }};
}

// The list still to draw, head first (R is its head). Kept reversed in a vector, the head last, so that drawing the
// head costs O(1) and moving a polygon to the head, or putting the parts of a split in the place of the polygon cut,
// costs O(its distance from the head): near the head is where the work happens. Beside each entry, the greatest
// MAXZ from it to the tail, so that the scan for the polygons whose z extent overlaps R's can stop where everything
// left is wholly nearer than R; for the list sorted farthest first that is the first wholly nearer polygon. Without
// it every R walked the whole list, 10^12 looks for 10^6 polygons.
class DisplayList {
public:
    DisplayList(const std::vector<std::uint32_t>& head_first, const std::vector<Extents>& ext)
        : ext_(ext), reversed_(head_first.rbegin(), head_first.rend()) {
        refresh_from(0);
    }
    bool empty() const { return reversed_.empty(); }
    std::size_t size() const { return reversed_.size(); }
    std::uint32_t operator[](std::size_t k) const { return reversed_[index(k)]; }  // k = 0 is the head
    std::uint32_t front() const { return reversed_.back(); }
    void pop_front() { reversed_.pop_back(), farthest_.pop_back(); }
    // Is every polygon from the k-th to the tail wholly nearer than depth z (MAXZ ≤ z)?
    bool wholly_nearer_from(std::size_t k, double z) const { return farthest_[index(k)] <= z; }
    void move_to_front(std::size_t k) {
        const std::size_t i = index(k);
        const std::uint32_t q = reversed_[i];
        reversed_.erase(reversed_.begin() + std::ptrdiff_t(i));
        reversed_.push_back(q);
        refresh_from(i);
    }
    // The polygon `cut` is replaced by its two parts, `first` where it was and `second` just after it.
    void replace(std::uint32_t cut, std::uint32_t first, std::uint32_t second) {
        std::size_t i = reversed_.size() - 1;
        while (reversed_[i] != cut) --i;  // from the head: the polygon cut is R, Q, or one moved to the head
        reversed_[i] = first;
        reversed_.insert(reversed_.begin() + std::ptrdiff_t(i), second);
        refresh_from(i);
    }
    std::vector<std::uint32_t> head(std::size_t count) const {
        return {reversed_.rbegin(), reversed_.rbegin() + std::ptrdiff_t(std::min(count, size()))};
    }

private:
    std::size_t index(std::size_t k) const { return reversed_.size() - 1 - k; }
    void refresh_from(std::size_t i) {
        farthest_.resize(reversed_.size());
        for (; i < reversed_.size(); ++i)
            farthest_[i] = std::max(i == 0 ? -1e300 : farthest_[i - 1], ext_[reversed_[i]].max_z);
    }
    const std::vector<Extents>& ext_;     // grows with the parts of splits
    std::vector<std::uint32_t> reversed_;  // the tail first, the head last
    std::vector<double> farthest_;         // farthest_[i]: the greatest MAXZ of reversed_[0 … i]
};

// What tests 1–5, then 3 and 4 with the roles swapped, say of the pair R, Q.
enum class PairOrder { r_first, q_first, unknown };

// The tests in order of cost: may R be drawn before Q (1–5)? Else must Q be drawn first (3 and 4 with the roles
// swapped)? Each test tried is an event; the one that settles the pair is counted in decided_by.
Steps<DepthSortEvent, PairOrder> order_pair(const SortPolygon& r, const Extents& er, const SortPolygon& q, const Extents& eq,
                                            std::uint64_t (&decided_by)[7]) {
    for (TestTried t : r_before_q_tests(r, er, q, eq)) {
        if (t.test == OrderTest::projections) t.passed = !projections_overlap(r.vertices, q.vertices), t.a = !t.passed;
        co_yield t;
        if (t.passed) {
            ++decided_by[int(t.test)];
            co_return PairOrder::r_first;
        }
    }
    const TestTried swapped[2] = {plane_test(OrderTest::q_behind_r, q.vertices, er, false),
                                  plane_test(OrderTest::r_in_front_of_q, r.vertices, eq, true)};
    for (const TestTried& t : swapped) {
        co_yield t;
        if (t.passed) {
            ++decided_by[int(t.test)];
            co_return PairOrder::q_first;
        }
    }
    co_return PairOrder::unknown;
}

// What the sort works on beside R and Q: the polygons (the parts of splits appended), their extents, which were
// moved to the head, the moves since a polygon was last drawn, and the list still to draw.
struct Sorting {
    DepthSortResult& out;
    std::vector<Extents>& ext;
    std::vector<bool>& moved;
    std::size_t& moves_since_drawn;
    DisplayList& list;
};

// How a pair the tests could not order was resolved.
enum class Unordered { q_moved, split, too_small_to_cut, bounded };

// R and Q (the k-th of the list) are not in order: Q goes to the head of the list if it must go first and was not
// moved before; else a cycle, or no order: a polygon is split by another's plane, as the notes say.
Steps<DepthSortEvent, Unordered> resolve_unordered(Sorting s, std::uint32_t r, std::uint32_t q, std::size_t k, bool q_first,
                                                   std::uint64_t max_splits) {
    auto& [out, ext, moved, moves_since_drawn, list] = s;
    if (q_first && !moved[q]) {  // Q goes to the head of the list
        moved[q] = true;
        ++out.moves, ++moves_since_drawn;
        list.move_to_front(k);
        co_yield PolygonMoved{q, r};
        co_return Unordered::q_moved;
    }
    // Q was moved before: a cycle, or no order could be shown. As the notes say, split R by Q's plane; if that
    // plane does not cut R, split Q by R's.
    std::uint32_t cut = r, by = q;
    std::optional<Plane> across;  // a plane along the view rays, when no polygon's plane cuts the cycle
    if (classify(ext[q].plane, out.polygons[r].vertices, tol) != PolygonSide::spanning) cut = q, by = r;
    if (!cuts(ext[by], out.polygons[cut])) {
        // Neither cuts the other, and Q must go first: that is an order, not a cycle of these two (Q's mark is
        // from another R): move it again. But only while this round has moved fewer polygons than the list
        // holds; beyond that the moves go round a cycle of three or more (each before the next, the last
        // before the first) in which R's and Q's planes cut neither: the plane of another member of the
        // cycle must cut one of them, so split that one.
        if (q_first && moves_since_drawn < list.size()) {
            ++out.moves, ++moves_since_drawn;
            list.move_to_front(k);
            co_yield PolygonMoved{q, r};
            co_return Unordered::q_moved;
        }
        // The cycle's members: the polygons moved to the head of the list since the last was drawn, and Q
        std::vector<std::uint32_t> cycle = list.head(std::min(moves_since_drawn + 1, k));
        cycle.push_back(q);
        if (const auto pair = cut_in_cycle(cycle, out.polygons, ext)) {
            std::tie(cut, by) = *pair;
        } else if (const Plane p = across_plane(out.polygons[r]); classify(p, out.polygons[r].vertices, tol) == PolygonSide::spanning) {
            // No plane of the cycle cuts another member (bars lying each over the next): cut R across its
            // length by a plane along the view rays, so that each half overlaps fewer of the others
            cut = by = r, across = p;
        } else {
            co_return Unordered::too_small_to_cut;  // nothing orders them better than the list
        }
        moves_since_drawn = 0;  // the parts are new polygons: the round starts again
    }
    if (q_first) co_yield CycleDetected{q};
    if (out.splits == max_splits) {
        out.bounded = true;
        co_yield SortBoundReached{SortBound::splits, max_splits};
        co_return Unordered::bounded;
    }
    const SplitParts parts = split(across.value_or(ext[by].plane), out.polygons[cut].vertices, tol);
    const auto front = std::uint32_t(out.polygons.size()), back = front + 1;
    for (const auto* part : {&parts.front, &parts.back}) {
        out.polygons.push_back({out.polygons[cut].id, out.polygons[cut].color, *part, out.polygons[cut].opacity});
        ext.push_back(extents_of(out.polygons.back()));
        moved.push_back(false);
    }
    ++out.splits;
    list.replace(cut, back, front);
    const DepthSortEvent cut_event = PolygonCut{cut, by, front, back, parts.front, parts.back, across.has_value()};
    co_yield cut_event;
    co_return Unordered::split;
}

}  // namespace

Steps<DepthSortEvent, DepthSortResult> depth_sort(std::vector<SortPolygon> polygons, DepthSortOptions o) {
    DepthSortResult out;
    out.polygons = std::move(polygons);
    std::vector<Extents> ext;
    for (const auto& p : out.polygons) ext.push_back(extents_of(p));
    const std::uint64_t n = out.polygons.size();
    const std::uint64_t max_pairs = o.max_pairs.value_or(std::clamp<std::uint64_t>(256 * n * n, 100'000, 50'000'000));
    std::vector<bool> moved(out.polygons.size(), false);
    std::size_t moves_since_drawn = 0;  // moves since a polygon was last drawn: a round moves each polygon once at most
    // Find MINZ and MAXZ; sort, farthest first
    std::vector<std::uint32_t> sorted(out.polygons.size());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) sorted[i] = i;
    std::stable_sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) { return ext[a].max_z > ext[b].max_z; });
    {
        const DepthSortEvent event = ListSorted{sorted};
        co_yield event;
    }
    DisplayList list(sorted, ext);
    sorted = {};
    // Resolve overlaps in z, then draw the head of the list
    while (!list.empty()) {
        const std::uint32_t r = list.front();
        bool draw_r = true;
        for (std::size_t k = 1; k < list.size() && draw_r; ++k) {
            if (list.wholly_nearer_from(k, ext[r].min_z)) break;  // so is every Q after it: R may go first
            const std::uint32_t q = list[k];
            // Q wholly nearer than R: R may go first. (Not so when Q is wholly farther: once polygons have been moved
            // to the head, R need not be the farthest, and a Q behind it must be tested like any other.)
            if (ext[q].max_z <= ext[r].min_z) continue;
            if (++out.pairs > max_pairs) {
                out.bounded = true;
                co_yield SortBoundReached{SortBound::pairs, max_pairs};
                co_return out;
            }
            co_yield PairExamined{r, q, ext[r].min_z, ext[r].max_z, ext[q].min_z, ext[q].max_z};
            auto tests = order_pair(out.polygons[r], ext[r], out.polygons[q], ext[q], out.decided_by);
            for (const DepthSortEvent& e : tests) co_yield e;
            if (tests.result() == PairOrder::r_first) continue;
            const bool q_first = tests.result() == PairOrder::q_first;
            auto resolved = resolve_unordered({out, ext, moved, moves_since_drawn, list}, r, q, k, q_first, o.max_splits);
            for (const DepthSortEvent& e : resolved) co_yield e;
            if (resolved.result() == Unordered::bounded) co_return out;
            if (resolved.result() == Unordered::too_small_to_cut) continue;  // on to the next Q
            draw_r = false;  // Q went to the head, or a polygon was cut: the list's head is tested again
            break;
        }
        if (!draw_r) continue;
        list.pop_front();
        moves_since_drawn = 0;
        out.order.push_back(r);
        co_yield PolygonPainted{r, out.polygons[r].id, o.front_to_back.has_value()};
    }
    if (o.front_to_back) {  // the display step, nearest first, until the screen is full
        auto display = display_front_to_back(out.polygons, out.order, *o.front_to_back);
        for (const FrontToBackEvent& e : display) {
            const DepthSortEvent event = std::visit([](const auto& x) -> DepthSortEvent { return x; }, e);
            co_yield event;
        }
    }
    co_yield DepthSortFinished{std::uint32_t(out.order.size()), out.splits, out.moves, out.pairs};
    co_return out;
}

std::vector<SortPolygon> sort_polygons(const Scene& scene) {
    std::vector<SortPolygon> out;
    for (const ScenePolygon& p : scene.polygons) {
        for (std::size_t k = 0; k < p.vertices.size(); ++k)
            require_finite(p.vertices[k], "polygon " + std::to_string(p.id) + " vertex " + std::to_string(k));
        if (p.vertices.size() < 3) continue;
        if (scene.coordinates == Coordinates::world) require_convex(p);
        ClipPolygon clip{p.id, {}};
        for (const auto& v : p.vertices) clip.vertices.push_back(to_clip(scene, v));
        const PolygonClip visible = sutherland_hodgman(std::move(clip), {.space = ClipSpace::homogeneous}).run_to_end();
        if (visible.vertices.size() < 3) continue;  // wholly outside the view volume
        SortPolygon s{p.id, p.color, {}, p.opacity};
        for (const Vec4& c : visible.vertices) s.vertices.push_back(Vec3(c) / c.w);
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace hsr::algo
