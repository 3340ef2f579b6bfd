// SPDX-License-Identifier: MIT
#include "scene/random_scene.h"

#include <algorithm>
#include <numeric>

#include "core/portable_random.h"

namespace hsr::algo {

Scene random_triangles(RandomTriangles o) {
    Scene s;
    s.name = "random triangles";
    s.source = "random_triangles(seed " + std::to_string(o.seed) + ")";
    s.camera = {.eye = {0, 0, 10}, .target = {0, 0, 0}, .fov_y = 60, .near = o.near, .far = o.far};
    PortableRandom rng(o.seed);
    const auto centre = [&] { return rng.uniform(-4, 4); };
    const auto offset = [&] { return rng.uniform(-o.size, o.size); };
    const auto channel = [&] { return std::uint8_t(rng.integer(40, 255)); };
    for (std::size_t i = 0; i < o.count; ++i) {  // (braced lists: evaluated left to right)
        const glm::dvec3 c{centre(), centre(), centre()};
        ScenePolygon p{SceneId(i + 1), {channel(), channel(), channel()}, {}};
        for (int k = 0; k < 3; ++k) p.vertices.emplace_back(c + glm::dvec3{offset(), offset(), offset()}, 1.0);
        s.polygons.push_back(std::move(p));
    }
    return s;
}

Scene cell_maze(CellMaze o) {
    Scene s;
    s.name = "cell maze";
    s.source = "cell_maze(" + std::to_string(o.rows) + "x" + std::to_string(o.cols) + ", seed " + std::to_string(o.seed) + ")";
    s.camera = {.fov_y = 70, .aspect = 1.333, .near = 0.05, .far = 4.0 * (o.rows + o.cols)};
    const double size = 4, door = 1.2;
    const auto name = [](std::uint32_t r, std::uint32_t c) { return "r" + std::to_string(r) + "c" + std::to_string(c); };
    for (std::uint32_t r = 0; r < o.rows; ++r)
        for (std::uint32_t c = 0; c < o.cols; ++c) {
            const double x = c * size, y = r * size;
            s.floor_plan.cells.push_back({name(r, c), {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}}, 0});
        }
    // Walls between neighbours, in a random order: Kruskal's maze keeps those that join two parts, and some others
    struct Wall {
        std::uint32_t a, b;
        bool vertical;  // between (r, c) and (r, c + 1)
    };
    std::vector<Wall> walls;
    for (std::uint32_t r = 0; r < o.rows; ++r)
        for (std::uint32_t c = 0; c < o.cols; ++c) {
            if (c + 1 < o.cols) walls.push_back({r * o.cols + c, r * o.cols + c + 1, true});
            if (r + 1 < o.rows) walls.push_back({r * o.cols + c, (r + 1) * o.cols + c, false});
        }
    PortableRandom rng(o.seed);
    rng.shuffle(walls);
    std::vector<std::uint32_t> part(o.rows * o.cols);
    std::iota(part.begin(), part.end(), 0u);
    const auto find = [&](std::uint32_t i) {
        while (part[i] != i) i = part[i] = part[part[i]];
        return i;
    };
    for (const Wall& w : walls) {
        const bool joins = find(w.a) != find(w.b);
        if (!joins && rng.unit() >= o.extra_doors) continue;
        part[find(w.a)] = find(w.b);
        const double x = (w.a % o.cols) * size, y = (w.a / o.cols) * size, t = rng.uniform(0.2, size - door - 0.2);
        ScenePortal p{{s.floor_plan.cells[w.a].name, s.floor_plan.cells[w.b].name}, {}, {}, 0, s.floor_plan.height, {}, 0};
        if (w.vertical) p.from = {x + size, y + t}, p.to = {x + size, y + t + door};
        else p.from = {x + t, y + size}, p.to = {x + t + door, y + size};
        s.floor_plan.portals.push_back(p);
    }
    s.floor_plan.eye = glm::dvec2(size / 2, size / 2);
    s.floor_plan.look = glm::dvec2(o.cols * size, o.rows * size);
    s.camera.eye = {size / 2, s.floor_plan.eye_height, -size / 2};
    s.camera.target = {o.cols * size, s.floor_plan.eye_height, -double(o.rows) * size};
    return s;
}

}  // namespace hsr::algo
