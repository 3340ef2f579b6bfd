// SPDX-License-Identifier: MIT
#include "analysis/face_visibility.h"

#include "raycast/nearest_hit.h"
#include "raycast/ray_cast.h"

namespace hsr::analysis {

std::vector<std::size_t> pixels_seen(std::span<const algo::Face> faces, const algo::Camera& camera, algo::Viewport size) {
    std::vector<std::vector<algo::Vec3>> polygons;
    std::vector<algo::Plane> planes;
    for (const algo::Face& f : faces) {
        algo::Plane p;
        const bool has_area = f.vertices.size() >= 3 && algo::plane_of(f.vertices, p);
        polygons.push_back(has_area ? f.vertices : std::vector<algo::Vec3>{});  // no area: no ray meets it
        planes.push_back(p);
    }
    std::vector<std::size_t> seen(faces.size(), 0);
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x)
            if (const auto h = algo::nearest_hit(algo::pixel_ray(camera, size, x, y), polygons, planes)) ++seen[h->index];
    return seen;
}

}  // namespace hsr::analysis
