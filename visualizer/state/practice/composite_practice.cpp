// SPDX-License-Identifier: MIT
// Practice for alpha compositing: two or three panes of glass across the view, nearest first, with colours in fifths
// and opacities a hand can multiply; the question asks A′ front to back after some layer, or a channel of the
// premultiplied result back to front. The answer is an event of the lesson's own machine on the exercise's panes.
#include <string>

#include "compositing/compositing.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"

namespace hsr::viz::practice {
namespace {

// What the questions say, each template once (the catalogues' [exercise.compositing] translate them).
namespace say {
using algo::Saying;
constexpr Saying alpha{"compositing.alpha",
                       "Panes of glass along a pixel's ray, nearest first, straight (r, g, b, α): {layers}. Front to back, each "
                       "goes under what lies in front: C′ = C + (1 − A)·C_F, premultiplied. What is A′ after layer {layer}?"};
constexpr Saying channel{"compositing.channel",
                         "Panes of glass along a pixel's ray, nearest first, straight (r, g, b, α): {layers}. Back to front, "
                         "each goes over what lies behind: C′ = C_F + (1 − A_F)·C, premultiplied, starting from (0, 0, 0, 0). "
                         "What is the pixel's premultiplied {channel} (the {channel} of (αr, αg, αb, α))?"};
constexpr Saying all[] = {alpha, channel};
}  // namespace say

std::optional<Exercise> compositing_exercise(Dice& d, Level level) {
    const int count = level == Level::easy ? 2 : 3;
    const std::vector<double> alphas = level == Level::hard ? std::vector<double>{0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9}
                                                            : std::vector<double>{0.25, 0.5, 0.75};
    algo::Scene scene;
    scene.name = "practice panes";
    scene.camera.eye = {0, 0, 6}, scene.camera.target = {0, 0, 0}, scene.camera.near = 1, scene.camera.far = 20;
    std::string layers_text;
    nlohmann::json given_layers = nlohmann::json::array();
    for (int i = 0; i < count; ++i) {
        algo::ScenePolygon p;
        p.id = algo::SceneId(i + 1);
        const int r = d.below(6), g = d.below(6), b = d.below(6);  // fifths: 51 / 255 = 0.2 exactly
        p.color = {std::uint8_t(51 * r), std::uint8_t(51 * g), std::uint8_t(51 * b)};
        p.opacity = d.pick(alphas);
        const double z = 1.0 - i, w = 1.0 + 0.3 * i;
        p.vertices = {{-w, -w, z, 1}, {w, -w, z, 1}, {w, w, z, 1}, {-w, w, z, 1}};
        layers_text += (i ? ", " : "") + std::string("(") + number_text(r / 5.0) + ", " + number_text(g / 5.0) + ", " +
                       number_text(b / 5.0) + ", " + number_text(p.opacity) + ")";
        given_layers.push_back({r / 5.0, g / 5.0, b / 5.0, p.opacity});
        scene.polygons.push_back(p);
    }
    std::vector<algo::CompositeEvent> events;
    auto machine = algo::composite(algo::layers_along(scene, algo::centre_ray(scene.camera)));
    while (const algo::CompositeEvent* e = machine.next()) events.push_back(*e);
    Exercise e;
    const bool ask_alpha = d.coin();
    if (ask_alpha) {
        const int layer = 1 + d.below(count - 1);
        for (std::size_t k = 0; k < events.size(); ++k)
            if (const auto* u = std::get_if<algo::UnderApplied>(&events[k]); u && int(u->layer) == layer) {
                e.answer = decimal_text(u->alpha, 4);
                e.deciding = algo::describe(events[k]);
                e.deciding_step = k;
            }
        if (e.deciding.empty()) return std::nullopt;  // stopped early before it (an opaque pane in front)
        e.ask(Wording(say::alpha, {{"layers", layers_text}, {"layer", std::to_string(layer)}}));
        e.given = {{"kind", "compositing_alpha"}, {"layers", given_layers}, {"layer", layer}};
    } else {
        static const char* const channels[] = {"r", "g", "b"};
        const int channel = d.below(3);
        for (std::size_t k = 0; k < events.size(); ++k)
            if (const auto* o = std::get_if<algo::OverApplied>(&events[k]); o && o->layer == 0) {
                const double v[] = {o->after.r, o->after.g, o->after.b};
                e.answer = decimal_text(v[channel], 4);
                e.deciding = algo::describe(events[k]);
                e.deciding_step = k;
            }
        if (e.deciding.empty()) return std::nullopt;
        e.ask(Wording(say::channel, {{"layers", layers_text}, {"channel", channels[channel]}}));
        e.given = {{"kind", "compositing_channel"}, {"layers", given_layers}, {"channel", channel}};
    }
    e.tolerance = 0.005;
    e.scene = std::move(scene);
    e.algorithm = "alpha_compositing";
    return e;
}

}  // namespace

std::vector<Topic> compositing_topics() {
    return {{"compositing", "Alpha compositing: A′ and premultiplied channels", {"alpha_compositing"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return compositing_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
