// SPDX-License-Identifier: MIT
// [SECTION] the world and the view
// [SECTION] each machine's pseudocode, lines and steps
// [SECTION] the sessions
#include "state/culling_session.h"

#include <algorithm>

#include "core/overloaded.h"
#include "culling/bounding_volume.h"
#include "culling/view_frustum.h"
#include "scene/generated_scenes.h"
#include "state/long_work.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

void mark_subtree(CullingView& v, std::uint32_t node, NodeMark mark, PrimitiveMark prims) {
    const Hierarchy& h = v.world->hierarchy;
    std::vector<std::uint32_t> stack{node};
    while (!stack.empty()) {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        v.nodes[n] = mark;
        for (std::uint32_t p : h.nodes[n].primitives)
            if (v.primitives[p] != PrimitiveMark::earlier) v.primitives[p] = prims;
        for (std::uint32_t c : h.nodes[n].children) stack.push_back(c);
    }
}

void count(CullingView& v) {
    v.kept = std::uint32_t(std::count(v.primitives.begin(), v.primitives.end(), PrimitiveMark::kept));
    v.left_out = std::uint32_t(std::count(v.primitives.begin(), v.primitives.end(), PrimitiveMark::left_out));
    v.earlier = std::uint32_t(std::count(v.primitives.begin(), v.primitives.end(), PrimitiveMark::earlier));
}

// The scene's objects and the void space of each one's box, sphere and OBB (see SceneObject).
std::vector<SceneObject> scene_objects(const Scene& scene) {
    if (scene.polygons.size() > 20000) return {};  // not worth joining: a scene of many objects
    std::vector<std::vector<Vec3>> polygons;
    for (const auto& p : scene.polygons) {
        std::vector<Vec3> w;
        for (const auto& q : p.vertices) w.emplace_back(q);
        polygons.push_back(std::move(w));
    }
    const auto groups = connected_objects(polygons);
    if (groups.size() > 12) return {};
    std::vector<SceneObject> out;
    for (const std::vector<std::size_t>& group : groups) {
        std::vector<std::vector<Vec3>> faces;
        std::vector<Vec3> points;
        for (std::size_t k : group) {
            faces.push_back(polygons[k]);
            points.insert(points.end(), polygons[k].begin(), polygons[k].end());
        }
        Vec3 sum(0);
        for (const Vec3& q : points) sum += q;
        const double volume = enclosed_volume(faces);
        out.push_back({std::to_string(scene.polygons[group.front()].id) + "–" + std::to_string(scene.polygons[group.back()].id), group,
                       glm::vec3(sum / double(std::max<std::size_t>(points.size(), 1))), void_fraction(aabb_of(points).volume(), volume),
                       void_fraction(sphere_of(points).volume(), volume), void_fraction(obb_of(points, face_normals(faces)).volume(), volume)});
    }
    return out;
}

}  // namespace

// ── [SECTION] the world and the view ────────────────────────────────────────────────────────────────────────
OcclusionOptions occlusion_options(const Lesson& lesson) {
    OcclusionOptions o{.max_occluders = 8, .fusion = lesson.fusion};
    for (const OccluderKind k : {OccluderKind::planar, OccluderKind::proxy, OccluderKind::solid})
        if (lesson.occluder == to_string(k)) o.kind = k;
    return o;
}

std::shared_ptr<const CullingWorld> culling_world(const Lesson& lesson) {
    auto w = std::make_shared<CullingWorld>();
    w->machine = machine_of<CullingMachine>(lesson);
    w->scene = lesson.scene;
    w->scene.camera.aspect = double(lesson.grid.width) / double(lesson.grid.height);
    const HierarchyKind kind = machine_of<CullingMachine>(lesson) == CullingMachine::bounds ? HierarchyKind::bvh : HierarchyKind::octree;
    w->hierarchy = LongWork::run_to_end(build_hierarchy(polygon_boxes(w->scene), {.kind = kind}));
    w->zbuffer = zbuffer_options(w->scene, lesson.grid, lesson.depth_format, EventDetail::polygon);
    w->detail_pixels = 4;
    w->frustum = view_frustum(w->scene.camera);
    const OcclusionOptions occlusion = occlusion_options(lesson);
    w->occluders = occlusion.kind, w->fusion = occlusion.fusion;
    w->pipeline = run_pipeline(w->scene, {.stages = parse_stages(lesson.cull), .viewport = lesson.grid, .hierarchy = kind,
                                          .detail_pixels = w->detail_pixels, .max_occluders = occlusion.max_occluders,
                                          .occluders = occlusion.kind, .fusion = occlusion.fusion})
                      .stages;
    // the stage the lesson's machine is: it starts from what the stages before it kept
    const std::optional<Stage> stage = [&]() -> std::optional<Stage> {
        switch (machine_of<CullingMachine>(lesson)) {
            case CullingMachine::frustum: return Stage::frustum;
            case CullingMachine::detail: return Stage::detail;
            case CullingMachine::occluders: return Stage::occluders;
            case CullingMachine::hiz: return Stage::hiz;
            case CullingMachine::bounds: break;
        }
        return std::nullopt;
    }();
    for (const StageReport& r : w->pipeline)
        if (stage && r.stage == *stage) w->candidates = r.candidates;
    if (w->machine == CullingMachine::bounds) w->objects = scene_objects(w->scene);
    return w;
}

std::vector<std::uint32_t> rendered_depth(const CullingView& v) {
    const ZBufferOptions& o = v.world->zbuffer;
    FrameDepth f = cleared_buffers(o);
    for (std::uint32_t p : v.rendered) {
        const auto& poly = v.world->scene.polygons[p];
        std::vector<glm::dvec4> clip;
        for (const auto& q : poly.vertices) clip.push_back(to_clip(v.world->scene, q));
        fill_polygon(f, project_polygon(poly.id, poly.color, std::move(clip), o.viewport), std::int32_t(p), o);
    }
    return std::move(f.depth);
}

std::size_t approx_bytes(const CullingView& v) {
    std::size_t outlines = 0;
    for (const auto& o : v.occluders) outlines += sizeof(o) + o.outline.capacity() * sizeof(Vec3);
    return sizeof(CullingView) + v.nodes.capacity() + v.primitives.capacity() + outlines + v.rendered.capacity() * 4;
}

void reduce(CullingView& v, const HierarchyEvent& event) {
    std::visit(overloaded{
                   [&](const HierarchyNodeBuilt& e) {
                       v.nodes[e.node] = NodeMark::built, v.current = std::int32_t(e.node);
                       ++v.built, v.leaves += e.leaf != LeafReason::not_a_leaf;
                   },
                   [&](const HierarchyBuilt&) { v.done = true, v.current = -1; },
               },
               event);
}

void reduce(CullingView& v, const HierarchyCullEvent& event) {
    std::visit(overloaded{
                   [&](const NodeCulled& e) {
                       v.current = std::int32_t(e.node), v.plane_tests += e.planes_tested + e.primitive_tests;
                       switch (e.outcome) {
                           case NodeOutcome::outside: mark_subtree(v, e.node, NodeMark::outside, PrimitiveMark::left_out); break;
                           case NodeOutcome::too_small: mark_subtree(v, e.node, NodeMark::too_small, PrimitiveMark::left_out); break;
                           case NodeOutcome::inside:
                           case NodeOutcome::partial:
                           case NodeOutcome::large_enough: {
                               v.nodes[e.node] = e.outcome == NodeOutcome::inside    ? NodeMark::inside
                                                 : e.outcome == NodeOutcome::partial ? NodeMark::partial
                                                                                     : NodeMark::large_enough;
                               const auto& node = v.world->hierarchy.nodes[e.node];
                               // its own primitives: kept unless their boxes fail a plane still to test
                               for (std::uint32_t p : node.primitives)
                                   if (v.primitives[p] != PrimitiveMark::earlier)
                                       v.primitives[p] = box_passes(v.world->hierarchy.boxes[p], v.world->frustum, e.mask_after)
                                                         ? PrimitiveMark::kept
                                                         : PrimitiveMark::left_out;
                               break;
                           }
                       }
                       count(v);
                   },
                   [&](const HierarchyCullFinished&) {
                       v.done = true, v.current = -1;
                       for (auto& p : v.primitives)  // what an accepted subtree held without a visit
                           if (p == PrimitiveMark::untouched) p = PrimitiveMark::kept;
                       count(v);
                   },
               },
               event);
}

void reduce(CullingView& v, const OcclusionEvent& event) {
    std::visit(overloaded{
                   [&](const OccluderChosen& e) { v.occluders.push_back({e.outline, e.shape, e.polygon, e.faces}); },
                   [&](const OcclusionTested& e) {
                       const std::uint32_t left_out_before = v.left_out;
                       if (e.node >= 0) {
                           v.current = e.node, v.primitive = -1;
                           if (e.outcome == OcclusionOutcome::occluded) mark_subtree(v, std::uint32_t(e.node), NodeMark::occluded, PrimitiveMark::left_out);
                           else v.nodes[std::size_t(e.node)] = e.outcome == OcclusionOutcome::partly ? NodeMark::partial : NodeMark::visible;
                       } else {
                           v.primitive = e.primitive;
                           v.primitives[std::size_t(e.primitive)] = e.outcome == OcclusionOutcome::occluded ? PrimitiveMark::left_out : PrimitiveMark::kept;
                       }
                       count(v);
                       if (e.fused) v.fused += v.left_out - left_out_before;  // what fusion culled, no single occluder
                   },
                   [&](const OcclusionFinished&) {
                       v.done = true, v.current = -1, v.primitive = -1;
                       for (auto& p : v.primitives)
                           if (p == PrimitiveMark::untouched) p = PrimitiveMark::kept;
                       count(v);
                   },
               },
               event);
}

void reduce(CullingView& v, const HizEvent& event) {
    std::visit(overloaded{
                   [&](const HizNodeTested& e) {
                       v.current = std::int32_t(e.node), v.texels += e.texels_tested;
                       if (e.outcome == HizOutcome::rendered) {
                           v.nodes[e.node] = NodeMark::visible;
                           for (std::uint32_t p : v.world->hierarchy.nodes[e.node].primitives) {
                               if (v.primitives[p] == PrimitiveMark::earlier) continue;  // as the machine skips it
                               v.primitives[p] = PrimitiveMark::kept;
                               v.rendered.push_back(p);
                           }
                       } else {
                           mark_subtree(v, e.node, e.outcome == HizOutcome::occluded ? NodeMark::occluded : NodeMark::outside, PrimitiveMark::left_out);
                       }
                       count(v);
                   },
                   [&](const HizFinished&) { v.done = true, v.current = -1; },
               },
               event);
}

std::vector<ShownBox> shown_boxes(const CullingView& v) {
    const Hierarchy& h = v.world->hierarchy;
    std::vector<ShownBox> out;
    if (h.nodes.empty()) return out;
    const auto touched = [&](std::size_t n) { return v.nodes[n] != NodeMark::untouched; };
    const auto decided_whole = [&](std::size_t n) {  // it stands for its subtree
        const NodeMark m = v.nodes[n];
        const bool passed_whole = m == NodeMark::visible && v.world->machine == CullingMachine::occluders;  // Hi-Z tests its children
        return m == NodeMark::outside || m == NodeMark::inside || m == NodeMark::too_small || m == NodeMark::occluded || passed_whole;
    };
    if (v.done) {  // where the traversal stopped, but not the frustum's rejections
        for (std::size_t n = 0; n < h.nodes.size(); ++n) {
            if (!touched(n) || v.nodes[n] == NodeMark::outside) continue;
            bool under_decided = false;
            for (std::int32_t a = h.nodes[n].parent; a >= 0 && !under_decided; a = h.nodes[std::size_t(a)].parent)
                under_decided = decided_whole(std::size_t(a));
            const bool a_child_visited = std::any_of(h.nodes[n].children.begin(), h.nodes[n].children.end(),
                                                     [&](std::uint32_t c) { return touched(c); });
            if (!under_decided && (decided_whole(n) || !a_child_visited)) out.push_back({std::uint32_t(n), v.nodes[n], ShownBox::Weight::settled, false});
        }
        return out;
    }
    if (v.current < 0) {  // before the first step: the root, still to test
        out.push_back({0, v.nodes[0], ShownBox::Weight::next, true});
        return out;
    }
    const auto current = std::uint32_t(v.current);
    std::vector<std::uint32_t> path;  // the root first, down to the current node's parent
    for (std::int32_t a = h.nodes[current].parent; a >= 0; a = h.nodes[std::size_t(a)].parent) path.insert(path.begin(), std::uint32_t(a));
    for (std::size_t k = 0; k < path.size(); ++k) {
        out.push_back({path[k], v.nodes[path[k]], ShownBox::Weight::path, false});
        const std::uint32_t below = k + 1 < path.size() ? path[k + 1] : current;
        for (std::uint32_t c : h.nodes[path[k]].children)  // settled beside the way down
            if (c != below && touched(c)) out.push_back({c, v.nodes[c], ShownBox::Weight::settled, false});
    }
    // the children still to test (a node decided whole has none; a subtree the stages before emptied is not
    // visited), the first two named
    const auto holds_a_candidate = [&](std::uint32_t top) {
        std::vector<std::uint32_t> stack{top};
        while (!stack.empty()) {
            const std::uint32_t n = stack.back();
            stack.pop_back();
            for (std::uint32_t p : h.nodes[n].primitives)
                if (v.primitives[p] != PrimitiveMark::earlier) return true;
            stack.insert(stack.end(), h.nodes[n].children.begin(), h.nodes[n].children.end());
        }
        return false;
    };
    std::size_t named = 0;
    if (!decided_whole(current))
        for (std::uint32_t c : h.nodes[current].children)
            if (!touched(c) && holds_a_candidate(c)) out.push_back({c, NodeMark::untouched, ShownBox::Weight::next, named++ < 2});
    out.push_back({current, v.nodes[current], ShownBox::Weight::current, true});
    return out;
}

std::vector<std::uint32_t> named_primitives(const CullingView& v) {
    std::vector<std::uint32_t> out;
    if (v.world->machine != CullingMachine::occluders) return out;
    // every primitive that reached the stage, culled, passed on or still to test, when they are few: the chapters
    // and questions name them ("find #13 in the picture") before their turn comes
    for (std::uint32_t p = 0; p < v.primitives.size(); ++p)
        if (v.primitives[p] != PrimitiveMark::earlier) out.push_back(p);
    if (out.size() <= max_named) return out;
    out.clear();  // a crowd of labels names nothing: the primitive under test and the next in its node
    if (v.done || v.current < 0) return out;
    if (v.primitive >= 0) out.push_back(std::uint32_t(v.primitive));
    if (v.nodes[std::size_t(v.current)] != NodeMark::partial) return out;  // only a node partly inside tests its own
    for (std::uint32_t p : v.world->hierarchy.nodes[std::size_t(v.current)].primitives)
        if (v.primitives[p] == PrimitiveMark::untouched) {
            out.push_back(p);
            break;
        }
    return out;
}

// ── [SECTION] each machine's pseudocode, lines and steps ────────────────────────────────────────────────────
namespace {

const Pseudocode<HierarchyEvent> bounds_lines = {
    {"BuildBVH(primitives):", {}},
    {"  node.box = the box round its primitives", {}},
    {"  if few primitives (or the depth bound): a leaf", {step<HierarchyNodeBuilt>([](const HierarchyNodeBuilt& e) { return e.leaf != LeafReason::not_a_leaf; })}},
    {"  else split at the median centre along the longest axis", {step<HierarchyNodeBuilt>()}},
    {"       BuildBVH(each half)", {}},
    {"bounding volumes: AABB, sphere, OBB; void = 1 - object / volume", {step<HierarchyBuilt>()}},
};
const Pseudocode<HierarchyCullEvent> frustum_lines = {
    {"Cull(node, planes):            planes: those the parent was not inside", {}},
    {"  for each plane: test node.box against the plane", {}},
    {"    wholly outside: reject node and its subtree", {step<NodeCulled>([](const NodeCulled& e) { return e.outcome == NodeOutcome::outside; })}},
    {"    wholly inside: drop the plane for the subtree", {}},
    {"  no plane left: accept node and its subtree", {step<NodeCulled>([](const NodeCulled& e) { return e.outcome == NodeOutcome::inside; })}},
    {"  projected size < threshold: leave it out (detail)", {step<NodeCulled>([](const NodeCulled& e) { return e.outcome == NodeOutcome::too_small; })}},
    {"  keep node's primitives; Cull(child, planes) for each child", {step<NodeCulled>()}},
    {"done", {step<HierarchyCullFinished>()}},
};
const Pseudocode<OcclusionEvent> occluder_lines = {
    {"choose occluders (polygons, proxies, solids):", {}},
    {"  f = -A (n . v/|v|) / |v|^2 (n of unit length), the best first", {step<OccluderChosen>()}},
    {"occlusion frustum: eye and the occluder's edges, and its plane", {}},
    {"Cull(node):", {}},
    {"  wholly inside one occlusion frustum: cull node and subtree", {step<OcclusionTested>([](const OcclusionTested& e) { return e.node >= 0 && e.outcome == OcclusionOutcome::occluded && !e.fused; }), micro<OcclusionTested>([](const OcclusionTested& e) { return e.outcome == OcclusionOutcome::occluded && !e.fused; })}},
    {"  fusion: image covered by occluders it lies behind: cull", {step<OcclusionTested>([](const OcclusionTested& e) { return e.node >= 0 && e.fused; }), micro<OcclusionTested>([](const OcclusionTested& e) { return e.fused > 0; })}},
    {"  partly inside: test its primitives; Cull(each child)", {step<OcclusionTested>([](const OcclusionTested& e) { return e.node >= 0 && e.outcome == OcclusionOutcome::partly; }), micro<OcclusionTested>([](const OcclusionTested& e) { return e.outcome == OcclusionOutcome::partly; })}},
    {"  outside them all: pass it on to hidden-surface elimination", {step<OcclusionTested>([](const OcclusionTested& e) { return e.node >= 0; }), micro<OcclusionTested>()}},
    {"done", {step<OcclusionFinished>()}},
};
const Pseudocode<HizEvent> hiz_lines = {
    {"Cull_or_Render(N):", {}},
    {"  if N is outside the view frustum: return", {step<HizNodeTested>([](const HizNodeTested& e) { return e.outcome == HizOutcome::outside_frustum; })}},
    {"  if isOccluded(N, Zp): return", {step<HizNodeTested>([](const HizNodeTested& e) { return e.outcome == HizOutcome::occluded; })}},
    {"  for each primitive p in N: render p and update Zp", {step<HizNodeTested>()}},
    {"  for each child C of N, front to back: Cull_or_Render(C)", {}},
    {"isOccluded(g, Zp):", {}},
    {"  if nearZ(g) is behind Zp.z: return true", {}},
    {"  else return isOccluded(g, each child texel under g)", {}},
    {"done", {step<HizFinished>()}},
};

// Each machine's table, by its events.
const Pseudocode<HierarchyEvent>& table_of(const HierarchyEvent*) { return bounds_lines; }
const Pseudocode<HierarchyCullEvent>& table_of(const HierarchyCullEvent*) { return frustum_lines; }
const Pseudocode<OcclusionEvent>& table_of(const OcclusionEvent*) { return occluder_lines; }
const Pseudocode<HizEvent>& table_of(const HizEvent*) { return hiz_lines; }

}  // namespace

// ── [SECTION] the sessions ──────────────────────────────────────────────────────────────────────────────────
namespace {

CullingView initial_view(const std::shared_ptr<const CullingWorld>& world) {
    CullingView v;
    v.world = world;
    v.nodes.assign(world->hierarchy.nodes.size(), NodeMark::untouched);
    v.primitives.assign(world->scene.polygons.size(), PrimitiveMark::untouched);
    for (std::size_t p = 0; p < world->candidates.size(); ++p)
        if (!world->candidates[p]) v.primitives[p] = PrimitiveMark::earlier;
    count(v);
    return v;
}

// The lesson's culling machine, on the lesson's world (each overload is one of the four machines' types).
Steps<HierarchyEvent, Hierarchy> steps_of(const CullingWorld& w, const Lesson&, HierarchyEvent*) {
    return build_hierarchy(w.hierarchy.boxes, {.kind = w.hierarchy.kind});
}
Steps<HierarchyCullEvent, HierarchyCull> steps_of(const CullingWorld& w, const Lesson& lesson, HierarchyCullEvent*) {
    const HierarchyCullOptions o = machine_of<CullingMachine>(lesson) == CullingMachine::frustum
                                       ? HierarchyCullOptions{.frustum = true, .candidates = w.candidates}
                                       : HierarchyCullOptions{.frustum = false, .detail_pixels = w.detail_pixels,
                                                              .viewport_height = lesson.grid.height, .candidates = w.candidates};
    return cull_hierarchy(&w.hierarchy, w.scene.camera, o);
}
Steps<OcclusionEvent, OcclusionCull> steps_of(const CullingWorld& w, const Lesson& lesson, OcclusionEvent*) {
    OcclusionOptions o = occlusion_options(lesson);
    o.candidates = w.candidates;
    return occlusion_cull(&w.scene, &w.hierarchy, std::move(o));
}
Steps<HizEvent, HizResult> steps_of(const CullingWorld& w, const Lesson&, HizEvent*) {
    return hiz_render(&w.scene, &w.hierarchy, w.zbuffer, w.candidates);
}

}  // namespace

template <class Event, class Result>
typename CullingSession<Event, Result>::RunType CullingSession<Event, Result>::machine(const Lesson& lesson) {
    const auto world = culling_world(lesson);  // the machines read it through pointers: the view keeps it alive
    return {steps_of(*world, lesson, static_cast<Event*>(nullptr)), initial_view(world)};
}

template <class Event, class Result>
CullingSession<Event, Result>::CullingSession(Lesson lesson, PlayerOptions options)
    : PlayerSession<Event, Result, CullingView>(lesson, machine(lesson), options), machine_(machine_of<CullingMachine>(lesson)) {}

template <class Event, class Result>
const Pseudocode<Event>& CullingSession<Event, Result>::table() const {
    return table_of(static_cast<const Event*>(nullptr));
}
template <class Event, class Result>
std::string CullingSession<Event, Result>::sentence_of(const Event& e, const CullingView&) {
    return describe(e);
}
template <class Event, class Result>
std::string CullingSession<Event, Result>::describe_event(const Event& e) const {
    return describe(e);
}
template <class Event, class Result>
std::string CullingSession<Event, Result>::speak_event(const Event& e) const {
    return window_strings().say(phrase(e));
}
template <class Event, class Result>
const FamilyFacts CullingSession<Event, Result>::facts = {
    .topic = "Culling",
    .speaks_to = [](const Scene&, const AlgorithmInfo&) { return false; },
    .random_scene = [](std::uint32_t seed, bool) -> std::optional<Scene> { return city_scene({.triangles = 3000, .seed = seed}); },
    .measure = &analysis::measure_culling,
};

template class CullingSession<HierarchyEvent, Hierarchy>;
template class CullingSession<HierarchyCullEvent, HierarchyCull>;
template class CullingSession<OcclusionEvent, OcclusionCull>;
template class CullingSession<HizEvent, HizResult>;

std::string_view to_string(CullingMachine m) {
    switch (m) {
        case CullingMachine::bounds: return "bounds";
        case CullingMachine::frustum: return "frustum";
        case CullingMachine::detail: return "detail";
        case CullingMachine::occluders: return "occluders";
        case CullingMachine::hiz: return "hiz";
    }
    return "?";
}

}  // namespace hsr::viz
