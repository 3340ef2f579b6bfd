// SPDX-License-Identifier: MIT
#include "perspective/perspective_transform.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/numeric.h"

namespace hsr::algo {
namespace {

glm::dmat4 scale(double x, double y, double z) { return glm::scale(glm::dmat4(1), Vec3(x, y, z)); }

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

ViewVolumeMaps view_volume_maps(const Camera& c) {
    ViewVolumeMaps m;
    m.perspective = c.projection == Projection::perspective;
    m.view = glm::lookAt(c.eye, c.target, c.up);
    m.start = scale(1 / c.far, 1 / c.far, 1 / c.far);
    if (!m.perspective) {  // the volume is a box already: stage 1 is the whole way, stage 2 has nothing to do
        m.normalize = scale(1, 1, -1) * glm::ortho(c.box[0], c.box[1], c.box[2], c.box[3], c.near, c.far);
        return m;
    }
    const double ty = std::tan(glm::radians(c.fov_y) / 2), tx = ty * c.aspect;
    m.normalize = scale(1 / (c.far * tx), 1 / (c.far * ty), 1 / c.far);
    // The canonical frustum (near at z = −n′, far at −1, n′ = near/far) into the box, with the picture's z = −z′:
    // z_c = (1 + n′)/(1 − n′)·z + 2n′/(1 − n′), w = −z (glm is column-major: m[column][row]).
    const double n = c.near / c.far;
    m.transform = glm::dmat4(0);
    m.transform[0][0] = 1, m.transform[1][1] = 1;
    m.transform[2][2] = (1 + n) / (1 - n), m.transform[3][2] = 2 * n / (1 - n);
    m.transform[2][3] = -1;
    return m;
}

std::optional<Vec3> warp(const ViewVolumeMaps& m, std::uint32_t stage, double s, Vec3 p) {
    const glm::dvec4 h(p, 1);
    if (stage == 0) return Vec3(m.start * h);
    if (stage == 1) return Vec3((1 - s) * (m.start * h) + s * (m.normalize * h));
    const glm::dvec4 q = m.normalize * h;
    const glm::dvec4 r = (1 - s) * q + s * (m.transform * q);
    if (!(r.w > 0)) return std::nullopt;
    return Vec3(r) / r.w;
}

std::vector<Vec3> view_volume_corners(const Camera& c) {
    std::vector<Vec3> corners;
    for (const double d : {c.near, c.far}) {
        double l = c.box[0], r = c.box[1], b = c.box[2], t = c.box[3];
        if (c.projection == Projection::perspective) {
            const double ty = std::tan(glm::radians(c.fov_y) / 2) * d, tx = ty * c.aspect;
            l = -tx, r = tx, b = -ty, t = ty;
        }
        corners.insert(corners.end(), {Vec3(l, b, -d), Vec3(r, b, -d), Vec3(r, t, -d), Vec3(l, t, -d)});
    }
    return corners;
}

bool same_coordinate(double u, double v, double tolerance) {
    return std::abs(u - v) <= tolerance * std::max({1.0, std::abs(u), std::abs(v)});
}

glm::dvec2 projector_ratios(Vec3 eye, bool perspective) {
    return perspective ? glm::dvec2(eye.x / eye.z, eye.y / eye.z) : glm::dvec2(eye.x, eye.y);
}

bool same_projector(glm::dvec2 a, glm::dvec2 b, double tolerance) {
    return same_coordinate(a.x, b.x, tolerance) && same_coordinate(a.y, b.y, tolerance);
}

Steps<TransformEvent, TransformResult> perspective_transform(Scene scene, TransformOptions options) {
    if (scene.coordinates != Coordinates::world) throw InvalidInput("the perspective transform needs a scene in world coordinates");
    if (scene.points.empty()) throw InvalidInput("the perspective transform compares the scene's [[points]]: it has none");
    const Camera& c = scene.camera;
    const bool perspective = c.projection == Projection::perspective;
    const ViewVolumeMaps maps = view_volume_maps(c);
    const glm::dmat4 projection = view_projection(c);
    const auto n = std::uint32_t(scene.points.size());
    co_yield VolumeShown{perspective, c.near, c.far, n};

    // The picture warps: the volume normalized, then (perspective) the frustum into the box.
    for (const double s : {0.5, 1.0}) co_yield WarpStep{1, s, perspective};
    if (perspective)
        for (const double s : {0.25, 0.5, 0.75, 1.0}) co_yield WarpStep{2, s, true};
    else
        co_yield WarpStep{2, 1.0, false};

    // Each point: to clip space, divided by w once.
    TransformResult result;
    result.ndc.resize(n), result.eye.resize(n);
    std::uint32_t left_out = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::dvec4 world = scene.points[i].p;
        const Vec3 eye = Vec3(maps.view * world);
        const glm::dvec4 clip = projection * world;
        result.eye[i] = eye;
        const Vec3 ndc = Vec3(clip) / clip.w;
        if (!(clip.w > 0) || !finite(eye) || !finite(ndc) || !finite(Vec3(projector_ratios(eye, perspective), 0))) {
            ++left_out;
            co_yield PointLeftOut{i, !(clip.w > 0) && finite(eye)};
            continue;
        }
        result.ndc[i] = ndc;
        co_yield PointTransformed{i, eye.x, eye.y, eye.z, clip.w, ndc.x, ndc.y, ndc.z};
    }

    // Every pair, both ways.
    std::uint32_t disagreements = 0;
    for (std::uint32_t a = 0; a < n && !result.bounded; ++a) {
        if (!result.ndc[a]) continue;
        for (std::uint32_t b = a + 1; b < n; ++b) {
            if (!result.ndc[b]) continue;
            if (result.comparisons == options.max_comparisons) {
                result.bounded = true;
                break;
            }
            ++result.comparisons;
            const Vec3 &ea = result.eye[a], &eb = result.eye[b], &pa = *result.ndc[a], &pb = *result.ndc[b];
            const glm::dvec2 ra = projector_ratios(ea, perspective), rb = projector_ratios(eb, perspective);  // 4 divisions
            const bool before = same_projector(ra, rb, options.tolerance);
            const bool after = same_projector(glm::dvec2(pa), glm::dvec2(pb), options.tolerance);
            const std::int32_t nearer = pa.z < pb.z ? std::int32_t(a) : pb.z < pa.z ? std::int32_t(b) : -1;
            disagreements += before != after;
            if (after) result.occluding.push_back(nearer == std::int32_t(b) ? std::pair(b, a) : std::pair(a, b));  // nearer first
            co_yield PairCompared{a, b, ra.x, ra.y, rb.x, rb.y, before, after, nearer};
        }
    }
    const std::uint32_t kept = n - left_out;
    const std::uint64_t divisions_before = perspective ? 4 * result.comparisons : 0;
    co_yield TransformFinished{n, left_out, std::uint32_t(result.occluding.size()), result.comparisons, divisions_before,
                               3 * std::uint64_t(kept), disagreements, result.bounded};
    co_return result;
}

}  // namespace hsr::algo
