#include "state/zbuffer_session.h"

#include <array>

#include "core/overloaded.h"
#include "raycast/ray_cast.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lectures' zBuffer(), with the depth stepped by the plane equation's forward difference.
constexpr std::array<std::string_view, 10> fill_lines = {
    "for all pixels (x, y):",
    "  Depth[x, y] = far;  Image[x, y] = background",
    "for each polygon P:",
    "  for each scan line y that P covers:",
    "    [x0, x1) = pixels of y inside P     /* top-left rule */",
    "    z = depth of P at (x0, y)",
    "    for x = x0 .. x1 - 1:",
    "      if (z nearer than Depth[x, y]):",
    "        Image[x, y] = colour of P;  Depth[x, y] = z",
    "      z = z + (-a/c)                   /* forward difference */",
};

ZBufferSession::PlayerType make_player(const Scene& scene, Viewport grid, DepthFormat format, PlayerOptions options) {
    const ZBufferOptions o = zbuffer_options(scene, grid, format, EventDetail::pixel);
    auto polygons = std::make_shared<const std::vector<ScreenPolygon>>(project_polygons(scene, grid));
    ZView initial = initial_view(polygons, o);
    return ZBufferSession::PlayerType(zbuffer_fill(*polygons, o), std::move(initial), options);
}

// How many pixels the finished fill shows differently from the ray cast through the same pixel centres.
std::size_t unlike_ray_cast(const Scene& scene, Viewport grid, DepthFormat format) {
    const FrameDepth z = zbuffer_fill(project_polygons(scene, grid), zbuffer_options(scene, grid, format, EventDetail::polygon)).run_to_end();
    const RayCastResult r = ray_cast(scene, {.viewport = grid, .detail = RayDetail::ray}).run_to_end();
    std::size_t n = 0;
    for (std::size_t k = 0; k < z.polygon.size(); ++k) n += z.image.ids[k] != r.image.ids[k];
    return n;
}

}  // namespace

ZBufferSession::ZBufferSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, make_player(grid_scene(lesson), lesson.grid, lesson.depth_format, options)),
      scene_(grid_scene(lesson)),
      format_(lesson.depth_format),
      options_(options),
      unlike_ray_cast_(unlike_ray_cast(scene_, lesson.grid, format_)) {}

void ZBufferSession::rerun() {
    replace_player(make_player(scene_, lesson().grid, format_, options_));
    unlike_ray_cast_ = unlike_ray_cast(scene_, lesson().grid, format_);
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

std::span<const std::string_view> ZBufferSession::pseudocode() const { return fill_lines; }

std::string ZBufferSession::describe_event(const ZBufferEvent& e) const { return describe(e, format_); }

int ZBufferSession::line_of(const ZBufferEvent& event) const {
    return std::visit(overloaded{
                          [](const BufferCleared&) { return 1; },
                          [](const PolygonFillStarted&) { return 2; },
                          [](const PolygonSkipped&) { return 2; },
                          [](const SpanStarted&) { return 5; },
                          [](const PixelTested&) { return 7; },
                          [](const DepthWritten&) { return 8; },
                          [](const DepthTestFailed&) { return 9; },
                          [](const PolygonFillFinished&) { return 2; },
                          [](const FillFinished&) { return 2; },
                          [](const FillStepBoundReached&) { return 6; },
                      },
                      event);
}

// A Step is a span (or a polygon's start and end); the pixels inside it are micro-steps.
bool ZBufferSession::is_major(const ZBufferEvent& e) const {
    return !std::holds_alternative<PixelTested>(e) && !std::holds_alternative<DepthWritten>(e) &&
           !std::holds_alternative<DepthTestFailed>(e);
}

}  // namespace hsr::viz
