// SPDX-License-Identifier: MIT
// Practice for hierarchical view-frustum culling: small squares scattered around an orthographic camera's view volume
// (a box in world coordinates, so a student can read it), an octree over them, culled top-down with the notes'
// IntersectionTest. Is a node's cell wholly inside, wholly outside or partly inside the view volume? Every answer is a
// NodeCulled event of the culling lesson's own machine on the exercise's scene.
#include <cmath>
#include <cstdio>

#include "culling/culling_events.h"
#include "culling/hierarchy.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"

namespace hsr::viz::practice {
namespace {

using algo::Vec3;

// The camera: orthographic, at z = 10 looking down −z, so the view volume is x ∈ [−3.5, 3.5], y ∈ [−2.5, 2.5],
// z ∈ [10 − far, 10 − near] = [−6, 6] in world coordinates.
constexpr double half_width = 3.5, half_height = 2.5, eye_z = 10, near_plane = 4, far_plane = 16;
const Vec3 volume_lo(-half_width, -half_height, eye_z - far_plane), volume_hi(half_width, half_height, eye_z - near_plane);

// %g with a true minus sign (−), as the question's boxes print their corners
std::string minus_sign_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    std::string t = text;
    if (t.front() == '-') t.replace(0, 1, "−");
    return t;
}
std::string point_text(const Vec3& p) { return "(" + minus_sign_text(p.x) + ", " + minus_sign_text(p.y) + ", " + minus_sign_text(p.z) + ")"; }

algo::Scene squares_scene(Dice& d, Level l) {
    algo::Scene scene;
    scene.name = "squares around a view volume";
    scene.camera.projection = algo::Projection::orthographic;
    scene.camera.eye = {0, 0, eye_z};
    scene.camera.target = {0, 0, 0};
    scene.camera.near = near_plane;
    scene.camera.far = far_plane;
    scene.camera.box[0] = -half_width, scene.camera.box[1] = half_width, scene.camera.box[2] = -half_height, scene.camera.box[3] = half_height;
    // clusters of five squares, some inside the volume and some beside it: the octree splits each cluster's region
    // into cells small enough to lie wholly inside or wholly outside (scattered squares give only large cells that
    // are partly inside)
    const int clusters = l == Level::easy ? 3 : l == Level::medium ? 4 : 5;
    algo::SceneId id = 1;
    for (int c = 0; c < clusters; ++c) {
        const bool inside = d.coin();
        const double cx = inside ? d.grid(-4, 4, 1) / 2 : (d.coin() ? 1 : -1) * d.grid(10, 16, 1) / 2;
        const double cy = d.grid(-3, 3, 1) / 2, cz = d.grid(-8, 8, 1) / 2;
        for (int k = 0; k < 5; ++k) {
            const double x = cx + d.grid(-2, 2, 1) / 2, y = cy + d.grid(-2, 2, 1) / 2, z = cz + d.grid(-2, 2, 1) / 2, s = 0.5;
            algo::ScenePolygon p{id++, {200, 200, 200}, {}};
            p.vertices = {{x, y, z, 1}, {x + s, y, z, 1}, {x + s, y + s, z, 1}, {x, y + s, z, 1}};
            scene.polygons.push_back(p);
        }
    }
    return scene;
}

// A cell face within a twentieth of a face of the volume would be decided by which side of the plane 0 falls on.
bool touches_the_volume(const algo::Aabb& b) {
    for (int a = 0; a < 3; ++a)
        for (double face : {b.lo[a], b.hi[a]})
            if (std::abs(face - volume_lo[a]) < 0.05 || std::abs(face - volume_hi[a]) < 0.05) return true;
    return false;
}

// What the question says (the catalogues' [exercise.culling] translate it).
namespace say {
using algo::Saying;
constexpr Saying node{"culling.node",
                      "Hierarchical view-frustum culling, an orthographic camera: its view volume is the box from {volume_lo} "
                      "to {volume_hi} in world coordinates. Octree node {node}'s cell runs from {lo} to {hi}. Against the "
                      "view volume, it is:"};
constexpr Saying inside{"culling.inside", "wholly inside: accepted, with everything below it"};
constexpr Saying outside{"culling.outside", "wholly outside: rejected, with everything below it"};
constexpr Saying partial{"culling.partial", "partly inside: its primitives kept, its children tested"};
constexpr Saying all[] = {node, inside, outside, partial};
}  // namespace say

std::optional<Exercise> node_exercise(Dice& d, Level l) {
    algo::Scene scene = squares_scene(d, l);
    // as the culling lesson does: an octree over the polygons' boxes, culled against the camera's frustum
    const algo::Hierarchy tree = algo::build_hierarchy(algo::polygon_boxes(scene), {.kind = algo::HierarchyKind::octree}).run_to_end();
    std::vector<algo::HierarchyCullEvent> events;
    auto machine = algo::cull_hierarchy(&tree, scene.camera, {.frustum = true});
    while (const algo::HierarchyCullEvent* e = machine.next()) events.push_back(*e);
    // the steps of nodes a student can decide, by outcome: an outcome first, then a node, so that "partly inside"
    // (the large cells near the top) does not crowd out the others; the root only at the easy level
    std::vector<std::size_t> by_outcome[3];
    for (std::size_t step = 0; step < events.size(); ++step)
        if (const auto* c = std::get_if<algo::NodeCulled>(&events[step]);
            c && c->outcome != algo::NodeOutcome::too_small && (c->node != 0 || l == Level::easy) && !touches_the_volume(tree.nodes[c->node].box))
            by_outcome[std::size_t(c->outcome)].push_back(step);
    std::vector<const std::vector<std::size_t>*> present;
    for (const auto& steps : by_outcome)
        if (!steps.empty()) present.push_back(&steps);
    if (present.empty()) return std::nullopt;
    const std::vector<std::size_t>& pick = *present[std::size_t(d.below(int(present.size())))];
    const std::size_t step = pick[std::size_t(d.below(int(pick.size())))];
    const auto& c = std::get<algo::NodeCulled>(events[step]);
    const algo::Aabb& box = tree.nodes[c.node].box;
    Exercise x;
    if (c.outcome == algo::NodeOutcome::too_small) return std::nullopt;  // not with detail culling off
    x.ask(Wording(say::node, {{"volume_lo", point_text(volume_lo)},
                              {"volume_hi", point_text(volume_hi)},
                              {"node", std::to_string(c.node)},
                              {"lo", point_text(box.lo)},
                              {"hi", point_text(box.hi)}}));
    x.offer({Wording(say::inside), Wording(say::outside), Wording(say::partial)},
            c.outcome == algo::NodeOutcome::inside ? 0 : c.outcome == algo::NodeOutcome::outside ? 1 : 2);
    x.deciding = algo::describe(events[step]);
    x.deciding_step = step;
    x.given = {{"kind", "node_outcome"},
               {"volume", {{volume_lo.x, volume_lo.y, volume_lo.z}, {volume_hi.x, volume_hi.y, volume_hi.z}}},
               {"cell", {{box.lo.x, box.lo.y, box.lo.z}, {box.hi.x, box.hi.y, box.hi.z}}}};
    x.scene = std::move(scene);
    x.algorithm = "cull_frustum";
    x.cull = "frustum";
    return x;
}

}  // namespace

std::vector<Topic> culling_topics() {
    return {{"culling", "View-frustum culling: inside, outside, partly", {"cull_frustum", "cull_bounds"},
             [](Draw draw) {
                 Dice d(draw.seed);
                 return node_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
