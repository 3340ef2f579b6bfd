// SPDX-License-Identifier: MIT
// Practice: for every topic, 200 exercises over the three levels, each answer recomputed from the numbers the
// exercise gives by an independent reference (exact rationals: outcodes, the trivial tests and Sutherland–Hodgman's
// stages by hand, Liang–Barsky's parameters from the exact clipper, the eye's side of a plane), and the grading.
#include <array>
#include <gmpxx.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <set>

#include "analysis/exact_clip.h"
#include "analysis/exact_horizon.h"
#include "catch.h"
#include "core/numeric.h"
#include "horizon/floating_horizon.h"
#include "scene/save_scene.h"
#include "state/lesson.h"
#include "state/practice/practice.h"
#include "state/practice/practice_mode.h"
#include "state/trace.h"

namespace {

using hsr::viz::practice::Exercise;
using hsr::viz::practice::Level;
using Q = mpq_class;
using QPoint = std::array<Q, 4>;

QPoint exact(const nlohmann::json& numbers) {
    QPoint p{Q(0), Q(0), Q(0), Q(1)};
    for (std::size_t k = 0; k < numbers.size(); ++k) p[k] = Q(numbers[k].get<double>());
    return p;
}

hsr::algo::Vec4 vec4(const nlohmann::json& n) { return {n[0].get<double>(), n[1].get<double>(), n[2].get<double>(), n[3].get<double>()}; }

// The notes' planes in their bit order, as boundary values (≥ 0 inside), written out again here: z max, z min,
// y max, y min, x max, x min, and w min in clip space.
const std::vector<std::string> plane_names = {"z max", "z min", "y max", "y min", "x max", "x min", "w min"};

Q boundary(const QPoint& p, std::size_t plane, bool homogeneous) {
    const Q w = homogeneous ? p[3] : Q(1);
    switch (plane) {
        case 0: return w - p[2];
        case 1: return w + p[2];
        case 2: return w - p[1];
        case 3: return w + p[1];
        case 4: return w - p[0];
        case 5: return w + p[0];
        default: return p[3] - Q(hsr::algo::ClipTolerance::w_epsilon);
    }
}
std::size_t planes(bool homogeneous) { return homogeneous ? 7 : 6; }

std::string outcode(const QPoint& p, bool homogeneous) {
    std::string code;
    for (std::size_t k = 0; k < 6; ++k) code += boundary(p, k, homogeneous) < 0 ? '1' : '0';
    if (homogeneous && boundary(p, 6, true) < 0) code += "+w";
    return code;
}

// Sutherland–Hodgman in rationals, stage by stage, to the named plane: the vertex count after it.
std::size_t vertices_after(std::vector<QPoint> polygon, const std::string& last, bool homogeneous) {
    for (std::size_t k = 0; k < planes(homogeneous); ++k) {
        std::vector<QPoint> out;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const QPoint &s = polygon[i], &e = polygon[(i + 1) % polygon.size()];
            const Q bs = boundary(s, k, homogeneous), be = boundary(e, k, homogeneous);
            auto cut = [&] {
                const Q t = bs / (bs - be);
                QPoint i_point;
                for (std::size_t c = 0; c < 4; ++c) i_point[c] = s[c] + t * (e[c] - s[c]);
                return i_point;
            };
            if (bs >= 0 && be >= 0) out.push_back(e);
            else if (bs >= 0) out.push_back(cut());
            else if (be >= 0) {
                out.push_back(cut());
                out.push_back(e);
            }
        }
        polygon = out;
        if (plane_names[k] == last) return polygon.size();
    }
    FAIL("no plane " << last);
    return 0;
}

// Where along p1 → p2 an exact point lies.
double parameter_of(const hsr::analysis::ExactPoint& x, const QPoint& p1, const QPoint& p2) {
    std::size_t longest = 0;
    for (std::size_t k = 1; k < 4; ++k)
        if (abs(p2[k] - p1[k]) > abs(p2[longest] - p1[longest])) longest = k;
    return Q((x.c[longest] - p1[longest]) / (p2[longest] - p1[longest])).get_d();
}

// The notes' depth-sort tests for the first pair, from the corners (x, y, depth) in exact rationals: the viewer is
// at depth −∞, so its side of a plane is the side of (0, 0, −1) from it.
std::string settling_test(const Exercise& e) {
    const auto& g = e.given;
    using QP = std::array<Q, 3>;
    auto corners = [&](std::size_t k) {
        std::array<QP, 3> c;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t a = 0; a < 3; ++a) c[i][a] = Q(g["triangles"][k][i][a].get<double>());
        return c;
    };
    const auto r = corners(g["r"].get<std::size_t>() - 1), q = corners(g["q"].get<std::size_t>() - 1);
    auto apart = [](const std::array<QP, 3>& a, const std::array<QP, 3>& b, std::size_t axis) {
        Q alo = a[0][axis], ahi = alo, blo = b[0][axis], bhi = blo;
        for (const QP& p : a) alo = std::min(alo, p[axis]), ahi = std::max(ahi, p[axis]);
        for (const QP& p : b) blo = std::min(blo, p[axis]), bhi = std::max(bhi, p[axis]);
        return ahi <= blo || bhi <= alo;
    };
    // the sign of the side of `p` from the plane of `t`, and the viewer's side
    auto side = [](const std::array<QP, 3>& t, const QP& p) {
        const QP u{t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]}, v{t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
        const QP n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        return sgn(Q(n[0] * (p[0] - t[0][0]) + n[1] * (p[1] - t[0][1]) + n[2] * (p[2] - t[0][2])));
    };
    auto viewer = [&](const std::array<QP, 3>& t) { return side(t, {t[0][0], t[0][1], t[0][2] - 1}); };
    // every corner of `a` on the viewer's side of b's plane or on it (toward = true), or on the far side or on it
    auto wholly = [&](const std::array<QP, 3>& a, const std::array<QP, 3>& b, bool toward) {
        const int v = viewer(b);
        return std::all_of(a.begin(), a.end(), [&](const QP& p) { return side(b, p) == 0 || (side(b, p) == v) == toward; });
    };
    auto projections_apart = [&] {  // separating axes of two triangles; touching is apart
        for (const auto* t : {&r, &q})
            for (std::size_t k = 0; k < 3; ++k) {
                const QP& a = (*t)[k];
                const QP& b = (*t)[(k + 1) % 3];
                auto along = [&](const QP& p) { return Q((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])); };
                Q lo[2], hi[2];
                for (int s = 0; s < 2; ++s) {
                    const auto& poly = s == 0 ? r : q;
                    lo[s] = hi[s] = along(poly[0]);
                    for (const QP& p : poly) lo[s] = std::min(lo[s], along(p)), hi[s] = std::max(hi[s], along(p));
                }
                if (hi[0] <= lo[1] || hi[1] <= lo[0]) return true;
            }
        return false;
    };
    if (apart(r, q, 0)) return e.choices[0];
    if (apart(r, q, 1)) return e.choices[1];
    if (wholly(r, q, false)) return e.choices[2];
    if (wholly(q, r, true)) return e.choices[3];
    if (projections_apart()) return e.choices[4];
    if (wholly(q, r, false) || wholly(r, q, true)) return e.choices[5];
    return e.choices[6];
}

// The reference's answer to an exercise, from its given numbers only.
std::string reference_answer(const Exercise& e) {
    const nlohmann::json& g = e.given;
    const std::string kind = g.at("kind");
    const bool homogeneous = g.contains("space") && g["space"] == "homogeneous";
    if (kind == "outcode") return outcode(exact(g["point"]), homogeneous);
    if (kind == "trivial_test") {
        const std::string c1 = outcode(exact(g["p1"]), homogeneous), c2 = outcode(exact(g["p2"]), homogeneous);
        const std::string inside(6, '0');
        if (c1 == inside && c2 == inside) return e.choices[0];
        for (std::size_t k = 0; k < 6; ++k)
            if (c1[k] == '1' && c2[k] == '1') return e.choices[1];
        if (c1.size() > 6 && c2.size() > 6) return e.choices[1];  // both behind the eye
        return e.choices[2];
    }
    if (kind == "t_enter" || kind == "t_leave") {
        const auto space = homogeneous ? hsr::algo::ClipSpace::homogeneous : hsr::algo::ClipSpace::cube;
        const auto clip = hsr::analysis::exact_clip_segment(vec4(g["p1"]), vec4(g["p2"]), space);
        REQUIRE(clip.visible);
        const double t = parameter_of(kind == "t_enter" ? clip.a : clip.b, exact(g["p1"]), exact(g["p2"]));
        return std::to_string(t);
    }
    if (kind == "edge_case") {
        const std::size_t plane = std::size_t(std::find(plane_names.begin(), plane_names.end(), g["plane"].get<std::string>()) - plane_names.begin());
        const bool s_in = boundary(exact(g["s"]), plane, homogeneous) >= 0, e_in = boundary(exact(g["e"]), plane, homogeneous) >= 0;
        return e.choices[s_in ? (e_in ? 0 : 1) : (e_in ? 3 : 2)];
    }
    if (kind == "stage_count") {
        std::vector<QPoint> polygon;
        for (const auto& v : g["polygon"]) polygon.push_back(exact(v));
        return std::to_string(vertices_after(polygon, g["plane"], homogeneous));
    }
    if (kind == "facing" || kind == "distance") {
        const QPoint a = exact(g["a"]), b = exact(g["b"]), c = exact(g["c"]), eye = exact(g["eye"]);
        const Q ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const Q n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
        const Q side = n[0] * (eye[0] - a[0]) + n[1] * (eye[1] - a[1]) + n[2] * (eye[2] - a[2]);
        if (kind == "facing") return e.choices[side > 0 ? 0 : 1];
        const Q length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        return std::to_string(side.get_d() / std::sqrt(length2.get_d()));
    }
    if (kind == "wall_side" || kind == "eye_side") {  // the left of wall 1's a → b is its front
        const auto& walls = g["walls"];
        auto side = [&](const nlohmann::json& p) {
            const Q ax(walls[0][0][0].get<double>()), ay(walls[0][0][1].get<double>());
            const Q bx(walls[0][1][0].get<double>()), by(walls[0][1][1].get<double>());
            const Q cross = (bx - ax) * (Q(p[1].get<double>()) - ay) - (by - ay) * (Q(p[0].get<double>()) - ax);
            return sgn(cross);
        };
        if (kind == "eye_side") return e.choices[side(g["eye"]) > 0 ? 0 : 1];
        const auto& wall = walls[g["wall"].get<std::size_t>() - 1];
        const int s1 = side(wall[0]), s2 = side(wall[1]);
        if (s1 == 0 && s2 == 0) return "coplanar";
        if (s1 >= 0 && s2 >= 0) return "front";
        if (s1 <= 0 && s2 <= 0) return "back";
        return "spanning";
    }
    if (kind == "depth_test" || kind == "visible" || kind == "hits") {  // pixel centres in exact rationals; the nearer depth wins
        const Q cx = Q(g["pixel"][0].get<int>()) + Q(1, 2), cy = Q(g["pixel"][1].get<int>()) + Q(1, 2);
        auto covers = [&](const nlohmann::json& t) {
            int signs[3];
            for (int k = 0; k < 3; ++k) {
                const auto& a = t["corners"][k];
                const auto& b = t["corners"][(k + 1) % 3];
                const Q ax(a[0].get<double>()), ay(a[1].get<double>()), bx(b[0].get<double>()), by(b[1].get<double>());
                signs[k] = sgn(Q((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)));
            }
            return (signs[0] > 0 && signs[1] > 0 && signs[2] > 0) || (signs[0] < 0 && signs[1] < 0 && signs[2] < 0);
        };
        const auto& triangles = g["triangles"];
        if (kind == "hits") {
            int hits = 0;
            for (const auto& t : triangles) hits += covers(t);
            return std::to_string(hits);
        }
        const std::size_t last = kind == "visible" ? triangles.size() : g["triangle"].get<std::size_t>() - 1;
        std::optional<std::size_t> nearest;  // among the triangles drawn before `last` (all of them for "visible")
        for (std::size_t k = 0; k < last; ++k)
            if (covers(triangles[k]) && (!nearest || triangles[k]["depth"].get<double>() < triangles[*nearest]["depth"].get<double>())) nearest = k;
        if (kind == "visible") return nearest ? e.choices[*nearest] : e.choices.back();
        const bool passes = !nearest || triangles[last]["depth"].get<double>() < triangles[*nearest]["depth"].get<double>();
        REQUIRE(covers(triangles[last]));
        return e.choices[passes ? 0 : 1];
    }
    if (kind == "node_outcome") {  // an axis-aligned cell against an axis-aligned volume, exactly
        const auto& v = g["volume"];
        const auto& c = g["cell"];
        bool inside = true, outside = false;
        for (std::size_t a = 0; a < 3; ++a) {
            const Q vlo(v[0][a].get<double>()), vhi(v[1][a].get<double>()), clo(c[0][a].get<double>()), chi(c[1][a].get<double>());
            outside = outside || chi < vlo || clo > vhi;
            inside = inside && clo >= vlo && chi <= vhi;
        }
        return e.choices[outside ? 1 : inside ? 0 : 2];
    }
    if (kind == "settling_test") return settling_test(e);
    if (kind == "farthest_visible") {  // the PVS by sampled rays: lines through points inside the first opening and
        const auto& o = g["openings"];   // inside the last, strictly inside every opening between
        auto sees_through = [&](std::size_t last) {
            constexpr int samples = 96;
            const double xa = o[0][0], xb = o[last][0];
            for (int i = 0; i < samples; ++i)
                for (int j = 0; j < samples; ++j) {
                    const double ya = o[0][1].get<double>() + (o[0][2].get<double>() - o[0][1].get<double>()) * (i + 0.5) / samples;
                    const double yb = o[last][1].get<double>() + (o[last][2].get<double>() - o[last][1].get<double>()) * (j + 0.5) / samples;
                    bool through = true;
                    for (std::size_t k = 1; k < last && through; ++k) {
                        const double y = ya + (yb - ya) * (o[k][0].get<double>() - xa) / (xb - xa);
                        through = o[k][1].get<double>() < y && y < o[k][2].get<double>();
                    }
                    if (through) return true;
                }
            return false;
        };
        std::size_t farthest = 0;  // room B, behind the first opening, is always seen
        while (farthest + 1 < o.size() && sees_through(farthest + 1)) ++farthest;
        return e.choices[farthest];
    }
    if (kind == "hiz_occluded") {  // every pixel of the footprint holds something drawn nearer than the box
        const auto& f = g["footprint"];
        for (int y = f[1].get<int>(); y < f[3].get<int>(); ++y)
            for (int x = f[0].get<int>(); x < f[2].get<int>(); ++x) {
                double depth = 10;  // the background
                for (const auto& r : g["drawn"])
                    if (r["pixels"][0].get<int>() <= x && x < r["pixels"][2].get<int>() && r["pixels"][1].get<int>() <= y &&
                        y < r["pixels"][3].get<int>())
                        depth = std::min(depth, r["depth"].get<double>());
                if (!(depth < g["near"].get<double>())) return e.choices[1];
            }
        return e.choices[0];
    }
    if (kind == "active_edges" || kind == "enter_x") {  // the line through the pixel centres, y + 1/2, exactly
        const Q line = Q(g["pixel"][1].get<int>()) + Q(1, 2);
        int active = 0;
        std::optional<Q> enter;
        for (std::size_t k = 0; k < g["triangles"].size(); ++k)
            for (std::size_t c = 0; c < 3; ++c) {
                const auto& a = g["triangles"][k]["corners"][c];
                const auto& b = g["triangles"][k]["corners"][(c + 1) % 3];
                const Q ax(a[0].get<double>()), ay(a[1].get<double>()), bx(b[0].get<double>()), by(b[1].get<double>());
                if (!(std::min(ay, by) < line && line < std::max(ay, by))) continue;
                ++active;
                const Q x = ax + (bx - ax) * (line - ay) / (by - ay);
                if (k + 1 == g["triangle"].get<std::size_t>() && (!enter || x < *enter)) enter = x;
            }
        if (kind == "active_edges") return std::to_string(active);
        REQUIRE(enter);
        return std::to_string(enter->get_d());
    }
    if (kind == "fight" || kind == "codes_apart") {  // the notes' codes, round((2^N − 1)(a + b/z)), exactly
        const Q n(g["near"].get<double>()), f(g["far"].get<double>());
        const Q levels = Q(mpz_class(1) << g["bits"].get<int>()) - 1;
        auto code = [&](double z) {
            const Q scaled = levels * (f / (f - n) + f * n / ((n - f) * Q(z)));
            mpz_class rounded;
            mpz_fdiv_q(rounded.get_mpz_t(), Q(scaled + Q(1, 2)).get_num_mpz_t(), Q(scaled + Q(1, 2)).get_den_mpz_t());
            return rounded;
        };
        const mpz_class apart = code(g["farther"].get<double>()) - code(g["nearer"].get<double>());
        for (const char* square : {"farther", "nearer"}) {  // the student computes from the question's numbers
            char text[32];
            std::snprintf(text, sizeof text, "z = %.10g", g[square].get<double>());
            CHECK_THAT(e.question, Catch::Contains(text));
        }
        if (kind == "codes_apart") return apart.get_str();
        return e.choices[apart > 0 ? 0 : 1];
    }
    if (kind == "compositing_alpha" || kind == "compositing_channel") {  // the question's numbers, exactly
        std::vector<std::array<Q, 4>> layers;  // premultiplied, nearest first
        for (const auto& l : g["layers"]) {
            const Q a(l[3].get<double>());
            layers.push_back({a * Q(l[0].get<double>()), a * Q(l[1].get<double>()), a * Q(l[2].get<double>()), a});
        }
        const auto over = [](const std::array<Q, 4>& f, const std::array<Q, 4>& b) {
            std::array<Q, 4> c;
            for (int k = 0; k < 4; ++k) c[std::size_t(k)] = f[std::size_t(k)] + (1 - f[3]) * b[std::size_t(k)];
            return c;
        };
        std::array<Q, 4> c{0, 0, 0, 0};
        if (kind == "compositing_alpha") {
            for (int i = 0; i <= g["layer"].get<int>(); ++i) c = over(c, layers[std::size_t(i)]);
            return std::to_string(c[3].get_d());
        }
        for (std::size_t i = layers.size(); i-- > 0;) c = over(layers[i], c);
        return std::to_string(c[std::size_t(g["channel"].get<int>())].get_d());
    }
    if (kind == "horizon_sight") {  // the exact ray walk says seen or hidden; a seen point's side is row 0's
        hsr::algo::Terrain t{.columns = g["samples"].get<int>(), .rows = g["rows"].get<int>(), .elevation = g["elevation"].get<double>()};
        t.heights = g["heights"].get<std::vector<double>>();
        const int columns = g["columns"].get<int>(), row = g["row"].get<int>(), column = g["column"].get<int>();
        const auto exact = hsr::analysis::exact_horizon(t, columns);
        if (!exact.at(row, column)) return e.choices[2];
        const hsr::algo::HorizonProjection view(t.elevation);
        const double x = (column + 0.5) * t.width() / columns;  // from the question's own words
        const auto height = [&](int r) -> Q {  // linear between the samples either side of x, exactly
            const int i = std::min(int(x), t.columns - 2);
            const Q s = Q(x) - i;
            return (1 - s) * Q(t.height(i, r)) + s * Q(t.height(i + 1, r));
        };
        const Q above = (height(row) - height(0)) * Q(view.cos_e) + Q(row) * Q(view.sin_e);
        return e.choices[above > 0 ? 0 : 1];
    }
    if (kind == "occluding_pair") {  // one projection ray exactly: x_a·z_b = x_b·z_a and y_a·z_b = y_b·z_a (orthographic: x, y equal)
        const auto a = exact(g["a"]), b = exact(g["b"]);
        const bool one_ray = g["perspective"].get<bool>() ? a[0] * b[2] == b[0] * a[2] && a[1] * b[2] == b[1] * a[2] : a[0] == b[0] && a[1] == b[1];
        if (!one_ray) return e.choices[2];
        return e.choices[a[2] > b[2] ? 0 : 1];  // the nearer has the larger z (the eye looks down −z)
    }
    FAIL("no reference for " << kind);
    return "";
}

}  // namespace

TEST_CASE("every practice topic: 200 exercises agree with an independent reference", "[practice]") {
    namespace p = hsr::viz::practice;
    REQUIRE(p::topics().size() >= 4);
    for (const p::Topic& topic : p::topics()) {
        std::map<std::string, std::set<std::string>> answers;  // per kind of question
        for (std::uint64_t i = 0; i < 200; ++i) {
            const Level level = Level(1 + i % 3);
            const Exercise e = p::exercise(topic, 2026, i, level);
            INFO(topic.id << " exercise " << i << ": " << e.question << " → " << e.answer);
            CHECK(e.topic == topic.id);
            CHECK(!e.deciding.empty());
            CHECK(e.hold_at.value_or(e.deciding_step) <= e.deciding_step);
            const std::string want = reference_answer(e);
            if (e.choices.empty()) {
                CHECK(std::abs(std::stod(e.answer) - std::stod(want)) <= 1e-4);  // the answer to 4 decimals
                CHECK(p::grade(e, want));
                CHECK(p::grade(e, std::to_string(std::stod(e.answer) + 0.8 * e.tolerance)));
                CHECK_FALSE(p::grade(e, std::to_string(std::stod(e.answer) + 2 * e.tolerance + 1e-6)));
            } else {
                CHECK(e.answer == want);
                CHECK(std::set<std::string>(e.choices.begin(), e.choices.end()).size() == e.choices.size());
                const auto at = std::find(e.choices.begin(), e.choices.end(), e.answer);
                REQUIRE(at != e.choices.end());
                CHECK(p::grade(e, e.answer));
                CHECK(p::grade(e, std::to_string(at - e.choices.begin() + 1)));  // by its number
                for (const std::string& other : e.choices)
                    if (other != e.answer) CHECK_FALSE(p::grade(e, other));
            }
            answers[e.given["kind"]].insert(e.answer);
        }
        // more than one kind of question, or one whose answers vary: a generator stuck on one answer teaches nothing
        INFO(topic.id);
        for (const auto& [kind, seen] : answers) {
            INFO(kind);
            CHECK(seen.size() >= 2);
        }
    }
}

TEST_CASE("practice topics: ids the command line takes, titles that fit the practice box's chooser", "[practice]") {
    std::set<std::string_view> ids;
    for (const auto& topic : hsr::viz::practice::topics()) {
        INFO(topic.id);
        CHECK(ids.insert(topic.id).second);
        CHECK(topic.id.find(' ') == std::string_view::npos);
        CHECK(!topic.algorithms.empty());
        // the chooser is as wide as the panel column at its narrowest (a culling title of 63 characters was cut)
        CHECK(topic.title.size() <= 54);
    }
}

TEST_CASE("practice: the same series gives the same exercises, byte for byte, another series others", "[practice]") {
    namespace p = hsr::viz::practice;
    for (const p::Topic& topic : p::topics()) {
        for (std::uint64_t i = 0; i < 20; ++i) {
            const std::string a = p::to_json(p::exercise(topic, 1234, i, Level::medium)).dump();
            const std::string b = p::to_json(p::exercise(topic, 1234, i, Level::medium)).dump();
            CHECK(a == b);
        }
        std::set<std::string> questions;
        for (std::uint64_t series = 1; series <= 20; ++series) questions.insert(p::exercise(topic, series, 0, Level::easy).question);
        CHECK(questions.size() >= 15);
    }
}

TEST_CASE("practice grading: numbers with a comma or a minus sign, choices by number, nothing else", "[practice]") {
    hsr::viz::practice::Exercise number;
    number.answer = "-0.25";
    number.tolerance = 0.005;
    using hsr::viz::practice::grade;
    CHECK(grade(number, "-0.25"));
    CHECK(grade(number, " −0,254 "));
    CHECK_FALSE(grade(number, "-0.26"));
    CHECK_FALSE(grade(number, "0.25"));
    CHECK_FALSE(grade(number, "a quarter"));
    CHECK_FALSE(grade(number, ""));
    CHECK_FALSE(grade(number, "nan"));
    CHECK_FALSE(grade(number, "-0.25 m"));  // the whole reply is the number, or it is no number
    CHECK_FALSE(grade(number, "+-0.25"));
    CHECK_FALSE(grade(number, "-1e999"));   // out of a double's range
    hsr::viz::practice::Exercise choice;
    choice.choices = {"front-facing: kept", "back-facing: culled"};
    choice.answer = choice.choices[1];
    CHECK(grade(choice, "back-facing: culled"));
    CHECK(grade(choice, "2"));
    CHECK_FALSE(grade(choice, "1"));
    CHECK_FALSE(grade(choice, "3"));
    CHECK_FALSE(grade(choice, "0"));
    CHECK_FALSE(grade(choice, "back"));
}

TEST_CASE("practice: Liang–Barsky holds before its answer shows, also when two planes meet t at one corner", "[practice]") {
    namespace p = hsr::viz::practice;
    const std::string path = (std::filesystem::temp_directory_path() / "hsrviz_practice_lb.toml").string();
    const std::string lesson_path = (std::filesystem::temp_directory_path() / "hsrviz_practice_lb_lesson.toml").string();
    const p::Topic& topic = p::topics()[*p::PracticeMode::topic_of("liang_barsky")];
    int corners = 0;  // exercises whose t is met again by a second plane (the case that showed the answer)
    for (std::uint64_t series : {1u, 2026u})
        for (std::uint64_t i = 0; i < 60; ++i) {
            const Exercise e = p::exercise(topic, series, i, Level(1 + i % 3));
            INFO("series " << series << " exercise " << i << ": " << e.question << " → " << e.answer);
            std::ofstream(path) << hsr::algo::scene_toml(e.scene);
            std::ofstream(lesson_path) << p::lesson_toml(e, "hsrviz_practice_lb.toml");
            std::ostringstream trace;
            hsr::viz::trace_lesson(hsr::viz::load_lesson(lesson_path), &trace);
            std::istringstream lines(trace.str());
            const std::size_t hold = e.hold_at.value_or(e.deciding_step);
            const std::string kind = e.given.at("kind");
            int updates_to_answer = 0;
            for (std::string line; std::getline(lines, line);) {
                const nlohmann::json event = nlohmann::json::parse(line);
                if (event["kind"] != "ParameterUpdated" || event["which"] != kind) continue;
                const bool shows_answer = std::abs(event["after"].get<double>() - std::stod(e.answer)) < 1e-4;
                updates_to_answer += shows_answer;
                // t_enter only grows and t_leave only shrinks: a value equal to the answer before the hold is the answer shown
                if (event["step"].get<std::size_t>() < hold) CHECK_FALSE(shows_answer);
            }
            corners += updates_to_answer > 1;
        }
    CHECK(corners > 0);  // the case is among them (series 1, exercise 1: two planes through one corner)
    std::filesystem::remove(path);
    std::filesystem::remove(lesson_path);
}

TEST_CASE("practice: the exercise's scene, saved and played as the window plays it, decides at the step it names", "[practice]") {
    namespace p = hsr::viz::practice;
    const std::string path = (std::filesystem::temp_directory_path() / "hsrviz_practice_scene.toml").string();
    const std::string lesson_path = (std::filesystem::temp_directory_path() / "hsrviz_practice_lesson.toml").string();
    for (const p::Topic& topic : p::topics())
        for (std::uint64_t i = 0; i < 12; ++i) {
            const Exercise e = p::exercise(topic, 77, i, Level(1 + i % 3));
            INFO(topic.id << " exercise " << i << ": " << e.question);
            std::ofstream(path) << hsr::algo::scene_toml(e.scene);
            std::ofstream(lesson_path) << p::lesson_toml(e, "hsrviz_practice_scene.toml");
            const hsr::viz::Lesson lesson = hsr::viz::load_lesson(lesson_path);
            std::ostringstream trace;
            hsr::viz::trace_lesson(lesson, &trace);
            std::istringstream lines(trace.str());
            std::string line;
            for (std::size_t step = 0; step <= e.deciding_step; ++step) REQUIRE(std::getline(lines, line));
            const nlohmann::json event = nlohmann::json::parse(line);
            CHECK(event["step"] == e.deciding_step);
            CHECK(event["text"] == e.deciding);
        }
    // the window writes the title in every language it speaks; English stays the lesson's first language
    const Exercise e = p::exercise(p::topics().front(), 5, 0, Level::easy);
    std::ofstream(path) << hsr::algo::scene_toml(e.scene);
    std::ofstream(lesson_path) << p::lesson_toml(e, "hsrviz_practice_scene.toml", {{"de", "Übung \"5\""}, {"en", "Practice 5"}});
    const hsr::viz::Lesson titled = hsr::viz::load_lesson(lesson_path);
    CHECK(titled.languages == std::vector<std::string>{"en", "de"});
    CHECK(titled.title == "Practice 5");
    CHECK(titled.titles.at("de") == "Übung \"5\"");
    std::filesystem::remove(path);
    std::filesystem::remove(lesson_path);
}

TEST_CASE("the window's practice: a series from its first exercise, held before the deciding step, scored per topic", "[practice]") {
    namespace p = hsr::viz::practice;
    p::PracticeMode mode;
    const auto backface = p::PracticeMode::topic_of("backface_plane_equation");
    REQUIRE(backface);
    CHECK(p::topics()[*backface].id == "backface");
    CHECK(p::PracticeMode::topic_of("liang_barsky") != p::PracticeMode::topic_of("cohen_sutherland"));
    CHECK_FALSE(p::PracticeMode::topic_of("depth_sort_nothing"));
    CHECK_FALSE(mode.answer("1"));  // nothing waits for an answer yet

    // series 1234's first exercise is the command line's `--seed 1234`'s first
    mode.choose(*backface, Level::medium, 1234);
    const Exercise first = mode.next();
    CHECK(p::to_json(first).dump() == p::to_json(p::exercise(p::topics()[*backface], 1234, 0, Level::medium)).dump());
    CHECK(mode.waiting());
    CHECK(mode.hold() == first.hold_at.value_or(first.deciding_step));

    // a wrong answer, then the right one to the next: the streak starts again
    const std::string wrong = first.choices.empty() ? p::decimal_text(std::stod(first.answer) + 1, 4)
                                                    : (first.choices[0] == first.answer ? first.choices[1] : first.choices[0]);
    CHECK(mode.answer(wrong) == false);
    CHECK_FALSE(mode.waiting());
    CHECK_FALSE(mode.hold());
    CHECK_FALSE(mode.answer(first.answer));  // answered once only
    const Exercise second = mode.next();
    CHECK(second.index == 1);
    CHECK(mode.answer(second.answer) == true);
    CHECK(mode.score().answered == 2);
    CHECK(mode.score().right == 1);
    CHECK(mode.score().streak == 1);
    CHECK(mode.score().best_streak == 1);

    // a number is typed key by key: digits, one sign at the front, a comma or a point, Backspace
    mode.choose(*p::PracticeMode::topic_of("liang_barsky"), Level::easy, 5);
    const Exercise t = mode.next();
    REQUIRE(t.choices.empty());
    for (char c : std::string("-0-,5x")) mode.type(c);
    CHECK(mode.typed == "-0,5");
    mode.type('\b');
    mode.type('\b');
    CHECK(mode.typed == "-0");
    CHECK(mode.score().answered == 0);  // scores are per topic
    // another series starts from its first exercise
    mode.choose(mode.topic(), Level::easy, 5);
    CHECK(mode.next().index == 0);

    // the scores the window keeps between runs: the streak starts again, its best stays
    const auto kept = mode.records();
    REQUIRE(kept.contains("backface"));
    CHECK(kept.at("backface") == hsr::viz::PracticeRecord{2, 1, 1});
    p::PracticeMode again;
    again.restore(kept);
    again.choose(*backface, Level::easy, 1);
    CHECK(again.score().answered == 2);
    CHECK(again.score().right == 1);
    CHECK(again.score().streak == 0);
    CHECK(again.score().best_streak == 1);
}
