#include "bsp/bsp_scene.h"

namespace hsr::algo {
namespace {

Steps<BspEvent, std::vector<BspPolygonId>> bsp_scene_machine(Steps<BspEvent, BspTree> build, Vec3 eye) {
    for (const auto& e : build) co_yield e;
    const BspTree tree = std::move(build).result();  // owned by this frame while the traversal runs
    auto display = traverse_bsp(&tree, eye);
    for (const auto& e : display) co_yield e;
    co_return std::move(display).result();
}

}  // namespace

BspJob bsp_job(const Scene& scene, SplitterRule rule) {
    BspJob job;
    job.options.splitter = rule;
    job.eye = scene.camera.eye;
    for (const auto& p : scene.polygons) {
        BspInput in{p.id, {}};
        for (const auto& v : p.vertices) in.vertices.emplace_back(v);
        job.polygons.push_back(std::move(in));
    }
    if (job.polygons.empty()) {
        for (const auto& s : scene.segments) job.polygons.push_back({s.id, {{s.a.x, s.a.y, 0}, {s.b.x, s.b.y, 0}}});
        job.eye.z = 0;
    }
    return job;
}

Steps<BspEvent, std::vector<BspPolygonId>> bsp_scene(BspJob job) {
    auto build = build_bsp(std::move(job.polygons), job.options);  // validates now: InvalidInput names the polygon
    return bsp_scene_machine(std::move(build), job.eye);
}

}  // namespace hsr::algo
