// SPDX-License-Identifier: MIT
// libFuzzer: OBJ face lines made from the fuzzer's bytes (issue 53, item 4: tinyobjloader keeps a face's size in an
// unsigned char). The bytes choose a ring of vertices, then faces of 3 to 2000 of them, each index written as "i",
// "i/t", "i//n", "i/t/n" or counted back from the last ("-k"), apart by spaces or tabs, lines ended by \n, \r\n or
// \r. A face line that loads is a polygon of exactly its line's vertices, in its order; nothing else may come of it.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/load_scene.h"
#include "scene/obj_faces.h"

namespace {

struct Bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    unsigned next() { return at < size ? data[at++] : 0; }
    bool empty() const { return at >= size; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("hsrviz_fuzz_obj_faces_" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    Bytes b{data, size};
    // a convex ring of n vertices in z = 0: any subset, in ring order, is a convex face with area
    const std::size_t n = 3 + (b.next() << 8 | b.next()) % 2000;
    std::string obj;
    for (std::size_t k = 0; k < n; ++k) {
        char line[80];
        const double a = 2 * M_PI * double(k) / double(n);
        std::snprintf(line, sizeof line, "v %.17g %.17g 0\n", std::cos(a), std::sin(a));
        obj += line;
    }
    obj += "vt 0 0\nvn 0 0 1\n";
    std::vector<std::vector<std::size_t>> faces;  // each face's vertices (0-based) in the file's order
    while (!b.empty() && faces.size() < 8) {
        // a face: a count (3 … n) of vertices spread round the ring in its order (a face of area, never a sliver)
        const std::size_t count = 3 + (b.next() << 8 | b.next()) % (n - 2), stride = n / count;
        const std::size_t start = b.next() % (n - (count - 1) * stride);
        std::vector<std::size_t> face;
        for (std::size_t k = 0; k < count; ++k) face.push_back(start + k * stride);
        std::string line = b.next() % 2 ? "f" : " \tf";
        for (const std::size_t v : face) {
            const unsigned form = b.next();
            line += form & 1 ? "\t" : " ";
            line += form & 2 ? "-" + std::to_string(n - v) : std::to_string(v + 1);  // -k: the k-th from the last
            line += std::array<const char*, 4>{"", "/1", "//1", "/1/1"}[(form >> 2) & 3];
        }
        obj += line + std::array<const char*, 3>{"\n", "\r\n", "\r"}[b.next() % 3];
        faces.push_back(std::move(face));
    }
    if (faces.empty()) return 0;
    std::ofstream(dir / "m.obj", std::ios::binary | std::ios::trunc) << obj;
    if (hsr::algo::obj_faces(obj).size() != faces.size()) std::abort();
    hsr::algo::Scene s;
    try {
        s = hsr::algo::load_scene_text((dir / "s.toml").string(), "[camera]\neye = [0, 1, 5]\n[[meshes]]\nfile = \"m.obj\"\nid = 1\n");
    } catch (const hsr::algo::LoadError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        std::abort();  // every face here is good: refusing one is a fault
    }
    if (s.polygons.size() != faces.size()) std::abort();
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (s.polygons[f].vertices.size() != faces[f].size()) std::abort();
        for (std::size_t k = 0; k < faces[f].size(); ++k) {
            const double a = 2 * M_PI * double(faces[f][k]) / double(n);
            if (std::abs(s.polygons[f].vertices[k].x - std::cos(a)) > 1e-12 || std::abs(s.polygons[f].vertices[k].y - std::sin(a)) > 1e-12)
                std::abort();
        }
    }
    return 0;
}
