// SPDX-License-Identifier: MIT
// libFuzzer: any bytes as geometry. The bytes are read as doubles (so NaN, infinities, huge, tiny and denormal
// values all come up) and shaped into up to 8 polygons of 3 to 6 vertices, sometimes a dense circle of up to 5,100
// vertices, and a few segments before a fixed camera, then every machine runs on them (run_machines.h).
#include <cstddef>
#include <cstdint>
#include <cmath>
#include <cstring>

#include "run_machines.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hsr::algo;
    std::size_t at = 0;
    const auto next = [&]() -> double {
        double d = 0;
        if (at + sizeof d <= size) std::memcpy(&d, data + at, sizeof d), at += sizeof d;
        return d;
    };
    const auto byte = [&]() -> int { return at < size ? data[at++] : 0; };
    Scene s;
    s.camera = {.eye = {0, 0, 6}, .target = {0, 0, 0}, .fov_y = 50, .near = 0.5, .far = 30};
    const int polygons = byte() % 9;
    for (int p = 0; p < polygons && at < size; ++p) {
        ScenePolygon poly{SceneId(p + 1), {200, 100, 50}, {}};
        const int n = 3 + byte() % 4;
        for (int k = 0; k < n; ++k) poly.vertices.emplace_back(next(), next(), next(), 1.0);
        s.polygons.push_back(std::move(poly));
    }
    // Dense convex polygons (hundreds to thousands of vertices, closer than the sub-pixel grid): a circle whose
    // centre, radius and tilt come from the bytes
    if (at < size && byte() % 4 == 0) {
        ScenePolygon circle{SceneId(50), {90, 180, 90}, {}};
        const int n = 100 + (byte() * 256 + byte()) % 5000;
        const glm::dvec3 centre(next(), next(), next());
        const double radius = next(), tilt = next();
        for (int k = 0; k < n; ++k) {
            const double a = 2 * M_PI * k / n;
            circle.vertices.emplace_back(centre.x + radius * std::cos(a), centre.y + radius * std::sin(a),
                                         centre.z + tilt * radius * std::cos(a), 1.0);
        }
        s.polygons.push_back(std::move(circle));
    }
    const int segments = byte() % 4;
    for (int k = 0; k < segments && at < size; ++k)
        s.segments.push_back({SceneId(100 + k), {}, {next(), next(), next(), 1.0}, {next(), next(), next(), 1.0}});
    hsr::fuzz::run_machines(s);
    return 0;
}
