// SPDX-License-Identifier: MIT
// Alpha compositing's rows of the report: stacks of translucent layers with 8-bit colours and alphas, composited
// in each storage against exact rationals (GMP): premultiplied "over" in double and float, the straight formula and
// the premultiplied one rounded to 8 bits after every step (what an 8-bit framebuffer keeps), and front to back
// with its early stop at two thresholds. The error is the largest channel error of the premultiplied result, in
// 1/255; the wrong count is the pixels whose 8-bit colour (straight, rounded) differs from the exact one's.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gmpxx.h>

#include "analysis/measurement.h"
#include "compositing/compositing.h"

namespace hsr::analysis {

namespace {

using algo::Rgba;

constexpr int layers_per_pixel = 8;

// Straight colours and alphas that an 8-bit image holds: k / 255.
std::vector<Rgba> random_stacks(std::size_t pixels, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> byte(0, 255), alpha(20, 235);
    std::vector<Rgba> layers(pixels * layers_per_pixel);
    for (Rgba& c : layers) c = {byte(rng) / 255.0, byte(rng) / 255.0, byte(rng) / 255.0, alpha(rng) / 255.0};
    return layers;
}

struct ExactRgba {
    mpq_class r, g, b, a;
};

// Back to front, premultiplied, exactly: the 8-bit inputs are the rationals k / 255 they stand for.
ExactRgba exact_composite(const Rgba* stack) {
    ExactRgba c{0, 0, 0, 0};
    for (int i = layers_per_pixel; i-- > 0;) {
        const auto q = [](double v) {
            mpq_class k(int(std::lround(v * 255)), 255);
            k.canonicalize();  // GMP's (num, den) constructor leaves it to us
            return k;
        };
        const mpq_class a = q(stack[i].a), k = 1 - a;
        c = {a * q(stack[i].r) + k * c.r, a * q(stack[i].g) + k * c.g, a * q(stack[i].b) + k * c.b, a + k * c.a};
    }
    return c;
}

double error_255(Rgba got, const ExactRgba& want) {
    const auto d = [](double g, const mpq_class& w) { return std::abs(g - w.get_d()) * 255; };
    return std::max({d(got.r, want.r), d(got.g, want.g), d(got.b, want.b), d(got.a, want.a)});
}

// The 8-bit straight colour a pixel shows (what an image file would hold), from a premultiplied composite.
std::array<int, 4> bytes_of(double r, double g, double b, double a) {
    const auto q = [](double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
    if (!(a > 0)) return {0, 0, 0, 0};
    return {q(r / a), q(g / a), q(b / a), q(a)};
}

double round8(double v) { return std::round(std::clamp(v, 0.0, 1.0) * 255) / 255; }
Rgba round8(Rgba c) { return {round8(c.r), round8(c.g), round8(c.b), round8(c.a)}; }

// One way of compositing a pixel's stack (nearest first), giving its premultiplied colour and the layers it used.
struct Method {
    std::string name;
    Rgba (*pixel)(const Rgba* stack, int& used);
};

Rgba back_to_front_double(const Rgba* s, int& used) {
    Rgba c;
    for (int i = layers_per_pixel; i-- > 0;) c = algo::over(algo::premultiply(s[i]), c);
    used = layers_per_pixel;
    return c;
}

Rgba back_to_front_float(const Rgba* s, int& used) {
    float r = 0, g = 0, b = 0, a = 0;
    for (int i = layers_per_pixel; i-- > 0;) {
        const float fa = float(s[i].a), k = 1 - fa;
        r = fa * float(s[i].r) + k * r, g = fa * float(s[i].g) + k * g, b = fa * float(s[i].b) + k * b, a = fa + k * a;
    }
    used = layers_per_pixel;
    return {r, g, b, a};
}

Rgba straight_8bit(const Rgba* s, int& used) {
    Rgba c;  // straight, rounded to 8 bits after every step
    for (int i = layers_per_pixel; i-- > 0;) c = round8(algo::over_straight(s[i], c));
    used = layers_per_pixel;
    return algo::premultiply(c);
}

Rgba premultiplied_8bit(const Rgba* s, int& used) {
    Rgba c;  // premultiplied, rounded to 8 bits after every step (the layer's own premultiplied colour too)
    for (int i = layers_per_pixel; i-- > 0;) c = round8(algo::over(round8(algo::premultiply(s[i])), c));
    used = layers_per_pixel;
    return c;
}

template <int per_mille>
Rgba front_to_back_stop(const Rgba* s, int& used) {
    Rgba c;
    used = 0;
    for (int i = 0; i < layers_per_pixel && c.a < per_mille / 1000.0; ++i, ++used) c = algo::over(c, algo::premultiply(s[i]));
    return c;
}

}  // namespace

std::vector<Measurement> measure_compositing(const ReportOptions& o) {
    const std::size_t pixels = o.quick ? 2000 : 50000;
    const std::vector<Rgba> stacks = random_stacks(pixels, 7);
    std::vector<ExactRgba> exact;
    exact.reserve(pixels);
    for (std::size_t p = 0; p < pixels; ++p) exact.push_back(exact_composite(&stacks[p * layers_per_pixel]));
    const std::vector<Method> methods = {
        {"premultiplied over, double, back to front", back_to_front_double},
        {"premultiplied over, float32, back to front", back_to_front_float},
        {"straight (the notes' formula), 8 bits per step", straight_8bit},
        {"premultiplied over, 8 bits per step", premultiplied_8bit},
        {"front to back (double), stop at α ≥ 0.99", front_to_back_stop<990>},
        {"front to back (double), stop at α ≥ 0.999", front_to_back_stop<999>},
    };
    plan_runs(o, int(methods.size()));
    std::vector<Measurement> rows;
    const std::string setting = std::to_string(pixels) + " pixels × " + std::to_string(layers_per_pixel) + " layers, 8-bit inputs";
    for (const Method& m : methods) {
        std::vector<Rgba> out(pixels);
        std::uint64_t used = 0;
        const double ms = median_ms(o, [&] {
            used = 0;
            for (std::size_t p = 0; p < pixels; ++p) {
                int u = 0;
                out[p] = m.pixel(&stacks[p * layers_per_pixel], u);
                used += std::uint64_t(u);
            }
        });
        double worst = 0;
        std::uint64_t wrong = 0;
        for (std::size_t p = 0; p < pixels; ++p) {
            worst = std::max(worst, error_255(out[p], exact[p]));
            const ExactRgba& e = exact[p];
            wrong += bytes_of(out[p].r, out[p].g, out[p].b, out[p].a) != bytes_of(e.r.get_d(), e.g.get_d(), e.b.get_d(), e.a.get_d());
        }
        char layers[64];
        std::snprintf(layers, sizeof layers, "%.2f layers composited per pixel", double(used) / double(pixels));
        rows.push_back({.family = "compositing", .method = m.name, .setting = setting, .median_ms = ms, .error = worst,
                        .error_name = "largest channel error against exact rationals (GMP), in 1/255",
                        .wrong = wrong, .wrong_name = "pixels whose 8-bit colour differs from the exact one's", .extra = layers});
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection compositing_report{measure_compositing, {{"compositing", "Alpha compositing: colour error against GMP rationals, per storage and order"}}};

}  // namespace hsr::analysis
