// SPDX-License-Identifier: MIT
// Alpha compositing against exact rationals (GMP): premultiplied "over" and the notes' straight formula, their
// associativity (and the naive blend's lack of it), back to front against front to back with the early stop, and
// Porter and Duff's operators against the coverage they stand for, counted on sub-pixels.
#include <gmpxx.h>

#include <random>

#include "catch.h"
#include "compositing/compositing.h"
#include "scene/load_scene.h"

using namespace hsr::algo;

namespace {

struct Q4 {
    mpq_class r, g, b, a;
};

mpq_class q8(double v) {
    mpq_class q(int(std::lround(v * 255)), 255);
    q.canonicalize();  // GMP's (num, den) constructor leaves it to us
    return q;
}
Q4 exact(Rgba c) { return {q8(c.r), q8(c.g), q8(c.b), q8(c.a)}; }  // an 8-bit colour as the rational it stands for
Q4 premultiply(const Q4& c) { return {c.a * c.r, c.a * c.g, c.a * c.b, c.a}; }
Q4 over(const Q4& f, const Q4& b) {
    const mpq_class k = 1 - f.a;
    return {f.r + k * b.r, f.g + k * b.g, f.b + k * b.b, f.a + k * b.a};
}
bool equal(const Q4& x, const Q4& y) { return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a; }
double off(Rgba got, const Q4& want) {
    return std::max({std::abs(got.r - want.r.get_d()), std::abs(got.g - want.g.get_d()), std::abs(got.b - want.b.get_d()),
                     std::abs(got.a - want.a.get_d())});
}

Rgba random_colour(std::mt19937& rng, int alpha_low = 0, int alpha_high = 255) {
    std::uniform_int_distribution<int> byte(0, 255), alpha(alpha_low, alpha_high);
    return {byte(rng) / 255.0, byte(rng) / 255.0, byte(rng) / 255.0, alpha(rng) / 255.0};
}

}  // namespace

TEST_CASE("premultiplied over is associative, exactly, and the machine's doubles follow the exact values", "[compositing]") {
    std::mt19937 rng(3);
    for (int k = 0; k < 500; ++k) {
        const Rgba f = random_colour(rng), m = random_colour(rng), b = random_colour(rng);
        const Q4 F = premultiply(exact(f)), M = premultiply(exact(m)), B = premultiply(exact(b));
        REQUIRE(equal(over(over(F, M), B), over(F, over(M, B))));
        CHECK(off(over(over(premultiply(f), premultiply(m)), premultiply(b)), over(over(F, M), B)) < 1e-15);
    }
}

TEST_CASE("the notes' straight formula is premultiplied over, un-premultiplied (it divides by A′)", "[compositing]") {
    std::mt19937 rng(4);
    for (int k = 0; k < 500; ++k) {
        const Rgba f = random_colour(rng), b = random_colour(rng, 1);
        const Q4 P = over(premultiply(exact(f)), premultiply(exact(b)));
        const Q4 straight{P.r / P.a, P.g / P.a, P.b / P.a, P.a};
        CHECK(off(over_straight(f, b), straight) < 1e-14);
    }
    // both clear: A′ = 0 and nothing to divide; no NaN
    const Rgba clear = over_straight({1, 0.5, 0.2, 0}, {0.3, 0.3, 0.3, 0});
    CHECK(clear == Rgba{});
    const Rgba faint = over_straight({1, 0.5, 0.2, 1e-300}, {0.3, 0.3, 0.3, 0});
    CHECK(faint.r == Approx(1.0));
    CHECK(faint.a == 1e-300);
}

TEST_CASE("the naive blend of straight colours is associative only when the middle layer is opaque", "[compositing]") {
    std::mt19937 rng(5);
    int differ = 0;
    for (int k = 0; k < 300; ++k) {
        const Rgba f = random_colour(rng, 30, 225), m = random_colour(rng, 30, 225), b = random_colour(rng);
        const Rgba left = blend_naive(blend_naive(f, m), b), right = blend_naive(f, blend_naive(m, b));
        differ += max_difference(left, right) > 1e-9;
        const Rgba opaque{m.r, m.g, m.b, 1};
        CHECK(max_difference(blend_naive(blend_naive(f, opaque), b), blend_naive(f, blend_naive(opaque, b))) < 1e-12);
    }
    CHECK(differ > 250);  // all but triples whose colours happen to agree
}

TEST_CASE("back to front and front to back give one colour, the early stop leaves out no more than 1 − A", "[compositing]") {
    std::mt19937 rng(6);
    for (int k = 0; k < 200; ++k) {
        std::vector<Layer> layers;
        const int n = 1 + k % 7;
        for (int i = 0; i < n; ++i) layers.push_back({SceneId(i + 1), random_colour(rng, 0, 255), double(i)});
        Q4 want{0, 0, 0, 0};
        for (int i = n; i-- > 0;) want = over(premultiply(exact(layers[std::size_t(i)].colour)), want);
        const CompositeResult all = composite(layers, {.opaque_enough = 2}).run_to_end();  // never stops early
        CHECK(off(all.back_to_front, want) < 1e-14);
        CHECK(off(all.front_to_back, want) < 1e-14);
        CHECK(all.front_to_back_layers == std::size_t(n));
        CHECK(max_difference(unpremultiply(all.back_to_front), all.straight) < 1e-12);
        const CompositeResult early = composite(layers, {.opaque_enough = 0.9}).run_to_end();
        CHECK(max_difference(early.front_to_back, all.back_to_front) <= 1 - early.front_to_back.a + 1e-12);
        if (early.front_to_back_layers < std::size_t(n)) CHECK(early.front_to_back.a >= 0.9);
    }
}

TEST_CASE("Porter and Duff's operators are the coverage of uncorrelated shapes, counted on sub-pixels", "[compositing]") {
    // A covers the left i of k columns, B the top j of k rows: both cover exactly (i/k)(j/k). Each operator shows A,
    // B, both summed or nothing in each of the four regions; summed over the sub-pixels that is F_A·A + F_B·B.
    const int k = 8;
    const Q4 ca{mpq_class(1, 5), mpq_class(2, 5), mpq_class(1, 2), 1}, cb{mpq_class(1, 2), mpq_class(1, 10), mpq_class(3, 10), 1};
    for (const PorterDuff op : porter_duff_operators())
        for (int i = 0; i <= k; ++i)
            for (int j = 0; j <= k; ++j) {
                const bool keeps_both_a = op == PorterDuff::a || op == PorterDuff::over || op == PorterDuff::in || op == PorterDuff::atop || op == PorterDuff::plus;
                const bool keeps_both_b = op == PorterDuff::b || op == PorterDuff::plus;
                const bool keeps_a_only = op == PorterDuff::a || op == PorterDuff::over || op == PorterDuff::out || op == PorterDuff::xor_ || op == PorterDuff::plus;
                const bool keeps_b_only = op == PorterDuff::b || op == PorterDuff::over || op == PorterDuff::atop || op == PorterDuff::xor_ || op == PorterDuff::plus;
                Q4 sum{0, 0, 0, 0};
                const auto add = [&](const Q4& c) { sum = {sum.r + c.r, sum.g + c.g, sum.b + c.b, sum.a + c.a}; };
                for (int x = 0; x < k; ++x)
                    for (int y = 0; y < k; ++y) {
                        const bool in_a = x < i, in_b = y < j;
                        if (in_a && in_b) {
                            if (keeps_both_a) add(ca);
                            if (keeps_both_b) add(cb);
                        } else if (in_a && keeps_a_only) {
                            add(ca);
                        } else if (in_b && keeps_b_only) {
                            add(cb);
                        }
                    }
                const mpq_class area = k * k;
                const Q4 want{sum.r / area, sum.g / area, sum.b / area, sum.a / area};
                const double aa = double(i) / k, ab = double(j) / k;
                const Rgba a{ca.r.get_d() * aa, ca.g.get_d() * aa, ca.b.get_d() * aa, aa};
                const Rgba b{cb.r.get_d() * ab, cb.g.get_d() * ab, cb.b.get_d() * ab, ab};
                const Rgba got = porter_duff(op, a, b);
                INFO(to_string(op) << ", α_A = " << i << "/" << k << ", α_B = " << j << "/" << k);
                if (op == PorterDuff::plus && want.a > 1) continue;  // plus clamps past full coverage
                REQUIRE(off(got, want) < 1e-15);
            }
}

TEST_CASE("the compositing machine on the lesson's glass: layers in depth order, its events, exact alphas", "[compositing]") {
    const Scene scene = load_scene(HSR_SOURCE_DIR "/assets/scenes/glass_layers.toml");
    const std::vector<Layer> layers = layers_along(scene, centre_ray(scene.camera));
    REQUIRE(layers.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) CHECK(layers[i].id == SceneId(i + 1));
    auto m = composite(layers);
    std::size_t events = 0, over = 0, under = 0, operators = 0;
    std::optional<EarlyStop> stop;
    std::optional<AssociativityChecked> assoc;
    double under_alpha_1 = -1;
    for (const auto& e : m) {
        ++events;
        over += std::holds_alternative<OverApplied>(e);
        if (const auto* u = std::get_if<UnderApplied>(&e)) {
            ++under;
            if (u->layer == 1) under_alpha_1 = u->alpha;
        }
        operators += std::holds_alternative<PorterDuffApplied>(e);
        if (const auto* s = std::get_if<EarlyStop>(&e)) stop = *s;
        if (const auto* a = std::get_if<AssociativityChecked>(&e)) assoc = *a;
    }
    CHECK(events <= 6 * layers.size() + 16);  // the machine's step bound
    CHECK(over == 4);
    CHECK(under == 3);  // the wall makes A = 1: the yellow glass behind it is left out
    REQUIRE(stop);
    CHECK(stop->skipped == 1);
    CHECK(under_alpha_1 == 0.875);  // exact: the lesson's question
    REQUIRE(assoc);
    CHECK(assoc->associative);
    CHECK_FALSE(assoc->naive_associative);
    CHECK(operators == porter_duff_operators().size());
    // no layers at all: a clear pixel
    const CompositeResult none = composite({}).run_to_end();
    CHECK(none.back_to_front == Rgba{});
    CHECK(none.front_to_back_layers == 0);
}
