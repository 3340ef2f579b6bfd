// SPDX-License-Identifier: MIT
// Culling lessons: a hierarchy built node by node (bounding volumes), culled against the frustum or for detail,
// occluders and their frusta, or Cull_or_Render with the Z-pyramid. One view serves them all: what happened to
// each node and each primitive so far. Every culling lesson also runs the whole pipeline once (the stages its
// scene needs) for the pipeline panel: what each stage leaves out.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/hiz.h"
#include "culling/occluders.h"
#include "culling/pipeline.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

// One object of a bounds lesson's scene (polygons joined through shared vertices), named by its ids ("101–112"),
// with the share of each bounding volume it does not fill (none for a group that is not a closed solid).
struct SceneObject {
    std::string name;
    std::vector<std::size_t> polygons;
    glm::vec3 centre;  // its corners' mean, where the view labels it
    std::optional<double> aabb_void, sphere_void, obb_void;
};

struct CullingWorld {
    algo::CullingMachine machine = algo::CullingMachine::frustum;  // the lesson's
    algo::Scene scene;
    algo::Hierarchy hierarchy;                 // complete (a bounds lesson folds its build event by event)
    std::vector<algo::StageReport> pipeline;   // the whole pipeline on this scene, once
    algo::ZBufferOptions zbuffer;              // the lesson's grid, for the Z-pyramid
    std::vector<algo::Plane> frustum;          // the camera's view frustum
    double detail_pixels = 0;
    algo::OccluderKind occluders = algo::OccluderKind::planar;  // the occluder stage's shapes, and fusion
    bool fusion = false;
    // per polygon: reached the lesson's stage, kept by the pipeline's stages before it (empty: all, for the bounds
    // lesson). The machine runs on these only, so that its counts are the pipeline's.
    std::vector<std::uint8_t> candidates;
    // a bounds lesson's objects, for its void table and the view's labels (figured once, not per frame); none for any
    // other lesson, or for a scene of more than 12 objects or 20,000 polygons
    std::vector<SceneObject> objects;
};

enum class NodeMark : std::uint8_t { untouched, built, outside, inside, partial, too_small, large_enough, occluded, visible };
enum class PrimitiveMark : std::uint8_t { untouched, kept, left_out, earlier };  // earlier: left out by a stage before

struct CullingView {
    std::shared_ptr<const CullingWorld> world;
    std::vector<NodeMark> nodes;
    std::vector<PrimitiveMark> primitives;
    struct ShownOccluder {
        std::vector<algo::Vec3> outline;  // the polygon, or the proxy that stands for it (or for a solid)
        algo::OccluderKind shape;
        std::uint32_t polygon, faces;
    };
    std::vector<ShownOccluder> occluders;       // chosen, best first
    std::vector<std::uint32_t> rendered;        // Hi-Z: primitives rendered, in order (the pyramid is rebuilt from them)
    std::int32_t current = -1;                  // the node last touched
    std::int32_t primitive = -1;                // occluders: the primitive last tested on its own
    std::uint32_t kept = 0, left_out = 0, earlier = 0, texels = 0;
    std::uint32_t plane_tests = 0;              // every plane test so far: nodes' boxes and their own primitives' boxes
    std::uint32_t built = 0, leaves = 0;        // the bounds lesson: nodes built so far, and how many of them are leaves
    std::uint32_t fused = 0;                    // occluders: primitives culled by fusion (no single occluder hid them)
    bool done = false;
};
std::size_t approx_bytes(const CullingView& view);
void reduce(CullingView& view, const algo::HierarchyEvent& event);
void reduce(CullingView& view, const algo::HierarchyCullEvent& event);
void reduce(CullingView& view, const algo::OcclusionEvent& event);
void reduce(CullingView& view, const algo::HizEvent& event);

// The hierarchy's boxes the view draws now, so that a class can read it: the node under test (bold), the nodes on
// its way down from the root, the nodes settled beside that way (faint; what lies below them is not drawn), and the
// children still to test (white). Before the first step, the root still to test; at the end, where the traversal
// stopped (the nodes with no child visited), but not the boxes rejected by the frustum: the frustum's lines and the
// faint primitives show what it left out. `labelled`: the boxes the narration names ("node 13").
struct ShownBox {
    enum class Weight : std::uint8_t { current, path, next, settled };
    std::uint32_t node;
    NodeMark mark;
    Weight weight;
    bool labelled;
};
std::vector<ShownBox> shown_boxes(const CullingView& view);
// The primitives the view labels with their numbers ("#7", as the sentences number them) in an occluder lesson:
// each that reached the stage, when they are at most max_named; else the primitive last tested on its own and the
// next one its node tests.
inline constexpr std::size_t max_named = 12;
std::vector<std::uint32_t> named_primitives(const CullingView& view);

// Hi-Z: the depth buffer of the primitives rendered so far (the Z-pyramid is built from it).
std::vector<std::uint32_t> rendered_depth(const CullingView& view);

// The occluder stage a lesson asks for (occluder = "…", fusion = …), the same in its pipeline and its machine.
algo::OcclusionOptions occlusion_options(const Lesson& lesson);

// The world a culling lesson plays in (its hierarchy: a BVH for the bounds lesson, else an octree).
std::shared_ptr<const CullingWorld> culling_world(const Lesson& lesson);

// What the panels draw of a culling lesson, whichever machine it plays.
class CullingLesson {
public:
    virtual ~CullingLesson() = default;
    virtual const CullingView& culling_view() const = 0;
    virtual algo::CullingMachine culling_machine() const = 0;
};
std::string_view to_string(algo::CullingMachine m);  // "bounds", "frustum", "detail", "occluders", "hiz"

// One session type per culling machine's events (frustum and detail culling share theirs); the four share the
// view, the panels and the screen.
template <class Event, class Result>
class CullingSession final : public PlayerSession<Event, Result, CullingView>, public CullingLesson {
public:
    using RunType = typename PlayerSession<Event, Result, CullingView>::RunType;
    explicit CullingSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static std::string sentence_of(const Event& e, const CullingView& view);  // describe(e)
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::CullingMachine m) {  // the machines whose events are Event (frustum and detail share theirs)
        using M = algo::CullingMachine;
        if constexpr (std::is_same_v<Event, algo::HierarchyEvent>) return m == M::bounds;
        else if constexpr (std::is_same_v<Event, algo::HierarchyCullEvent>) return m == M::frustum || m == M::detail;
        else if constexpr (std::is_same_v<Event, algo::OcclusionEvent>) return m == M::occluders;
        else return m == M::hiz;
    }
    const CullingView& culling_view() const override { return this->view(); }
    algo::CullingMachine culling_machine() const override { return machine_; }

private:
    std::string describe_event(const Event& e) const override;
    std::string speak_event(const Event& e) const override;
    const Pseudocode<Event>& table() const override;
    algo::CullingMachine machine_;
};

using BoundsSession = CullingSession<algo::HierarchyEvent, algo::Hierarchy>;
using HierarchyCullSession = CullingSession<algo::HierarchyCullEvent, algo::HierarchyCull>;  // frustum, detail
using OccluderSession = CullingSession<algo::OcclusionEvent, algo::OcclusionCull>;
using HizSession = CullingSession<algo::HizEvent, algo::HizResult>;
extern template class CullingSession<algo::HierarchyEvent, algo::Hierarchy>;
extern template class CullingSession<algo::HierarchyCullEvent, algo::HierarchyCull>;
extern template class CullingSession<algo::OcclusionEvent, algo::OcclusionCull>;
extern template class CullingSession<algo::HizEvent, algo::HizResult>;

}  // namespace hsr::viz
