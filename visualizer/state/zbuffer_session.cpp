// SPDX-License-Identifier: MIT
#include "state/zbuffer_session.h"

#include <algorithm>
#include <tuple>
#include <utility>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "raycast/ray_cast.h"
#include "core/numeric.h"
#include "geometry/exact_collinear.h"
#include "scene/load_scene.h"
#include "state/long_work.h"
#include "state/strings.h"
#include "core/okabe_ito.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lectures' zBuffer(), with the depth stepped by the plane equation's forward difference.
const Pseudocode<ZBufferEvent> fill_lines = {
    {"for all pixels (x, y):", {}},
    {"  Depth[x, y] = far;  Image[x, y] = background", {step<BufferCleared>()}},
    {"for each polygon P:", {step<PolygonFillStarted>(), step<PolygonSkipped>(), step<PolygonFillFinished>(), step<FillFinished>()}},
    {"  for each scan line y that P covers:", {}},
    {"    [x0, x1) = pixels of y inside P     /* top-left rule */", {}},
    {"    z = depth of P at (x0, y)", {step<SpanStarted>()}},
    {"    for x = x0 .. x1 - 1:", {step<FillStepBoundReached>()}},
    {"      if (z nearer than Depth[x, y]):", {micro<PixelTested>()}},
    {"        Image[x, y] = colour of P;  Depth[x, y] = z", {micro<DepthWritten>()}},
    {"      z = z + (-a/c)                   /* forward difference */", {micro<DepthTestFailed>()}},
};

// The fill of a scene (the lesson's, or as edited) into the grid, pixel by pixel.
ZBufferSession::RunType fill_run(const Scene& scene, Viewport grid, DepthFormat format) {
    const ZBufferOptions o = zbuffer_options(scene, grid, format, EventDetail::pixel);
    auto polygons = std::make_shared<const std::vector<ScreenPolygon>>(project_polygons(scene, grid));
    ZView initial = initial_view(polygons, o);
    return {zbuffer_fill(*polygons, o), std::move(initial)};
}

// Whether the centre of pixel (x, y) lies exactly on an edge of the polygon (sub-pixel fixed point: exact).
bool centre_on_edge(const ScreenPolygon& p, int x, int y) {
    const std::int64_t cx = std::int64_t(x) * subpixels + subpixels / 2, cy = std::int64_t(y) * subpixels + subpixels / 2;
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        const ScreenVertex& a = p.vertices[i];
        const ScreenVertex& b = p.vertices[(i + 1) % p.vertices.size()];
        // clipped to the view volume, the coordinates are within the grid's few thousand × 256: the products fit
        const std::int64_t cross = (b.x - a.x) * (cy - a.y) - (b.y - a.y) * (cx - a.x);
        if (cross == 0 && std::min(a.x, b.x) <= cx && cx <= std::max(a.x, b.x) && std::min(a.y, b.y) <= cy && cy <= std::max(a.y, b.y))
            return true;
    }
    return false;
}

// How many pixels the finished fill shows differently from the ray cast through the same pixel centres (the grid's
// walk sees what brute force sees, ties included, and a million-triangle city is cast in a moment, not 25 s), and
// how many of those have their centre on an edge of either polygon shown there.
std::pair<std::size_t, std::size_t> unlike_ray_cast(const Scene& scene, Viewport grid, DepthFormat format) {
    const auto polygons = project_polygons(scene, grid);
    const FrameDepth z = LongWork::run_to_end(zbuffer_fill(polygons, zbuffer_options(scene, grid, format, EventDetail::polygon)));
    const RayCastResult r = LongWork::run_to_end(ray_cast(scene, {.viewport = grid, .acceleration = Acceleration::grid, .detail = RayDetail::ray}));
    std::size_t n = 0, on_edges = 0;
    for (std::size_t k = 0; k < z.polygon.size(); ++k) {
        if (z.image.ids[k] == r.image.ids[k]) continue;
        ++n;
        const int x = int(k % std::size_t(grid.width)), y = int(k / std::size_t(grid.width));
        const bool on_edge = std::any_of(polygons.begin(), polygons.end(), [&](const ScreenPolygon& p) {
            return p.status == ScreenStatus::drawn && (p.id == z.image.ids[k] || p.id == r.image.ids[k]) && centre_on_edge(p, x, y);
        });
        on_edges += on_edge;
    }
    return {n, on_edges};
}

}  // namespace

ZBufferSession::RunType ZBufferSession::machine(const Lesson& lesson) {
    return fill_run(grid_scene(lesson), lesson.grid, lesson.depth_format);
}

ZBufferSession::ZBufferSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options),
      scene_(grid_scene(lesson)),
      format_(lesson.depth_format),
      options_(options),
      unlike_ray_cast_(0) {
    std::tie(unlike_ray_cast_, unlike_on_edges_) = unlike_ray_cast(scene_, lesson.grid, format_);
}

std::optional<glm::dvec3> ZBufferSession::on_screen(const glm::dvec4& world) const {
    const glm::dvec4 c = view_projection(scene_.camera) * glm::dvec4(glm::dvec3(world), 1.0);
    if (!(c.w > 0)) return std::nullopt;
    const Viewport vp = lesson().grid;
    return glm::dvec3((c.x / c.w + 1) / 2 * vp.width, (1 - c.y / c.w) / 2 * vp.height, (c.z / c.w + 1) / 2);
}

glm::dvec4 ZBufferSession::world_at(glm::dvec2 pixel, double depth) const {
    const Viewport vp = lesson().grid;
    const glm::dvec4 ndc(pixel.x / vp.width * 2 - 1, 1 - pixel.y / vp.height * 2, depth * 2 - 1, 1);
    const glm::dvec4 w = glm::inverse(view_projection(scene_.camera)) * ndc;
    return {glm::dvec3(w) / w.w, 1.0};
}

bool ZBufferSession::edit(Scene edited, std::optional<std::pair<std::size_t, std::size_t>> moved) {
    try {  // the fill takes convex polygons with area: an edit that breaks that is not made
        for (const ScenePolygon& p : edited.polygons) {
            if (!has_area(p.vertices)) return false;
            require_convex(p);
        }
    } catch (const InvalidInput&) {
        return false;
    }
    if (edited.polygons.empty()) return false;
    history_.record(scene_, moved && last_moved_ == moved);
    last_moved_ = moved;
    scene_ = std::move(edited);
    rerun();
    return true;
}

bool ZBufferSession::move_vertex(std::size_t polygon, std::size_t vertex, glm::dvec2 pixel) {
    if (polygon >= scene_.polygons.size() || vertex >= scene_.polygons[polygon].vertices.size()) return false;
    const auto at = on_screen(scene_.polygons[polygon].vertices[vertex]);
    if (!at) return false;
    Scene edited = scene_;
    edited.polygons[polygon].vertices[vertex] = world_at(pixel, at->z);
    return edit(std::move(edited), std::pair{polygon, vertex});
}

bool ZBufferSession::delete_polygon(std::size_t polygon) {
    if (polygon >= scene_.polygons.size()) return false;
    Scene edited = scene_;
    edited.polygons.erase(edited.polygons.begin() + std::ptrdiff_t(polygon));
    return edit(std::move(edited));
}

bool ZBufferSession::add_triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    // three points on one line of the screen make no triangle (taken back to the world in doubles, they would make
    // a sliver of rounding's width)
    if (algo::collinear_exactly(std::vector<algo::Vec3>{{a, 0}, {b, 0}, {c, 0}})) return false;
    // at the window depth of the middle of the scene's depths, so that it lies among the polygons there
    double lo = 1, hi = 0;
    for (const ScenePolygon& p : scene_.polygons)
        for (const auto& v : p.vertices)
            if (const auto s = on_screen(v)) lo = std::min(lo, s->z), hi = std::max(hi, s->z);
    const double depth = lo <= hi ? (lo + hi) / 2 : 0.5;
    SceneId id = 1;
    for (const ScenePolygon& p : scene_.polygons) id = std::max(id, p.id + 1);
    Scene edited = scene_;
    edited.polygons.push_back({id, okabe_ito::as<Color>(okabe_ito::series[std::size_t(id) % okabe_ito::series.size()]), {world_at(a, depth), world_at(b, depth), world_at(c, depth)}});
    return edit(std::move(edited));
}

bool ZBufferSession::undo() {
    if (!history_.undo(scene_)) return false;
    last_moved_.reset();
    rerun();
    return true;
}

bool ZBufferSession::redo() {
    if (!history_.redo(scene_)) return false;
    last_moved_.reset();
    rerun();
    return true;
}

void ZBufferSession::rerun() {
    auto run = fill_run(scene_, lesson().grid, format_);
    replace_player(PlayerType(std::move(run.machine), std::move(run.initial), options_));
    std::tie(unlike_ray_cast_, unlike_on_edges_) = unlike_ray_cast(scene_, lesson().grid, format_);
}

void ZBufferSession::set_format(DepthFormat f) {
    if (f == format_) return;
    format_ = f;
    rerun();
}

void ZBufferSession::set_range(DepthRange r) {
    if (!(r.near > 0 && r.near < r.far) || (r.near == scene_.camera.near && r.far == scene_.camera.far)) return;
    scene_.camera.near = r.near, scene_.camera.far = r.far;
    rerun();
}

std::string ZBufferSession::sentence_of(const ZBufferEvent& e, const ZView& view) { return describe(e, view.format); }
std::string ZBufferSession::describe_event(const ZBufferEvent& e) const { return sentence_of(e, view()); }
std::string ZBufferSession::speak_event(const ZBufferEvent& e) const { return window_strings().say(phrase(e, view().format)); }

const Pseudocode<ZBufferEvent>& ZBufferSession::table() const { return fill_lines; }

const FamilyFacts ZBufferSession::facts = {
    .topic = "Z-buffer",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return expects_from_renderer(s, "zbuffer"); },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_zbuffer,
};

}  // namespace hsr::viz
