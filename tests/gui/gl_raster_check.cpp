// SPDX-License-Identifier: MIT
// Our z-buffer against OpenGL's rasteriser (Mesa llvmpipe here): the same triangles, the same viewport, each
// drawn in a colour that encodes its index, with GL_LESS on a 24-bit depth buffer. Prints how many pixels differ
// and fails if any does:
//   gl_raster_check mesh      a mesh of triangles with vertices on pixel centres, pixel corners and between
//                             them, covering the viewport: coverage and the fill rule on shared edges
//   gl_raster_check overlap   random overlapping, piercing triangles: coverage and the depth test
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "gl_peer.h"

using hsr::test::Triangle;

namespace {

constexpr int width = 64, height = 48;

std::vector<Triangle> mesh(std::mt19937& rng) {
    // Grid points snapped to quarter pixels (some on centres, some on corners), in NDC, covering [-1, 1]²
    std::uniform_int_distribution<int> quarter(-2, 2);
    const int nx = 9, ny = 7;
    std::vector<glm::dvec2> p;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            double px = double(i) * width / nx, py = double(j) * height / ny;
            px = std::round(px * 4) / 4 + (i > 0 && i < nx ? quarter(rng) * 0.25 : 0);
            py = std::round(py * 4) / 4 + (j > 0 && j < ny ? quarter(rng) * 0.25 : 0);
            p.emplace_back(px / width * 2 - 1, 1 - py / height * 2);
        }
    const auto at = [&](int i, int j) { return glm::dvec4(p[std::size_t(j * (nx + 1) + i)], 0.0, 1.0); };
    std::vector<Triangle> t;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            t.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
            t.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
        }
    return t;
}

std::vector<Triangle> overlap(std::mt19937& rng) {
    std::uniform_real_distribution<double> xy(-1.3, 1.3), z(-0.9, 0.9), w(0.5, 2);
    std::vector<Triangle> t;
    for (int k = 0; k < 60; ++k) {
        Triangle tri;
        for (auto& v : tri.v) {
            const double ww = w(rng);
            v = {xy(rng) * ww, xy(rng) * ww, z(rng) * ww, ww};
        }
        t.push_back(tri);
    }
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string what = argc > 1 ? argv[1] : "mesh";
    const hsr::test::GlContext gl_context(width, height);
    if (!gl_context.context) return std::fprintf(stderr, "gl_raster_check: %s\n", SDL_GetError()), 1;
    int differ = 0, covered = 0, runs = 0;
    for (std::uint32_t seed = 1; seed <= 20; ++seed, ++runs) {
        std::mt19937 rng(seed);
        const auto tris = what == "mesh" ? mesh(rng) : overlap(rng);
        const auto gl = hsr::test::gl_ids(tris, width, height), ours = hsr::test::our_ids(tris, width, height);
        for (std::size_t k = 0; k < gl.size(); ++k) {
            covered += ours[k] != 0;
            if (gl[k] != ours[k]) {
                if (differ < 10)
                    std::fprintf(stderr, "seed %u pixel (%zu, %zu): GL %d, ours %d\n", seed, k % width, k / width, gl[k], ours[k]);
                ++differ;
            }
        }
    }
    std::printf("gl_raster_check %s: %d of %d pixels differ from OpenGL (%s), %d covered\n", what.c_str(), differ,
                runs * width * height, gl_context.renderer(), covered);
    return differ == 0 ? 0 : 1;
}
