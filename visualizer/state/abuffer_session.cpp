// SPDX-License-Identifier: MIT
#include "state/abuffer_session.h"

#include <algorithm>

#include "core/overloaded.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The A-buffer as the UBC notes name it: a list of surfaces per pixel, with colour, depth and coverage.
const Pseudocode<ABufferEvent> abuffer_lines = {
    {"for each polygon P:", {step<ABufferStarted>()}},
    {"  for each pixel P reaches:", {}},
    {"    mask = the sub-samples inside P", {}},
    {"    if mask ≠ 0: add (RGB, α, Z, mask) to its list", {micro<FragmentMade>()}},
    {"  (P scanned)", {step<PolygonScanned>()}},
    {"for each pixel with a list:", {}},
    {"  sort the list by Z, nearest first", {}},
    {"  for each fragment f, front to back:", {}},
    {"    for each sub-sample s in f's mask:", {}},
    {"      colour_s += light_s · α_f · RGB_f", {}},
    {"      light_s ·= 1 − α_f", {micro<FragmentResolved>()}},
    {"  pixel = the mean over its sub-samples", {step<PixelResolved>()}},
    {"done", {step<ABufferFinished>()}},
};

}  // namespace

ABufferView abuffer_initial_view(const Scene& scene, Viewport viewport, int mask_size) {
    auto input = std::make_shared<ABufferInput>();
    input->viewport = viewport, input->mask_size = mask_size;
    const glm::dmat4 to_clip = view_projection(scene.camera);
    for (const ScenePolygon& p : scene.polygons) {
        std::vector<glm::dvec4> clip;
        for (const auto& v : p.vertices) clip.push_back(to_clip * v);
        input->polygons.push_back(p.vertices.size() >= 3 ? project_polygon(p.id, p.color, clip, viewport) : ScreenPolygon{});
        input->opacities.push_back(p.opacity);
    }
    input->one_sample = a_buffer(scene, viewport, {.mask_size = 1}).run_to_end().rgba;
    ABufferView v;
    const std::size_t pixels = std::size_t(viewport.width) * std::size_t(viewport.height);
    v.lists.resize(pixels), v.rgba.assign(pixels, glm::dvec4(0)), v.resolved.assign(pixels, 0);
    v.input = std::move(input);
    return v;
}

ABufferSession::RunType ABufferSession::machine(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    ABufferView initial = abuffer_initial_view(scene, lesson.grid, lesson.mask_size);
    return {a_buffer(scene, lesson.grid, {.mask_size = lesson.mask_size}), std::move(initial)};
}

void reduce(ABufferView& v, const ABufferEvent& event) {
    std::visit(overloaded{
                   [&](const ABufferStarted&) {},
                   [&](const FragmentMade& e) {
                       const Color c = v.input->polygons[e.polygon].color;
                       v.lists[v.at(e.x, e.y)].push_back({e.polygon, e.mask, e.depth, glm::dvec3(c.r, c.g, c.b) / 255.0, v.input->opacities[e.polygon]});
                       v.x = e.x, v.y = e.y, v.polygon = int(e.polygon), v.made = e;
                       ++v.fragments;
                   },
                   [&](const PolygonScanned& e) { v.polygon = int(e.polygon), v.made.reset(); },
                   [&](const FragmentResolved& e) {
                       std::vector<Fragment>& list = v.lists[v.at(e.x, e.y)];
                       if (e.order == 0)  // the machine resolves nearest first: sort as it did (equal depths keep their order)
                           std::stable_sort(list.begin(), list.end(), [](const Fragment& a, const Fragment& b) { return a.depth < b.depth; });
                       v.x = e.x, v.y = e.y, v.fragment = e, v.polygon = -1, v.made.reset();
                   },
                   [&](const PixelResolved& e) {
                       const std::size_t k = v.at(e.x, e.y);
                       v.rgba[k] = {e.r, e.g, e.b, e.a}, v.resolved[k] = 1;
                       v.x = e.x, v.y = e.y, v.pixel = e, v.fragment.reset();
                       ++v.pixels_resolved;
                   },
                   [&](const ABufferFinished&) { v.done = true, v.x = v.y = -1, v.fragment.reset(), v.made.reset(); },
               },
               event);
}

std::size_t approx_bytes(const ABufferView& v) {
    std::size_t n = sizeof(ABufferView) + v.lists.capacity() * sizeof(std::vector<Fragment>) + v.rgba.capacity() * sizeof(glm::dvec4) + v.resolved.capacity();
    for (const auto& l : v.lists) n += l.capacity() * sizeof(Fragment);
    return n;
}

ABufferSession::ABufferSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string ABufferSession::sentence_of(const ABufferEvent& e, const ABufferView&) { return describe(e); }
std::string ABufferSession::describe_event(const ABufferEvent& e) const { return sentence_of(e, view()); }
std::string ABufferSession::speak_event(const ABufferEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<ABufferEvent>& ABufferSession::table() const { return abuffer_lines; }

const FamilyFacts ABufferSession::facts = {
    .topic = "A-buffer",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_abuffer,
};

}  // namespace hsr::viz
