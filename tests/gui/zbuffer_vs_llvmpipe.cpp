// SPDX-License-Identifier: MIT
// Z-buffer fill against Mesa's llvmpipe through OpenGL (EGL offscreen via SDL), on the same 10^5 random triangles
// at 1024×1024, small (about 20 pixels each) and large (about 300): our machine drained with polygon-level events,
// llvmpipe with one thread (LP_NUM_THREADS=0: the rasteriser runs in the calling thread) and with its default
// threads, side by side in one run. Each time is the median of 5 (projection and fill for ours; clear, draw and
// glFinish for OpenGL, the triangles already uploaded). The visible triangle of every pixel is compared, which
// also checks our fill rule against OpenGL's. A benchmark: it prints figures, it is not a test.
//   SDL_VIDEODRIVER=offscreen build/tests/gui/zbuffer_vs_llvmpipe
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unistd.h>
#include <random>
#include <string>

#include "gl_peer.h"

using hsr::test::Triangle;

namespace {

constexpr int size = 1024, count = 100'000, repeats = 5;

// Random triangles of about `area` pixels, near-equilateral, at random depths with a slight slope.
std::vector<Triangle> random_triangles(double area, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> centre(-1, 1), depth(-0.9, 0.9), angle(0, 2 * M_PI), jitter(-0.3, 0.3), slope(-0.01, 0.01);
    const double radius = std::sqrt(area / 1.299) * 2.0 / size;  // equilateral: area = 1.299 R², in NDC units
    std::vector<Triangle> tris(count);
    for (Triangle& t : tris) {
        const double cx = centre(rng), cy = centre(rng), cz = depth(rng), a0 = angle(rng);
        for (int k = 0; k < 3; ++k) {
            const double a = a0 + 2 * M_PI * k / 3 + jitter(rng);
            // as floats, which is what OpenGL is given: both rasterisers start from the same vertices
            t.v[k] = {float(cx + radius * std::cos(a)), float(cy + radius * std::sin(a)), float(cz + slope(rng)), 1};
        }
    }
    return tris;
}

// The distance in pixels from the centre of pixel k to the nearest edge of triangle `id` (1-based; 1e300 for 0).
double distance_to_edges(const std::vector<Triangle>& tris, int id, std::size_t k) {
    if (id == 0) return 1e300;
    const double px = double(k % size) + 0.5, py = double(k / size) + 0.5;
    double best = 1e300;
    const Triangle& t = tris[std::size_t(id - 1)];
    for (int i = 0; i < 3; ++i) {
        const auto& a = t.v[i];
        const auto& b = t.v[(i + 1) % 3];
        const double ax = (a.x + 1) * size / 2, ay = (1 - a.y) * size / 2, bx = (b.x + 1) * size / 2, by = (1 - b.y) * size / 2;
        const double dx = bx - ax, dy = by - ay;
        const double h = std::clamp(((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
        best = std::min(best, std::hypot(px - ax - h * dx, py - ay - h * dy));
    }
    return best;
}

// The window depth of triangle `id` (1-based; the far plane for 0) at the centre of pixel k, from its vertices.
double depth_at(const std::vector<Triangle>& tris, int id, std::size_t k) {
    if (id == 0) return 1.0;
    const Triangle& t = tris[std::size_t(id - 1)];
    const double px = double(k % size) + 0.5, py = double(k / size) + 0.5;
    double x[3], y[3], d[3];
    for (int i = 0; i < 3; ++i) x[i] = (t.v[i].x + 1) * size / 2, y[i] = (1 - t.v[i].y) * size / 2, d[i] = (t.v[i].z + 1) / 2;
    const double area = (y[1] - y[2]) * (x[0] - x[2]) + (x[2] - x[1]) * (y[0] - y[2]);
    const double a = ((y[1] - y[2]) * (px - x[2]) + (x[2] - x[1]) * (py - y[2])) / area;
    const double b = ((y[2] - y[0]) * (px - x[2]) + (x[0] - x[2]) * (py - y[2])) / area;
    return a * d[0] + b * d[1] + (1 - a - b) * d[2];
}

// The child: one OpenGL configuration; writes the ids to `out` and prints "ms renderer".
int child(const std::string& kind, const std::string& out) {
    const hsr::test::GlContext gl(64, 64);
    if (!gl.context) return std::fprintf(stderr, "zbuffer_vs_llvmpipe: %s\n", SDL_GetError()), 1;
    double ms = 0;
    const auto ids = hsr::test::gl_ids(random_triangles(kind == "small" ? 20 : 300, 7), size, size, &ms, repeats);
    std::ofstream(out, std::ios::binary).write(reinterpret_cast<const char*>(ids.data()), std::streamsize(ids.size() * sizeof(int)));
    std::printf("%.3f %s\n", ms, gl.renderer());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 4 && std::string(argv[1]) == "--child") return child(argv[2], argv[3]);
    std::printf("| triangles | ours (ms) | llvmpipe 1 thread (ms) | llvmpipe default threads (ms) | ours / default | pixels differing (within 1/128 px of an edge, within a depth code of a tie) | covered |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string kind : {"small", "large"}) {
        double ours_ms = 0;
        const auto ours = hsr::test::our_ids(random_triangles(kind == "small" ? 20 : 300, 7), size, size, &ours_ms, repeats);
        double gl_ms[2] = {0, 0};
        std::string renderer;
        std::vector<int> gl_ids(ours.size());
        for (int threads = 0; threads < 2; ++threads) {
            const std::string out = "/tmp/hsr_llvmpipe_" + kind + ".ids";
            const std::string command = std::string(threads == 0 ? "LP_NUM_THREADS=0 " : "env -u LP_NUM_THREADS ") + "'" + argv[0] +
                                        "' --child " + kind + " " + out;
            FILE* p = popen(command.c_str(), "r");
            char line[512] = {};
            if (!p || !std::fgets(line, sizeof line, p) || pclose(p) != 0)
                return std::fprintf(stderr, "zbuffer_vs_llvmpipe: the OpenGL run failed (%s)\n", command.c_str()), 1;
            gl_ms[threads] = std::atof(line);
            renderer = line;
            std::ifstream(out, std::ios::binary).read(reinterpret_cast<char*>(gl_ids.data()), std::streamsize(gl_ids.size() * sizeof(int)));
        }
        // Where the two differ: how close the pixel centre is to an edge of either triangle (within 1/128 pixel the
        // two snap the float window coordinates to sub-pixels differently), or how close the two triangles' depths
        // are there (within one 24-bit code, our double plane and llvmpipe's float interpolation may round to
        // different codes, or to a tie, which GL_LESS gives to the first drawn). Either answer is a fair one.
        const auto tris = random_triangles(kind == "small" ? 20 : 300, 7);
        std::size_t differ = 0, on_edges = 0, on_ties = 0, covered = 0;
        for (std::size_t k = 0; k < ours.size(); ++k) {
            covered += ours[k] != 0;
            if (ours[k] == gl_ids[k]) continue;
            ++differ;
            if (std::min(distance_to_edges(tris, ours[k], k), distance_to_edges(tris, gl_ids[k], k)) < 1.0 / 128) ++on_edges;
            else if (std::abs(depth_at(tris, ours[k], k) - depth_at(tris, gl_ids[k], k)) * 16777215 < 1) ++on_ties;
        }
        std::printf("| 10^5 %s (%s px) | %.1f | %.1f | %.1f | %.2f | %zu of %d (%zu, %zu) | %zu |\n", kind.c_str(), kind == "small" ? "20" : "300",
                    ours_ms, gl_ms[0], gl_ms[1], ours_ms / gl_ms[1], differ, size * size, on_edges, on_ties, covered);
        if (kind == "large") std::printf("\nOpenGL: %s", renderer.substr(renderer.find(' ') + 1).c_str());
    }
    std::printf("(machine: %ld cores online)\n", sysconf(_SC_NPROCESSORS_ONLN));
    return 0;
}
