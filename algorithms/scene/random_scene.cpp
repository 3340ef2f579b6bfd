#include "scene/random_scene.h"

#include <random>

namespace hsr::algo {

Scene random_triangles(RandomTriangles o) {
    Scene s;
    s.name = "random triangles";
    s.source = "random_triangles(seed " + std::to_string(o.seed) + ")";
    s.camera = {.eye = {0, 0, 10}, .target = {0, 0, 0}, .fov_y = 60, .near = o.near, .far = o.far};
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> centre(-4, 4), offset(-o.size, o.size);
    std::uniform_int_distribution<int> channel(40, 255);
    for (std::size_t i = 0; i < o.count; ++i) {
        const glm::dvec3 c(centre(rng), centre(rng), centre(rng));
        ScenePolygon p{SceneId(i + 1), {std::uint8_t(channel(rng)), std::uint8_t(channel(rng)), std::uint8_t(channel(rng))}, {}};
        for (int k = 0; k < 3; ++k) p.vertices.emplace_back(c + glm::dvec3(offset(rng), offset(rng), offset(rng)), 1.0);
        s.polygons.push_back(std::move(p));
    }
    return s;
}

}  // namespace hsr::algo
