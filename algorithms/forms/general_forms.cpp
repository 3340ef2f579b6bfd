// SPDX-License-Identifier: MIT
#include "forms/general_forms.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/numeric.h"
#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

glm::dvec2 PlanCamera::to_camera(glm::dvec2 w) const {
    const glm::dvec2 d = w - eye;
    return {glm::dot(d, right), glm::dot(d, forward)};
}
glm::dvec2 PlanCamera::to_world(glm::dvec2 c) const { return eye + c.x * right + c.y * forward; }

double PlanCamera::image_u(glm::dvec2 c) const {
    if (perspective) return c.x / (tan_half * c.y);
    return (2 * c.x - (left + right_edge)) / (right_edge - left);
}

double PlanCamera::pixel_centre(std::uint32_t pixel, std::uint32_t pixels) const {
    return -1 + (2 * double(pixel) + 1) / double(pixels);
}

glm::dvec2 PlanCamera::projector_origin(double u) const {
    if (perspective) return {0, 0};
    return {left + (u + 1) / 2 * (right_edge - left), 0};
}
glm::dvec2 PlanCamera::projector_direction(double u) const { return perspective ? glm::dvec2(u * tan_half, 1) : glm::dvec2(0, 1); }

PlanCamera plan_camera(const Camera& c) {
    PlanCamera p;
    p.perspective = c.projection == Projection::perspective;
    p.eye = glm::dvec2(c.eye);
    const glm::dvec2 look = glm::dvec2(c.target) - p.eye;
    if (!(glm::length(look) > 0) || !std::isfinite(glm::length(look)))
        throw InvalidInput("camera: the eye and the target must be apart in the plane z = 0");
    p.forward = glm::normalize(look);
    p.right = {p.forward.y, -p.forward.x};  // looking along +y, the image's right is +x
    if (!(c.near > 0) || !(c.far > c.near) || !std::isfinite(c.far)) throw InvalidInput("camera: need 0 < near < far");
    p.near = c.near, p.far = c.far;
    if (p.perspective) {
        if (!(c.fov_y > 0 && c.fov_y < 180)) throw InvalidInput("camera.fov: must lie between 0 and 180 degrees");
        p.tan_half = std::tan(c.fov_y * std::numbers::pi / 360);
    } else {
        p.left = c.box[0], p.right_edge = c.box[1];
        if (!(p.right_edge > p.left)) throw InvalidInput("camera.box: right must be greater than left");
    }
    return p;
}

double PrimitiveImage::nearness(double u) const {
    if (u <= from) return g_from;
    if (u >= to) return g_to;
    return g_from + (g_to - g_from) * ((u - from) / (to - from));
}
double PrimitiveImage::depth(double u, bool perspective) const {
    const double g = nearness(u);
    return perspective ? 1 / g : -g;
}

std::optional<PrimitiveImage> image_of(const PlanCamera& c, glm::dvec2 a, glm::dvec2 b) {
    if (!finite(a) || !finite(b)) return std::nullopt;
    // Liang–Barsky against the half-planes f(p) ≥ 0 that bound the view: near, far, left, right.
    const auto f = [&](int k, glm::dvec2 p) {
        switch (k) {
            case 0: return p.y - c.near;
            case 1: return c.far - p.y;
            case 2: return c.perspective ? p.x + c.tan_half * p.y : p.x - c.left;
            default: return c.perspective ? c.tan_half * p.y - p.x : c.right_edge - p.x;
        }
    };
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 4; ++k) {
        const double fa = f(k, a), fb = f(k, b);
        if (!std::isfinite(fa) || !std::isfinite(fb)) return std::nullopt;
        if (fa < 0 && fb < 0) return std::nullopt;
        if (fa >= 0 && fb >= 0) continue;
        const double t = fa / (fa - fb);
        if (fa < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
    }
    if (!(t0 < t1)) return std::nullopt;
    PrimitiveImage im;
    im.a = a + t0 * (b - a), im.b = a + t1 * (b - a);
    double ua = c.image_u(im.a), ub = c.image_u(im.b);
    if (ub < ua) std::swap(ua, ub), std::swap(im.a, im.b);
    if (!(ub > ua) || !std::isfinite(ua) || !std::isfinite(ub)) return std::nullopt;  // edge-on: no width on the image
    im.from = std::max(ua, -1.0), im.to = std::min(ub, 1.0);  // rounding may step a hair past the edges
    const auto g = [&](glm::dvec2 p) { return c.perspective ? 1 / p.y : -p.y; };
    // g at the (clamped) ends, from the line through a and b: linear in u
    const double ga = g(im.a), gb = g(im.b);
    im.g_from = ga + (gb - ga) * ((im.from - ua) / (ub - ua));
    im.g_to = ga + (gb - ga) * ((im.to - ua) / (ub - ua));
    if (!(im.to > im.from) || !std::isfinite(im.g_from) || !std::isfinite(im.g_to)) return std::nullopt;
    return im;
}

Hidden hidden_by(const PrimitiveImage& p, const PrimitiveImage& o, bool other_first) {
    const double lo = std::max(p.from, o.from), hi = std::min(p.to, o.to);
    if (!(lo < hi)) return {};
    // d > 0 where the other is nearer; d is linear in u over the overlap
    const double d_lo = o.nearness(lo) - p.nearness(lo), d_hi = o.nearness(hi) - p.nearness(hi);
    if (d_lo == 0 && d_hi == 0) return other_first ? Hidden{true, lo, hi} : Hidden{true, lo, lo};  // one line: a tie
    if (d_lo >= 0 && d_hi >= 0) return {true, lo, hi};
    if (d_lo <= 0 && d_hi <= 0) return {true, lo, lo};
    const double crossing = std::clamp(lo + (hi - lo) * (d_lo / (d_lo - d_hi)), lo, hi);  // they pierce each other
    return d_lo > 0 ? Hidden{true, lo, crossing} : Hidden{true, crossing, hi};
}

std::vector<glm::dvec2> subtract(double from, double to, std::vector<glm::dvec2> removed) {
    std::sort(removed.begin(), removed.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x; });
    std::vector<glm::dvec2> left;
    double at = from;  // everything before `at` is decided
    for (const glm::dvec2 r : removed) {
        if (!(r.y > r.x)) continue;  // empty
        if (r.x > at) left.emplace_back(at, std::min(r.x, to));
        at = std::max(at, r.y);
        if (at >= to) break;
    }
    if (at < to) left.emplace_back(at, to);
    std::erase_if(left, [](glm::dvec2 i) { return !(i.y > i.x); });
    return left;
}

std::optional<double> projector_hit(const PlanCamera& c, double u, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 o = c.projector_origin(u), d = c.projector_direction(u), e = b - a, w = a - o;
    const double det = cross(d, e);
    if (det == 0 || !std::isfinite(det)) return std::nullopt;  // the projector runs along the segment
    const double t = cross(w, e) / det, s = cross(w, d) / det;
    if (!(s >= 0 && s <= 1) || !(t >= c.near && t <= c.far)) return std::nullopt;
    return t;  // d has z = 1: t is the depth
}

Steps<FormsEvent, FormsResult> general_forms(Scene scene, FormsOptions options) {
    if (scene.segments.empty()) throw InvalidInput("the general forms compare the scene's [[segments]] (a floor plan): it has none");
    if (options.pixels < 1 || options.pixels > 4096) throw InvalidInput("grid: the image's width must be 1 … 4096 pixels");
    const PlanCamera camera = plan_camera(scene.camera);
    const auto n = std::uint32_t(scene.segments.size());
    const std::uint32_t p = options.pixels;
    co_yield FormsShown{n, p, camera.perspective};

    // Each primitive's image on the line u (the frustum culling every form starts with).
    std::vector<glm::dvec2> cam_a(n), cam_b(n);
    std::vector<std::optional<PrimitiveImage>> images(n);
    std::vector<std::uint32_t> in_view;
    for (std::uint32_t i = 0; i < n; ++i) {
        const SceneSegment& s = scene.segments[i];
        cam_a[i] = camera.to_camera(glm::dvec2(s.a)), cam_b[i] = camera.to_camera(glm::dvec2(s.b));
        images[i] = image_of(camera, cam_a[i], cam_b[i]);
        if (images[i]) in_view.push_back(i);
        co_yield PrimitiveProjected{i, s.id, images[i].has_value(), images[i] ? images[i]->from : 0, images[i] ? images[i]->to : 0};
    }

    FormsResult result;
    result.object_image.assign(p, -1), result.image_image.assign(p, -1);
    const auto out_of_steps = [&] { return result.comparisons + result.tests >= options.max_steps; };

    // Object space: for each primitive, find its visible part against all others, then render it.
    for (const std::uint32_t i : in_view) {
        if (result.bounded) break;
        std::vector<glm::dvec2> hidden;
        for (const std::uint32_t j : in_view) {
            if (j == i) continue;
            if (out_of_steps()) {
                result.bounded = true;
                break;
            }
            ++result.comparisons;
            const Hidden h = hidden_by(*images[i], *images[j], j < i);
            if (h.to > h.from) hidden.emplace_back(h.from, h.to);
            co_yield PrimitivesCompared{i, j, scene.segments[i].id, scene.segments[j].id, h.overlap, h.to > h.from, h.from, h.to};
        }
        if (result.bounded) break;
        const PrimitiveImage& im = *images[i];
        const std::vector<glm::dvec2> parts = subtract(im.from, im.to, hidden);
        double visible = 0;
        for (const glm::dvec2 part : parts) visible += part.y - part.x;
        const FormsEvent found = VisiblePartFound{i, scene.segments[i].id, parts, visible / (im.to - im.from)};
        co_yield found;
        if (parts.empty()) continue;  // hidden whole: nothing to render
        std::vector<std::uint32_t> pixels;
        for (std::uint32_t k = 0; k < p; ++k) {
            const double u = camera.pixel_centre(k, p);
            for (const glm::dvec2 part : parts)
                if (u >= part.x && u < part.y) {  // half-open: a pixel centre on a shared end goes to one side only
                    result.object_image[k] = std::int32_t(i);
                    pixels.push_back(k);
                    break;
                }
        }
        const FormsEvent rendered = PartRendered{i, scene.segments[i].id, std::move(pixels)};
        co_yield rendered;
    }

    // Image space: for each pixel, find the closest primitive along its projector, then render the pixel.
    for (std::uint32_t k = 0; k < p && !result.bounded; ++k) {
        const double u = camera.pixel_centre(k, p);
        std::int32_t closest = -1;
        double closest_depth = 0;
        for (const std::uint32_t j : in_view) {
            if (out_of_steps()) {
                result.bounded = true;
                break;
            }
            ++result.tests;
            const std::optional<double> depth = projector_hit(camera, u, cam_a[j], cam_b[j]);
            const bool nearer = depth && (closest < 0 || *depth < closest_depth);  // a tie keeps the first
            if (nearer) closest = std::int32_t(j), closest_depth = *depth;
            co_yield ProjectorTested{k, j, scene.segments[j].id, depth.has_value(), depth.value_or(0), nearer};
        }
        if (result.bounded) break;
        result.image_image[k] = closest;
        co_yield PixelRendered{k, closest, closest < 0 ? -1 : scene.segments[std::size_t(closest)].id, closest < 0 ? 0 : closest_depth};
    }

    std::uint32_t differing = 0;
    for (std::uint32_t k = 0; k < p; ++k) differing += result.object_image[k] != result.image_image[k];
    co_yield FormsFinished{n, std::uint32_t(in_view.size()), p, result.comparisons, result.tests, result.bounded ? 0 : differing, result.bounded};
    co_return result;
}

}  // namespace hsr::algo
