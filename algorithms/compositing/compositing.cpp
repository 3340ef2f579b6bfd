// SPDX-License-Identifier: MIT
#include "compositing/compositing.h"

#include <algorithm>

#include "core/plane.h"

namespace hsr::algo {

Rgba premultiply(Rgba c) { return {c.a * c.r, c.a * c.g, c.a * c.b, c.a}; }

Rgba unpremultiply(Rgba p) {
    if (!(p.a > 0)) return {};
    return {p.r / p.a, p.g / p.a, p.b / p.a, p.a};
}

Rgba over(Rgba f, Rgba b) {
    const double k = 1 - f.a;
    return {f.r + k * b.r, f.g + k * b.g, f.b + k * b.b, f.a + k * b.a};
}

Rgba over_straight(Rgba f, Rgba b) {
    const double a = f.a + (1 - f.a) * b.a;  // A′
    if (!(a > 0)) return {};                  // both clear: nothing to divide (and nothing to see)
    const auto mix = [&](double cf, double cb) { return (cf * f.a + (1 - f.a) * cb * b.a) / a; };
    return {mix(f.r, b.r), mix(f.g, b.g), mix(f.b, b.b), a};
}

Rgba blend_naive(Rgba f, Rgba b) {
    const auto mix = [&](double cf, double cb) { return f.a * cf + (1 - f.a) * cb; };
    return {mix(f.r, b.r), mix(f.g, b.g), mix(f.b, b.b), f.a + (1 - f.a) * b.a};
}

Factors porter_duff_factors(PorterDuff op, double aa, double ab) {
    switch (op) {
        case PorterDuff::clear: return {0, 0};
        case PorterDuff::a: return {1, 0};
        case PorterDuff::b: return {0, 1};
        case PorterDuff::over: return {1, 1 - aa};
        case PorterDuff::in: return {ab, 0};
        case PorterDuff::out: return {1 - ab, 0};
        case PorterDuff::atop: return {ab, 1 - aa};
        case PorterDuff::xor_: return {1 - ab, 1 - aa};
        case PorterDuff::plus: return {1, 1};
    }
    return {0, 0};
}

Rgba porter_duff(PorterDuff op, Rgba a, Rgba b) {
    const Factors f = porter_duff_factors(op, a.a, b.a);
    // plus may sum past 1: the paper clamps
    const auto mix = [&](double ca, double cb) { return std::min(1.0, f.a * ca + f.b * cb); };
    return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b), mix(a.a, b.a)};
}

std::span<const PorterDuff> porter_duff_operators() {
    static constexpr PorterDuff ops[] = {PorterDuff::clear, PorterDuff::a,    PorterDuff::b,    PorterDuff::over, PorterDuff::in,
                                         PorterDuff::out,   PorterDuff::atop, PorterDuff::xor_, PorterDuff::plus};
    return ops;
}

Ray centre_ray(const Camera& camera) { return {camera.eye, camera.target - camera.eye}; }

std::vector<Layer> layers_along(const Scene& scene, const Ray& ray) {
    std::vector<Layer> layers;
    for (const ScenePolygon& p : scene.polygons) {
        std::vector<Vec3> v;
        for (const auto& q : p.vertices) v.emplace_back(q);
        if (v.size() < 3) continue;
        Plane plane;
        if (!plane_of(v, plane)) continue;  // no area: nothing to pass through
        if (const auto t = hit(ray, v, plane))
            layers.push_back({p.id, {p.color.r / 255.0, p.color.g / 255.0, p.color.b / 255.0, std::clamp(p.opacity, 0.0, 1.0)}, *t});
    }
    std::stable_sort(layers.begin(), layers.end(), [](const Layer& a, const Layer& b) { return a.t < b.t; });
    return layers;
}

Steps<CompositeEvent, CompositeResult> composite(std::vector<Layer> layers, CompositeOptions o) {
    CompositeResult result;
    const auto n = std::uint32_t(layers.size());
    co_yield LayersFound{n};
    std::vector<Rgba> pre(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        pre[i] = premultiply(layers[i].colour);
        co_yield LayerPremultiplied{i, layers[i].id, layers[i].colour, pre[i], pre[i].a};
    }
    // Back to front: each layer over what lies behind it
    Rgba c, straight;
    for (std::uint32_t i = n; i-- > 0;) {
        const Rgba before = c, straight_before = straight;
        c = over(pre[i], c);
        straight = over_straight(layers[i].colour, straight);
        co_yield OverApplied{i, layers[i].id, before, pre[i], c, straight_before, straight, c.a};
    }
    result.back_to_front = c, result.straight = straight;
    // Front to back: each layer under what lies in front of it, until nothing behind can show
    Rgba f;
    std::uint32_t i = 0;
    for (; i < n; ++i) {
        if (f.a >= o.opaque_enough) {
            co_yield EarlyStop{i, f.a, n - i};
            break;
        }
        const Rgba before = f;
        f = over(f, pre[i]);
        co_yield UnderApplied{i, layers[i].id, before, pre[i], f, f.a};
    }
    result.front_to_back = f, result.front_to_back_layers = i;
    const double difference = max_difference(c, f);
    co_yield OrdersCompared{c, f, difference, difference <= 1e-9};
    // Associativity on the three nearest layers
    if (n >= 3) {
        const Rgba left = over(over(pre[0], pre[1]), pre[2]), right = over(pre[0], over(pre[1], pre[2]));
        const Rgba &s0 = layers[0].colour, &s1 = layers[1].colour, &s2 = layers[2].colour;
        const Rgba naive_left = blend_naive(blend_naive(s0, s1), s2), naive_right = blend_naive(s0, blend_naive(s1, s2));
        const double d = max_difference(left, right), dn = max_difference(naive_left, naive_right);
        co_yield AssociativityChecked{left, right, naive_left, naive_right, d, dn, d <= 1e-9, dn <= 1e-9};
    }
    // Porter and Duff's operators on the two nearest
    if (n >= 2)
        for (const PorterDuff op : porter_duff_operators()) {
            const Factors k = porter_duff_factors(op, pre[0].a, pre[1].a);
            const Rgba r = porter_duff(op, pre[0], pre[1]);
            co_yield PorterDuffApplied{op, pre[0], pre[1], k.a, k.b, r, r.a};
        }
    co_yield CompositeFinished{c, unpremultiply(c)};
    co_return result;
}

}  // namespace hsr::algo
