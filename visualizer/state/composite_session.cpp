// SPDX-License-Identifier: MIT
#include "state/composite_session.h"

#include <random>

#include "core/overloaded.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The UBC notes' compositing, in the order the lesson takes it.
const Pseudocode<CompositeEvent> composite_lines = {
    {"layers = the polygons the pixel's ray passes, nearest first", {step<LayersFound>()}},
    {"for each layer:  (r, g, b, α) → (αr, αg, αb, α)", {step<LayerPremultiplied>()}},
    {"C = (0, 0, 0, 0);  for each layer F, farthest first:", {}},
    {"  C = F over C = C_F + (1 − A_F)·C", {step<OverApplied>()}},
    {"C = (0, 0, 0, 0);  for each layer F, nearest first:", {}},
    {"  if A ≥ 0.999: stop (nothing behind can show)", {step<EarlyStop>()}},
    {"  C = C over F = C + (1 − A)·C_F", {step<UnderApplied>()}},
    {"compare the two orders", {step<OrdersCompared>()}},
    {"(F over M) over B  =?  F over (M over B)", {step<AssociativityChecked>()}},
    {"for each Porter–Duff op:  F_A·A + F_B·B", {step<PorterDuffApplied>()}},
    {"done", {step<CompositeFinished>()}},
};

// Four panes across the view, one behind the other, of random colours and opacities (quarters, so that every α
// the lesson computes is exact).
std::optional<Scene> random_panes(std::uint32_t seed, bool) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> channel(40, 255), quarter(1, 4);
    Scene s;
    s.name = "random panes " + std::to_string(seed);
    s.camera.eye = {0, 0, 6}, s.camera.target = {0, 0, 0}, s.camera.near = 1, s.camera.far = 20;
    for (int i = 0; i < 4; ++i) {
        ScenePolygon p;
        p.id = SceneId(i + 1);
        p.color = {std::uint8_t(channel(rng)), std::uint8_t(channel(rng)), std::uint8_t(channel(rng))};
        p.opacity = quarter(rng) / 4.0;
        const double z = 1.5 - i, w = 1.0 + 0.4 * i;
        p.vertices = {{-w, -w, z, 1}, {w, -w, z, 1}, {w, w, z, 1}, {-w, w, z, 1}};
        s.polygons.push_back(p);
    }
    return s;
}

}  // namespace

CompositeView composite_initial_view(std::vector<Layer> layers) {
    CompositeView v;
    v.layers = std::make_shared<const std::vector<Layer>>(std::move(layers));
    return v;
}

CompositeSession::RunType CompositeSession::machine(const Lesson& lesson) {
    std::vector<Layer> layers = layers_along(lesson.scene, centre_ray(lesson.scene.camera));
    CompositeView initial = composite_initial_view(layers);
    return {composite(std::move(layers)), std::move(initial)};
}

void reduce(CompositeView& v, const CompositeEvent& event) {
    std::visit(overloaded{
                   [&](const LayersFound&) {},
                   [&](const LayerPremultiplied& e) { v.premultiplied.push_back(e.premultiplied); },
                   [&](const OverApplied& e) { v.back_to_front = e.after, v.straight = e.straight_after, v.over_layer = int(e.layer); },
                   [&](const UnderApplied& e) { v.front_to_back = e.after, v.under_layer = int(e.layer); },
                   [&](const EarlyStop& e) { v.stopped = e; },
                   [&](const OrdersCompared& e) { v.compared = e; },
                   [&](const AssociativityChecked& e) { v.associativity = e; },
                   [&](const PorterDuffApplied& e) { v.porter_duff.push_back(e); },
                   [&](const CompositeFinished&) { v.done = true; },
               },
               event);
    v.last = event;
}

std::size_t approx_bytes(const CompositeView& v) {
    return sizeof(CompositeView) + v.premultiplied.capacity() * sizeof(Rgba) + v.porter_duff.capacity() * sizeof(PorterDuffApplied);
}

CompositeSession::CompositeSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string CompositeSession::sentence_of(const CompositeEvent& e, const CompositeView&) { return describe(e); }
std::string CompositeSession::describe_event(const CompositeEvent& e) const { return sentence_of(e, view()); }
std::string CompositeSession::speak_event(const CompositeEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<CompositeEvent>& CompositeSession::table() const { return composite_lines; }

const FamilyFacts CompositeSession::facts = {
    .topic = "Compositing",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &random_panes,
    .measure = &analysis::measure_compositing,
};

}  // namespace hsr::viz
