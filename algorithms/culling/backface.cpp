// SPDX-License-Identifier: MIT
#include "culling/backface.h"

#include <cmath>

#include <cstdio>

#include <glm/geometric.hpp>

#include "clipping/sutherland_hodgman.h"
#include "core/numeric.h"
#include "core/overloaded.h"
#include "core/phrase.h"
#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {

Facing by_sign(double front_positive) {
    return front_positive > 0 ? Facing::front : front_positive < 0 ? Facing::back : Facing::edge_on;
}

// Signed area of the polygon's visible part on the screen (NDC), by the shoelace formula.
std::optional<double> screen_area(const Face& f, const glm::dmat4& view_projection) {
    ClipPolygon clip{f.id, {}};
    for (const Vec3& v : f.vertices) clip.vertices.push_back(view_projection * glm::dvec4(v, 1.0));
    // clipped at the near plane (and the rest of the volume) before the divide, so w > 0 for every vertex
    const PolygonClip visible = sutherland_hodgman(clip, {.space = ClipSpace::homogeneous}).run_to_end();
    if (visible.vertices.size() < 3) return std::nullopt;
    std::vector<glm::dvec2> on_screen;
    for (const Vec4& v : visible.vertices) on_screen.emplace_back(v.x / v.w, v.y / v.w);
    return 0.5 * twice_signed_area(on_screen);
}

Steps<CullEvent, std::vector<std::int32_t>> cull_machine(std::vector<Face> faces, Camera camera, BackfaceTest test,
                                                         std::vector<Plane> planes) {
    const glm::dmat4 vp = view_projection(camera);
    std::vector<std::int32_t> kept;
    std::uint32_t culled = 0;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const Face& f = faces[i];
        const Plane& plane = planes[i];
        double value = 0;
        Facing facing = Facing::edge_on;
        switch (test) {
            case BackfaceTest::view_vector: {  // v from the eye to a vertex of the polygon
                value = glm::dot(glm::normalize(f.vertices[0] - camera.eye), plane.n);
                facing = by_sign(-value);
                break;
            }
            case BackfaceTest::plane_equation:
                value = plane.distance(camera.eye);  // N · eye + D
                facing = by_sign(value);
                break;
            case BackfaceTest::screen_winding:
                if (const auto area = screen_area(f, vp)) {
                    value = *area;
                    facing = by_sign(value);
                } else {
                    facing = Facing::outside_view;
                }
                break;
        }
        co_yield FaceTested{f.id, test, facing, value};
        if (facing == Facing::front) kept.push_back(f.id);
        else ++culled;
    }
    co_yield CullingFinished{std::uint32_t(faces.size()), culled};
    co_return kept;
}

}  // namespace

Steps<CullEvent, std::vector<std::int32_t>> cull_back_faces(std::vector<Face> faces, Camera camera, BackfaceTest test) {
    std::vector<Plane> planes;
    for (const Face& f : faces) {
        const auto name = [&] { return "face " + std::to_string(f.id); };  // made only for an error: scenes run to 10^6 faces
        if (f.vertices.size() < 3) throw InvalidInput(name() + " has fewer than 3 vertices");
        for (std::size_t i = 0; i < f.vertices.size(); ++i)
            if (!std::isfinite(f.vertices[i].x) || !std::isfinite(f.vertices[i].y) || !std::isfinite(f.vertices[i].z))
                require_finite(glm::dvec4(f.vertices[i], 1.0), name() + " vertex " + std::to_string(i));
        Plane p;
        if (!plane_of(f.vertices, p)) throw InvalidInput(name() + " is degenerate (it has no area)");
        planes.push_back(p);
    }
    require_finite(glm::dvec4(camera.eye, 1.0), "camera eye");
    return cull_machine(std::move(faces), camera, test, std::move(planes));
}

std::vector<Face> faces_of(const Scene& scene) {
    std::vector<Face> faces;
    for (const auto& p : scene.polygons) {
        Face f{p.id, {}};
        for (const auto& v : p.vertices) f.vertices.emplace_back(v);
        faces.push_back(std::move(f));
    }
    return faces;
}

namespace {
// What back-face culling says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying view_vector{"backface.view_vector", "view vector"};
constexpr Saying plane_equation{"backface.plane_equation", "plane equation"};
constexpr Saying screen_winding{"backface.screen_winding", "screen winding"};
constexpr Saying front{"backface.front", "front-facing: kept"};
constexpr Saying back{"backface.back", "back-facing: culled"};
constexpr Saying edge_on{"backface.edge_on", "edge-on: culled"};
constexpr Saying outside_view{"backface.outside_view", "outside the view volume: culled"};
constexpr Saying screen_area{"backface.screen_area", "screen area"};
constexpr Saying tested{"backface.tested", "face {id}: {quantity} = {value}, {facing}"};
constexpr Saying finished{"backface.finished", "{tested} faces tested, {culled} culled"};
constexpr Saying all[] = {view_vector, plane_equation, screen_winding, front, back, edge_on, outside_view, screen_area, tested, finished};
}  // namespace say
}  // namespace

const Saying& term(BackfaceTest t) {
    switch (t) {
        case BackfaceTest::view_vector: return say::view_vector;
        case BackfaceTest::plane_equation: return say::plane_equation;
        case BackfaceTest::screen_winding: return say::screen_winding;
    }
    return say::view_vector;
}

const Saying& term(Facing f) {
    switch (f) {
        case Facing::front: return say::front;
        case Facing::back: return say::back;
        case Facing::edge_on: return say::edge_on;
        case Facing::outside_view: return say::outside_view;
    }
    return say::front;
}

std::string_view to_string(BackfaceTest t) { return term(t).english; }
std::string_view to_string(Facing f) { return term(f).english; }

std::span<const Saying> backface_sayings() { return say::all; }

Phrase phrase(const CullEvent& event) {
    return std::visit(overloaded{
                          [](const FaceTested& e) {
                              char value[32];
                              std::snprintf(value, sizeof value, "%.6g", e.value);
                              // the quantity tested: a formula, except the screen area, which is words
                              Terms terms{{"facing", &term(e.facing)}};
                              std::vector<NamedValue> values{{"id", std::to_string(e.id)}, {"value", value}};
                              if (e.test == BackfaceTest::screen_winding) terms.emplace_back("quantity", &say::screen_area);
                              else values.emplace_back("quantity", e.test == BackfaceTest::view_vector ? "v·n" : "N·eye + D");
                              return Phrase(say::tested, std::move(values), std::move(terms));
                          },
                          [](const CullingFinished& e) {
                              return Phrase(say::finished, {{"tested", std::to_string(e.tested)}, {"culled", std::to_string(e.culled)}});
                          },
                      },
                      event);
}

std::string describe(const CullEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
