// SPDX-License-Identifier: MIT
#include "bsp/bsp_scene.h"

namespace hsr::algo {
namespace {

Steps<BspEvent, std::vector<BspPolygonId>> bsp_scene_machine(Steps<BspEvent, BspTree> build, Viewpoint eye, Order order) {
    for (const auto& e : build) co_yield e;
    const BspTree tree = std::move(build).result();  // owned by this frame while the traversal runs
    auto display = traverse_bsp(&tree, eye, order);
    for (const auto& e : display) co_yield e;
    co_return std::move(display).result();
}

}  // namespace

Viewpoint viewpoint_of(const Camera& camera) {
    if (camera.projection == Projection::orthographic) return Viewpoint::at_infinity(camera.eye, camera.eye - camera.target);
    return camera.eye;
}

BspJob bsp_job(const Scene& scene, SplitterRule rule) {
    BspJob job;
    job.options.splitter = rule;
    job.eye = viewpoint_of(scene.camera);
    for (const auto& p : scene.polygons) {
        BspInput in{p.id, {}};
        for (const auto& v : p.vertices) in.vertices.emplace_back(v);
        job.polygons.push_back(std::move(in));
    }
    if (job.polygons.empty()) {
        for (const auto& s : scene.segments) job.polygons.push_back({s.id, {{s.a.x, s.a.y, 0}, {s.b.x, s.b.y, 0}}});
        job.eye = Vec3(scene.camera.eye.x, scene.camera.eye.y, 0);  // the eye stands in the plan
    }
    return job;
}

Steps<BspEvent, std::vector<BspPolygonId>> bsp_scene(BspJob job) {
    auto build = build_bsp(std::move(job.polygons), job.options);  // validates now: InvalidInput names the polygon
    return bsp_scene_machine(std::move(build), job.eye, job.order);
}

}  // namespace hsr::algo
