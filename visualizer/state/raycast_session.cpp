// SPDX-License-Identifier: MIT
#include "state/raycast_session.h"

#include <algorithm>
#include <cmath>

#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's RayCasting; with a grid, the primitives of a ray are those of the cells it walks.
const Pseudocode<RayCastEvent> cast_lines = {
    {"RayCasting(primitiveDB, v):", {}},
    {"  for each pixel p:", {step<CastFinished>(), step<CastStepBoundReached>()}},
    {"    minp = MAXINT", {micro<RayStarted>()}},
    {"    for each cell C the ray (v, p) walks:   /* or: every primitive */", {micro<CellEntered>(), micro<NodeEntered>()}},
    {"      for each primitive R in C:", {}},
    {"        I = intersect_primitive_ray(R, v, p)", {micro<PrimitiveTested>()}},
    {"        if (|I - v| < minp):", {}},
    {"          p -> nearest_primitive = R;  minp = |I - v|", {micro<NearerHitFound>()}},
    {"      if (minp is inside C): stop walking", {}},
    {"    p sees p -> nearest_primitive", {step<RayFinished>()}},
};

// The octree's build, by the notes' "Space Subdivision": recursively subdivide a cell into 8 subcells; stop when
// the object complexity within a cell is below a limit, or when an elementary cell size (voxel) is reached.
const Pseudocode<RayCastEvent> build_lines = {
    {"BuildOctree(cell):", {}},
    {"  list the primitives whose boxes overlap the cell", {step<OctreeCellExamined>()}},
    {"  if (primitives <= limit) or (cell is a voxel):", {}},
    {"    cell is a leaf          /* stop */", {step<OctreeLeafMade>()}},
    {"  else:", {}},
    {"    subdivide the cell into 8 subcells", {step<OctreeCellSplit>()}},
    {"    for each subcell S: BuildOctree(S)", {}},
    {"/* then cast the rays through it */", {step<OctreeBuilt>()}},
};

}  // namespace

RayCastSession::RunType RayCastSession::machine(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    const Viewport grid = lesson.grid;
    const auto a = machine_of<Acceleration>(lesson);
    RayView initial;
    initial.viewport = grid;
    initial.acceleration = a;
    initial.owner.assign(std::size_t(grid.width) * std::size_t(grid.height), -1);
    if (a == Acceleration::grid) initial.grid = std::make_shared<const Grid>(ray_cast_grid(scene));  // the machine's cells
    if (a == Acceleration::bvh) {  // the BVH's nodes, drawn as the octree's cells are (leaves faint, the node entered bold)
        for (const HierarchyNode& n : ray_cast_bvh(scene).nodes)
            initial.octree.push_back({n.box.lo, n.box.hi, int(n.depth), n.subtree_primitives, !n.children.empty(), n.children.empty()});
        initial.octree_built = true;
    }
    return {ray_cast(scene, {.viewport = grid, .acceleration = a, .detail = RayDetail::test, .octree = lesson.octree}), std::move(initial)};
}

RayCastSession::RayCastSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options),
      scene_(grid_scene(lesson)) {}

double RayCastSession::octree_voxel() const {
    if (lesson().octree.voxel > 0 || view().octree.empty()) return lesson().octree.voxel;
    const RayView& v = view();  // no voxel given: the depth limit's, the root's edge halved max_depth times
    const Vec3 size = v.octree[0].hi - v.octree[0].lo;
    return std::ldexp(std::max({size.x, size.y, size.z}), -lesson().octree.max_depth);
}

std::string RayCastSession::sentence_of(const RayCastEvent& e, const RayView&) { return describe(e); }
std::string RayCastSession::describe_event(const RayCastEvent& e) const { return sentence_of(e, view()); }
std::string RayCastSession::speak_event(const RayCastEvent& e) const { return window_strings().say(phrase(e)); }

// BuildOctree while the octree is being built, RayCasting from the first ray.
const Pseudocode<RayCastEvent>& RayCastSession::table() const {
    const auto e = player().last_applied();
    return e && build_lines.line_of(*e) >= 0 ? build_lines : cast_lines;
}

// Either table says: a Step back from the first ray lands in the build.
bool RayCastSession::is_major(const RayCastEvent& e) const {
    return build_lines.is_major(e).value_or(cast_lines.is_major(e).value_or(true));
}

const FamilyFacts RayCastSession::facts = {
    .topic = "Ray casting",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) {  // the reference every image is measured against
        return !s.expect.image.empty() || expects_from_renderer(s, "raycast");
    },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_hidden_surfaces,
};

}  // namespace hsr::viz
