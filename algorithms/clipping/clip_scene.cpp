// SPDX-License-Identifier: MIT
#include "clipping/clip_scene.h"

#include "clipping/cohen_sutherland.h"
#include "clipping/liang_barsky.h"
#include "clipping/point_clip.h"
#include "clipping/sutherland_hodgman.h"

namespace hsr::algo {
namespace {

Steps<ClipEvent, std::vector<PrimitiveClip>> clip_scene_machine(ClipJob job, ClipAlgorithm algorithm,
                                                                 ClipOptions o) {
    std::vector<PrimitiveClip> answers;
    for (const ClipPoint& point : job.points) {
        auto machine = clip_point(point, o);
        for (const auto& e : machine) co_yield e;
        const bool kept = machine.result();
        answers.push_back({point.id, kept ? ClipOutcome::inside : ClipOutcome::rejected,
                           kept ? std::vector<Vec4>{point.p} : std::vector<Vec4>{}});
    }
    if (algorithm != ClipAlgorithm::sutherland_hodgman) {
        for (const ClipSegment& segment : job.segments) {
            auto machine = algorithm == ClipAlgorithm::cohen_sutherland ? cohen_sutherland(segment, o)
                                                                        : liang_barsky(segment, o);
            for (const auto& e : machine) co_yield e;
            const SegmentClip& c = machine.result();
            answers.push_back({segment.id, c.outcome,
                               c.outcome == ClipOutcome::rejected ? std::vector<Vec4>{} : std::vector<Vec4>{c.a, c.b},
                               c.bounded});
        }
    } else {
        for (ClipPolygon& polygon : job.polygons) {
            const PrimitiveId id = polygon.id;
            auto machine = sutherland_hodgman(std::move(polygon), o);
            for (const auto& e : machine) co_yield e;
            const PolygonClip& c = machine.result();
            answers.push_back({id, c.outcome, c.vertices, c.bounded});
        }
    }
    co_return answers;
}

}  // namespace

ClipJob clip_job(const Scene& scene) {
    ClipJob job;
    job.space = scene.camera.projection == Projection::orthographic ? ClipSpace::cube : ClipSpace::homogeneous;
    for (const auto& p : scene.points) job.points.push_back({p.id, to_clip(scene, p.p)});
    for (const auto& s : scene.segments) job.segments.push_back({s.id, to_clip(scene, s.a), to_clip(scene, s.b)});
    for (const auto& p : scene.polygons) {
        ClipPolygon c{p.id, {}};
        for (const auto& v : p.vertices) c.vertices.push_back(to_clip(scene, v));
        job.polygons.push_back(std::move(c));
    }
    return job;
}

Steps<ClipEvent, std::vector<PrimitiveClip>> clip_scene(ClipJob job, ClipAlgorithm algorithm, ClipOptions options) {
    options.space = job.space;
    for (const auto& p : job.points) require_clippable(p);
    for (const auto& s : job.segments) require_clippable(s);
    for (const auto& p : job.polygons) require_clippable(p);
    return clip_scene_machine(std::move(job), algorithm, options);
}

}  // namespace hsr::algo
