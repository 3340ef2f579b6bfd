// SPDX-License-Identifier: MIT
#include "culling/hiz.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/events.h"
#include "core/overloaded.h"
#include "culling/view_frustum.h"
#include "zbuffer/depth_format.h"

namespace hsr::algo {

ZPyramid::ZPyramid(const std::vector<std::uint32_t>& depth, int w, int h) {
    levels_.push_back({w, h, depth});
    while (levels_.back().width > 1 || levels_.back().height > 1) {
        const Level& below = levels_.back();
        const int lw = (below.width + 1) / 2, lh = (below.height + 1) / 2;
        levels_.push_back({lw, lh, std::vector<std::uint32_t>(std::size_t(lw) * std::size_t(lh), 0)});
    }
    update(depth, {0, 0, w, h});
}

std::uint32_t ZPyramid::at(std::size_t level, int x, int y) const {
    const Level& l = levels_[level];
    return l.depth[std::size_t(y) * std::size_t(l.width) + std::size_t(x)];
}

void ZPyramid::update(const std::vector<std::uint32_t>& depth, PixelRect r) {
    Level& base = levels_[0];
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(base.width) + std::size_t(x);
            base.depth[k] = depth[k];
        }
    for (std::size_t l = 1; l < levels_.size(); ++l) {
        r = {r.x0 / 2, r.y0 / 2, (r.x1 + 1) / 2, (r.y1 + 1) / 2};
        const Level& below = levels_[l - 1];
        Level& level = levels_[l];
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                std::uint32_t farthest = 0;  // of the children that exist (an odd edge has fewer)
                for (int cy = 2 * y; cy < std::min(2 * y + 2, below.height); ++cy)
                    for (int cx = 2 * x; cx < std::min(2 * x + 2, below.width); ++cx)
                        farthest = std::max(farthest, below.depth[std::size_t(cy) * std::size_t(below.width) + std::size_t(cx)]);
                level.depth[std::size_t(y) * std::size_t(level.width) + std::size_t(x)] = farthest;
            }
    }
}

bool ZPyramid::occluded(PixelRect f, std::uint32_t near, std::uint32_t* texels_tested) const {
    std::uint32_t tested = 0;
    f = {std::max(f.x0, 0), std::max(f.y0, 0), std::min(f.x1, levels_[0].width), std::min(f.y1, levels_[0].height)};
    const bool hidden = f.empty() || occluded(levels_.size() - 1, 0, 0, f, near, tested);
    if (texels_tested) *texels_tested = tested;
    return hidden;
}

// isOccluded(g, texel (x, y) of `level`): behind the texel's farthest depth, or hidden in each child it overlaps
bool ZPyramid::occluded(std::size_t level, int x, int y, PixelRect f, std::uint32_t near, std::uint32_t& tested) const {
    ++tested;
    if (near > at(level, x, y)) return true;  // nearZ behind everything the texel holds
    if (level == 0) return false;
    const Level& below = levels_[level - 1];
    for (int cy = 2 * y; cy < std::min(2 * y + 2, below.height); ++cy)
        for (int cx = 2 * x; cx < std::min(2 * x + 2, below.width); ++cx) {
            const int span = 1 << (level - 1);  // level-0 pixels across a child texel
            const PixelRect covers{cx * span, cy * span, (cx + 1) * span, (cy + 1) * span};
            if (covers.x1 <= f.x0 || covers.x0 >= f.x1 || covers.y1 <= f.y0 || covers.y0 >= f.y1) continue;  // not under g
            if (!occluded(level - 1, cx, cy, f, near, tested)) return false;
        }
    return true;
}

BoxOnScreen box_on_screen(const Aabb& box, const Scene& scene, const ZBufferOptions& o) {
    BoxOnScreen s;
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, z = 1e300;
    const glm::dmat4 vp = view_projection(scene.camera);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec4 c = vp * glm::dvec4(box.corner(k), 1.0);
        if (c.w <= 0 || c.z < -c.w) {  // behind the eye or the near plane: the box reaches the eye
            s.reaches_eye = true;
            break;
        }
        const glm::dvec3 ndc = glm::dvec3(c) / c.w;
        x0 = std::min(x0, (ndc.x + 1) * 0.5 * o.viewport.width), x1 = std::max(x1, (ndc.x + 1) * 0.5 * o.viewport.width);
        y0 = std::min(y0, (1 - ndc.y) * 0.5 * o.viewport.height), y1 = std::max(y1, (1 - ndc.y) * 0.5 * o.viewport.height);
        z = std::min(z, (ndc.z + 1) * 0.5);
    }
    if (s.reaches_eye) {
        s.footprint = {0, 0, o.viewport.width, o.viewport.height};
        return s;
    }
    // every pixel whose centre the box's projection could cover, and one more each way for the rasteriser's snapping
    // (clamped to just outside the screen first: a box far off to one side projects to coordinates no int holds)
    const auto pixel = [](double v, int size) { return int(std::clamp(v, -2.0, double(size) + 2)); };
    s.footprint = {pixel(std::floor(x0), o.viewport.width) - 1, pixel(std::floor(y0), o.viewport.height) - 1,
                   pixel(std::ceil(x1), o.viewport.width) + 1, pixel(std::ceil(y1), o.viewport.height) + 1};
    if (!(x0 <= x1 && y0 <= y1)) s.footprint = {0, 0, o.viewport.width, o.viewport.height};  // NaN: the whole screen
    s.near = std::uint32_t(code_of_window_depth(o.format, std::max(z, 0.0), o.range, o.perspective));
    s.near = s.near > 0 ? s.near - 1 : 0;  // one code nearer: rounding of the corners' depths must not hide the box
    return s;
}

namespace {
// What Hi-Z culling says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying outside{"hiz.outside", "Node {node}: outside the frustum."};
constexpr Saying occluded{"hiz.occluded",
                          "Node {node}: occluded ({texels} pyramid {texels?texel|texels} tested); its {primitives} {primitives?primitive is|primitives are} left out."};
constexpr Saying visible{"hiz.visible",
                         "Node {node}: visible after {texels} {texels?texel|texels}; {rendered} {rendered?primitive|primitives} rendered, the pyramid updated."};
constexpr Saying visible_empty{"hiz.visible_empty",
                               "Node {node}: visible after {texels} {texels?texel|texels}; it renders no primitive of its own (the pyramid is unchanged)."};
constexpr Saying done{"hiz.done",
                      "Done: {nodes} nodes, {occluded} occluded; {rendered} {rendered?primitive|primitives} rendered, {left_out} left out."};
constexpr Saying all[] = {outside, occluded, visible, visible_empty, done};
}  // namespace say
}  // namespace

std::span<const Saying> hiz_sayings() { return say::all; }

Phrase phrase(const HizEvent& event) {
    const auto n = [](std::uint32_t v) { return std::to_string(v); };
    return std::visit(overloaded{
                          [&](const HizNodeTested& e) {
                              const Saying& saying = e.outcome == HizOutcome::outside_frustum ? say::outside
                                                     : e.outcome == HizOutcome::occluded      ? say::occluded
                                                     : e.primitives_rendered == 0             ? say::visible_empty
                                                                                              : say::visible;
                              return Phrase(saying, {{"node", n(e.node)}, {"texels", n(e.texels_tested)},
                                                     {"primitives", n(e.subtree_primitives)}, {"rendered", n(e.primitives_rendered)}});
                          },
                          [&](const HizFinished& e) {
                              return Phrase(say::done, {{"nodes", n(e.nodes)}, {"occluded", n(e.occluded_nodes)},
                                                        {"rendered", n(e.rendered)}, {"left_out", n(e.left_out)}});
                          },
                      },
                      event);
}

std::string describe(const HizEvent& event) { return phrase(event).english(); }

Steps<HizEvent, HizResult> hiz_render(const Scene* scene, const Hierarchy* h, ZBufferOptions o, std::vector<std::uint8_t> enabled,
                                      std::vector<std::uint8_t> draw_first) {
    HizResult out{cleared_buffers(o), std::vector<std::uint8_t>(h->boxes.size(), 0), 0, 0, 0, 0};
    const auto render = [&](std::uint32_t p) {
        const ScenePolygon& poly = scene->polygons[p];
        std::vector<glm::dvec4> clip;
        for (const auto& v : poly.vertices) clip.push_back(to_clip(*scene, v));
        const ScreenPolygon sp = project_polygon(poly.id, poly.color, std::move(clip), o.viewport);
        fill_polygon(out.buffers, sp, std::int32_t(p), o);
        out.rendered[p] = 1;
        return sp;
    };
    std::uint32_t nodes = 0, rendered = 0;
    // frame-to-frame coherence: what the previous frame saw first, then the pyramid over it
    for (std::uint32_t p = 0; p < draw_first.size() && p < h->boxes.size(); ++p)
        if (draw_first[p] && (enabled.empty() || enabled[p])) render(p), ++rendered, ++out.drawn_first;
    ZPyramid pyramid(out.buffers.depth, o.viewport.width, o.viewport.height);
    const std::vector<Plane> frustum = view_frustum(scene->camera);
    const Vec3 eye = scene->camera.eye;
    std::vector<std::uint32_t> stack;
    if (!h->nodes.empty()) stack.push_back(0);
    while (!stack.empty()) {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        const HierarchyNode& node = h->nodes[n];
        ++nodes;
        HizNodeTested e{n, HizOutcome::rendered, {}, 0, 0, 0, node.subtree_primitives};
        // view-frustum culling first, then isOccluded against the pyramid
        if (!box_passes(node.box, frustum, 0x3f)) {
            e.outcome = HizOutcome::outside_frustum, ++out.outside_nodes;
            co_yield e;
            continue;
        }
        const BoxOnScreen on_screen = box_on_screen(node.box, *scene, o);
        e.footprint = on_screen.footprint, e.near = on_screen.near;
        if (!on_screen.reaches_eye && pyramid.occluded(on_screen.footprint, on_screen.near, &e.texels_tested)) {
            e.outcome = HizOutcome::occluded, ++out.occluded_nodes;
            out.texels_tested += e.texels_tested;
            co_yield e;
            continue;
        }
        out.texels_tested += e.texels_tested;
        // render each primitive of N and update Zp over what it covered
        PixelRect touched{o.viewport.width, o.viewport.height, 0, 0};
        for (std::uint32_t p : node.primitives) {
            if ((!enabled.empty() && !enabled[p]) || out.rendered[p]) continue;  // culled before, or drawn first
            const ScreenPolygon sp = render(p);
            ++rendered, ++e.primitives_rendered;
            if (sp.status == ScreenStatus::drawn)
                touched = {std::min(touched.x0, 0), std::min(touched.y0, std::max(sp.row_begin, 0)), o.viewport.width,
                           std::max(touched.y1, std::min(sp.row_end, o.viewport.height))};
        }
        if (!touched.empty()) pyramid.update(out.buffers.depth, touched);
        co_yield e;
        // each child, front to back (nearest box first)
        std::vector<std::uint32_t> children = node.children;
        const auto distance = [&](std::uint32_t c) { return glm::distance(glm::clamp(eye, h->nodes[c].box.lo, h->nodes[c].box.hi), eye); };
        std::sort(children.begin(), children.end(), [&](std::uint32_t a, std::uint32_t b) { return distance(a) < distance(b); });
        for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(*it);
    }
    // left out: of the primitives that reached this stage (the enabled ones), those not rendered
    const auto reached = enabled.empty() ? std::uint32_t(h->boxes.size()) : std::uint32_t(std::count(enabled.begin(), enabled.end(), 1));
    co_yield HizFinished{nodes, out.occluded_nodes, rendered, reached - rendered};
    co_return out;
}

}  // namespace hsr::algo
