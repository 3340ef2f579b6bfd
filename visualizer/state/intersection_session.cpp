// SPDX-License-Identifier: MIT
#include "state/intersection_session.h"

#include <random>

#include "core/overloaded.h"
#include "scene/random_scene.h"
#include "state/strings.h"
#include "core/okabe_ito.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The Greek notes' pseudocode, line for line.
const Pseudocode<IntersectionEvent> intersection_lines = {
    {"for each ray:", {step<RayStartedAt>()}},
    {"IntersectionTest(M) {", {step<ModelEntered>([](const ModelEntered& e) { return !e.bottom; })}},
    {"    if BottomLevel(M)    return(LLIntersectionTest(M))",
     {step<ModelEntered>([](const ModelEntered& e) { return e.bottom; }), step<PrimitiveHitTested>()}},
    {"    else if LLIntersectionTest(BoundingBox(M)) {", {step<VolumeTested>()}},
    {"        v = false;", {}},
    {"        for each component M→C", {}},
    {"            v = (v || IntersectionTest(M→C));", {step<ComponentSkipped>()}},
    {"        return(v);", {step<ModelAnswered>([](const ModelAnswered& e) { return e.hit || e.false_alarm; })}},
    {"    }", {}},
    {"    else return(false);", {step<ModelAnswered>([](const ModelAnswered& e) { return !e.hit && !e.false_alarm; })}},
    {"}", {step<RayAnswered>()}},
    {"done", {step<IntersectionFinished>()}},
};

// Twelve random triangles and three rays from in front of them toward their middle.
std::optional<Scene> random_rays(std::uint32_t seed, bool) {
    Scene s = random_triangles({.count = 12, .seed = seed, .size = 3});
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> spread(-4, 4);
    for (int i = 0; i < 3; ++i)
        s.segments.push_back({SceneId(1001 + i), okabe_ito::as<Color>(okabe_ito::yellow), glm::dvec4(spread(rng), spread(rng), 9, 1), glm::dvec4(spread(rng) / 2, spread(rng) / 2, 0, 1)});
    return s;
}

}  // namespace

BoundingOptions bounding_options(const Lesson& lesson) {
    const VolumeKind kind = lesson.volume == "sphere" ? VolumeKind::sphere
                            : lesson.volume == "obb"  ? VolumeKind::obb
                            : lesson.volume == "kdop" ? VolumeKind::kdop
                            : lesson.volume == "hulls" ? VolumeKind::hulls
                                                       : VolumeKind::aabb;
    return {.volume = kind, .k = lesson.k};
}

IntersectionView intersection_initial_view(const Scene& scene, BoundingOptions options) {
    auto input = std::make_shared<IntersectionInput>();
    input->model = bounding_model(scene, options);
    for (const Ray& r : rays_of(scene)) input->rays.push_back(unit_ray(r));  // as the machine tests them: t is a distance
    IntersectionView v;
    v.marks.assign(input->model.tree.nodes.size(), CallMark::untouched);
    v.answers.resize(input->rays.size());
    v.input = std::move(input);
    return v;
}

IntersectionSession::RunType IntersectionSession::machine(const Lesson& lesson) {
    check_rays(rays_of(lesson.scene));  // before the hierarchy (9 to 11 s on field:20000000), not after it
    const BoundingOptions options = bounding_options(lesson);
    IntersectionView initial = intersection_initial_view(lesson.scene, options);
    return {intersection_test(lesson.scene, rays_of(lesson.scene), {.bounding = options}), std::move(initial)};
}

void reduce(IntersectionView& v, const IntersectionEvent& event) {
    std::visit(overloaded{
                   [&](const RayStartedAt& e) {
                       v.ray = e.ray, v.calls.clear(), v.volume.reset(), v.primitive.reset(), v.hit_point.reset();
                       std::fill(v.marks.begin(), v.marks.end(), CallMark::untouched);
                   },
                   [&](const ModelEntered& e) {
                       v.calls.push_back(e.node), v.marks[e.node] = CallMark::entered;
                       v.volume.reset(), v.primitive.reset();
                   },
                   [&](const VolumeTested& e) {
                       v.volume = e, ++v.volume_tests;
                       v.marks[e.node] = e.hit ? CallMark::inside : CallMark::missed;
                   },
                   [&](const PrimitiveHitTested& e) {
                       v.primitive = e, ++v.primitive_tests;
                       if (e.hit) {
                           const Ray& r = v.input->rays[e.ray];
                           v.hit_point = r.origin + e.t * r.direction;
                       }
                   },
                   [&](const ComponentSkipped& e) { v.marks[e.component] = CallMark::skipped; },
                   [&](const ModelAnswered& e) {
                       if (!v.calls.empty()) v.calls.pop_back();
                       if (e.false_alarm) ++v.false_alarms;
                       if (e.hit) v.marks[e.node] = CallMark::hit;
                       else if (e.false_alarm) v.marks[e.node] = CallMark::false_alarm;
                       else v.marks[e.node] = CallMark::missed;
                   },
                   [&](const RayAnswered& e) { v.answers[e.ray] = e.hit, v.volume.reset(), v.primitive.reset(); },
                   [&](const IntersectionFinished& e) { v.finished = e; },
               },
               event);
}

std::size_t approx_bytes(const IntersectionView& v) {
    return sizeof(IntersectionView) + v.calls.capacity() * sizeof(std::uint32_t) + v.marks.capacity() + v.answers.capacity() * sizeof(v.answers[0]);
}

IntersectionSession::IntersectionSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string IntersectionSession::sentence_of(const IntersectionEvent& e, const IntersectionView&) { return describe(e); }
std::string IntersectionSession::describe_event(const IntersectionEvent& e) const { return sentence_of(e, view()); }
std::string IntersectionSession::speak_event(const IntersectionEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<IntersectionEvent>& IntersectionSession::table() const { return intersection_lines; }

const FamilyFacts IntersectionSession::facts = {
    .topic = "Bounding volumes",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &random_rays,
    .measure = &analysis::measure_intersection,
};

}  // namespace hsr::viz
