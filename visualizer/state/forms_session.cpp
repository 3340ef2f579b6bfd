// SPDX-License-Identifier: MIT
#include "state/forms_session.h"

#include <random>

#include "core/overloaded.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The Greek notes' two general forms, one below the other, as they print them.
const Pseudocode<FormsEvent> forms_lines = {
    {"each primitive's image on the line u", {step<FormsShown>(), micro<PrimitiveProjected>()}},
    {"for each primitive                       // object space", {}},
    {"{", {}},
    {"    find visible part", {step<VisiblePartFound>()}},
    {"      // compare against all other primitives", {step<PrimitivesCompared>()}},
    {"    render visible part", {step<PartRendered>()}},
    {"}                                        // O(P²)", {}},
    {"for each pixel                           // image space", {}},
    {"{", {}},
    {"    find closest primitive", {micro<ProjectorTested>()}},
    {"    render pixel with color of closest primitive", {step<PixelRendered>()}},
    {"}                                        // O(pP)", {}},
    {"done", {step<FormsFinished>()}},
};

// Seven random walls in front of an eye at the origin looking along +y.
std::optional<Scene> random_walls(std::uint32_t seed, bool) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> across(-4, 4), deep(2, 9), turn(-1.2, 1.2), length(1, 3.5);
    Scene s;
    s.name = "random walls " + std::to_string(seed);
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 1, 0}, s.camera.up = {0, 0, 1};
    s.camera.fov_y = 70, s.camera.near = 0.5, s.camera.far = 12;
    for (int i = 0; i < 7; ++i) {
        const glm::dvec2 c(across(rng) * 0.8, deep(rng));
        const double angle = turn(rng), half = length(rng) / 2;
        const glm::dvec2 d(std::cos(angle) * half, std::sin(angle) * half);
        const auto hue = std::uint8_t(35 * i);
        s.segments.push_back({SceneId(i + 1), Color{hue, std::uint8_t(230 - hue), 160}, glm::dvec4(c - d, 0, 1), glm::dvec4(c + d, 0, 1)});
    }
    return s;
}

}  // namespace

FormsView forms_initial_view(const Scene& scene, std::uint32_t pixels) {
    auto input = std::make_shared<FormsInput>();
    input->camera = plan_camera(scene.camera);
    input->pixels = pixels;
    for (const SceneSegment& s : scene.segments) {
        input->a.push_back(glm::dvec2(s.a)), input->b.push_back(glm::dvec2(s.b));
        input->colors.push_back(s.color), input->ids.push_back(s.id);
        input->images.push_back(image_of(input->camera, input->camera.to_camera(input->a.back()), input->camera.to_camera(input->b.back())));
    }
    FormsView v;
    v.visible.resize(scene.segments.size());
    v.object_image.assign(pixels, -1), v.image_image.assign(pixels, -1);
    v.input = std::move(input);
    return v;
}

FormsSession::RunType FormsSession::machine(const Lesson& lesson) {
    const auto pixels = std::uint32_t(std::max(1, lesson.grid.width));
    FormsView initial = forms_initial_view(lesson.scene, pixels);
    return {general_forms(lesson.scene, {.pixels = pixels}), std::move(initial)};
}

void reduce(FormsView& v, const FormsEvent& event) {
    std::visit(overloaded{
                   [&](const FormsShown&) {},
                   [&](const PrimitiveProjected&) {},
                   [&](const PrimitivesCompared& e) {
                       if (v.primitive != e.primitive) v.hidden.clear();
                       v.primitive = e.primitive, v.compared = e;
                       ++v.comparisons;
                       if (e.hides) v.hidden.emplace_back(e.hidden_from, e.hidden_to);
                   },
                   [&](const VisiblePartFound& e) {
                       if (v.primitive != e.primitive) v.hidden.clear();  // a primitive alone in view compares nothing
                       v.primitive = e.primitive, v.compared.reset();
                       v.visible[e.primitive] = e.parts;
                   },
                   [&](const PartRendered& e) {
                       for (const std::uint32_t k : e.pixels) v.object_image[k] = std::int32_t(e.primitive);
                   },
                   [&](const ProjectorTested& e) {
                       if (!v.image_space) v.image_space = true, v.primitive.reset(), v.compared.reset(), v.hidden.clear();
                       if (v.pixel != e.pixel) v.hits.clear();
                       v.pixel = e.pixel, v.tested = e;
                       ++v.tests;
                       if (e.hit) v.hits.emplace_back(e.primitive, e.depth);
                   },
                   [&](const PixelRendered& e) {
                       if (!v.image_space) v.image_space = true, v.primitive.reset(), v.compared.reset(), v.hidden.clear();
                       if (v.pixel != e.pixel) v.hits.clear();
                       v.pixel = e.pixel, v.tested.reset();
                       v.image_image[e.pixel] = e.primitive;
                   },
                   [&](const FormsFinished& e) { v.finished = e, v.tested.reset(), v.compared.reset(), v.primitive.reset(); },
               },
               event);
}

std::size_t approx_bytes(const FormsView& v) {
    std::size_t parts = 0;
    for (const auto& p : v.visible) parts += p ? p->capacity() * sizeof(glm::dvec2) : 0;
    return sizeof(FormsView) + parts + v.visible.capacity() * sizeof(v.visible[0]) + v.hidden.capacity() * sizeof(glm::dvec2) +
           (v.object_image.capacity() + v.image_image.capacity()) * sizeof(std::int32_t) + v.hits.capacity() * sizeof(v.hits[0]);
}

FormsSession::FormsSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string FormsSession::sentence_of(const FormsEvent& e, const FormsView&) { return describe(e); }
std::string FormsSession::describe_event(const FormsEvent& e) const { return sentence_of(e, view()); }
std::string FormsSession::speak_event(const FormsEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<FormsEvent>& FormsSession::table() const { return forms_lines; }

const FamilyFacts FormsSession::facts = {
    .topic = "Object space and image space",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &random_walls,
    .measure = &analysis::measure_complexity,  // R: the complexity table, run time against P and p
};

}  // namespace hsr::viz
