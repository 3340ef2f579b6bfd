// SPDX-License-Identifier: MIT
#include "scene_families.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include <glm/geometric.hpp>

#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "scene/random_scene.h"

namespace hsr::test {
namespace {

using algo::Scene;
using glm::dvec3;

// A scene being made: its random numbers, the next free id, polygons added with random colours.
struct Maker {
    Scene scene;
    std::mt19937 rng;
    algo::SceneId next = 1;

    Maker(std::uint32_t seed, double aspect, std::string name) : rng(seed) {
        scene.name = std::move(name);
        scene.source = scene.name + " (seed " + std::to_string(seed) + ")";
        scene.camera = {.eye = {0, 0, 10}, .target = {0, 0, 0}, .fov_y = 60, .aspect = aspect, .near = 1, .far = 20};
    }
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    int between(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    dvec3 point(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
    dvec3 direction() {
        const dvec3 d = point(1);
        return glm::length(d) < 1e-3 ? dvec3(0, 0, 1) : glm::normalize(d);
    }
    void add(const std::vector<dvec3>& vertices) {
        algo::ScenePolygon p{next++, {std::uint8_t(between(40, 255)), std::uint8_t(between(40, 255)), std::uint8_t(between(40, 255))}, {}};
        for (const dvec3& v : vertices) p.vertices.emplace_back(v, 1.0);
        scene.polygons.push_back(std::move(p));
    }
    void triangle(dvec3 centre, double size) { add({centre + point(size), centre + point(size), centre + point(size)}); }
    Scene done() { return std::move(scene); }
};

// Two unit vectors spanning the plane with normal n.
std::pair<dvec3, dvec3> plane_axes(dvec3 n) {
    const dvec3 a = std::abs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    const dvec3 u = glm::normalize(glm::cross(n, a));
    return {u, glm::cross(n, u)};
}

// Convex polygons with one or two corners cut very close to the corner: edges of a hundredth of a pixel to a
// pixel, which snapping to the sub-pixel grid can turn the wrong way (the z-buffer's lost wedge).
Scene subpixel_edges(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "sub-pixel edges");
    for (int k = 0; k < 30; ++k) {
        const dvec3 c = m.point(3.5), a = c + m.point(2.5), b = c + m.point(2.5), d = c + m.point(2.5);
        const double t = std::pow(10.0, m.uniform(-4.5, -1.5)), s = std::pow(10.0, m.uniform(-4.5, -1.5));
        if (m.between(0, 1) == 0)  // the corner d cut
            m.add({a, b, d + (b - d) * t, d + (a - d) * s});
        else  // the corners d and a cut
            m.add({a + (b - a) * t, b, d + (b - d) * s, d + (a - d) * t, a + (d - a) * s});
    }
    return m.done();
}

// Piercing triangles seen by an orthographic camera from a random direction: every ray runs along the view
// direction, so an order taken from the eye point is wrong (the BSP's orthographic bug).
Scene orthographic(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "orthographic camera");
    m.scene.camera.projection = algo::Projection::orthographic;
    m.scene.camera.eye = m.direction() * 10.0;
    if (std::abs(m.scene.camera.eye.y) > 9.9) m.scene.camera.eye.x += 1;  // not along up
    const double h = m.uniform(3, 6);
    m.scene.camera.box[0] = -h * aspect, m.scene.camera.box[1] = h * aspect, m.scene.camera.box[2] = -h, m.scene.camera.box[3] = h;
    for (int k = 0; k < 40; ++k) m.triangle(m.point(4), 2.5);
    return m.done();
}

// One giant polygon (10^5 … 10^6 across, as a backdrop or far to one side) among ordinary and tiny ones: a
// tolerance that follows the scene's extent makes the ordinary ones coplanar (the BSP's giant bug).
Scene giant_and_tiny(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "giant and tiny polygons");
    const double giant = std::pow(10.0, m.uniform(5, 6));
    if (m.between(0, 1) == 0)
        m.add({{-giant, -giant, -6}, {giant, -giant, -6.5}, {giant, giant, -7}, {-giant, giant, -6.5}});
    else
        m.add({{giant, -giant, 0}, {2 * giant, -giant, 1}, {2 * giant, giant, 2}, {giant, giant, 1}});
    for (int k = 0; k < 25; ++k) m.triangle(m.point(3), 1.5);
    for (int k = 0; k < 15; ++k) m.triangle(m.point(3), std::pow(10.0, m.uniform(-3, -1.5)));
    return m.done();
}

// Large triangles all through the middle, piercing one another many times (depth sort's endless moves).
Scene interpenetrating(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "large interpenetrating triangles");
    for (int k = 0; k < 10; ++k) m.triangle(m.point(1), 5);
    return m.done();
}

// Bars lying round a centre, each over the next at one end and under it at the other: cyclic overlaps that only a
// split resolves.
Scene cyclic_overlaps(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "cyclic overlaps");
    const int bars = m.between(3, 5);
    const double turn = m.uniform(0, 2 * std::numbers::pi);
    for (int k = 0; k < bars; ++k) {
        const double a = turn + 2 * std::numbers::pi * k / bars + m.uniform(-0.1, 0.1);
        const dvec3 along(std::cos(a), std::sin(a), 0), across(-std::sin(a), std::cos(a), 0);
        const dvec3 start = across * 1.0 - along * 3.5, end = across * 1.0 + along * 3.5;
        const double rise = m.uniform(0.3, 1.5), width = m.uniform(0.6, 1.4);
        const dvec3 s = start + dvec3(0, 0, rise), e = end - dvec3(0, 0, rise);
        m.add({s - across * width / 2.0, e - across * width / 2.0, e + across * width / 2.0, s + across * width / 2.0});
    }
    for (int k = 0; k < 5; ++k) m.triangle(m.point(3), 1.5);
    return m.done();
}

// Stacks of overlapping quads 10^-3 … 10^-7 apart along their normal: depth ties at every pixel they share.
Scene coplanar_stacks(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "near-coplanar stacks");
    for (int stack = 0; stack < 3; ++stack) {
        const dvec3 n = glm::normalize(m.direction() + dvec3(0, 0, 1.5)), centre = m.point(2.5);
        const auto [u, v] = plane_axes(n);
        const double gap = std::pow(10.0, -m.between(3, 7));
        const int layers = m.between(2, 5);
        for (int k = 0; k < layers; ++k) {
            const dvec3 c = centre + n * (gap * k) + u * m.uniform(-0.6, 0.6) + v * m.uniform(-0.6, 0.6);
            const double r = m.uniform(1, 2);
            m.add({c - u * r - v * r, c + u * r - v * r, c + u * r + v * r, c - u * r + v * r});
        }
    }
    return m.done();
}

// Fans of slivers round a centre (some a ten-thousandth of a radian wide) and long slivers a ten-thousandth thick.
Scene slivers(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "slivers and fans of slivers");
    for (int fan = 0; fan < 2; ++fan) {
        const dvec3 centre = m.point(2), n = glm::normalize(m.direction() + dvec3(0, 0, 2));
        const auto [u, v] = plane_axes(n);
        double angle = 0;
        while (angle < 2 * std::numbers::pi) {
            const double step = std::min(2 * std::numbers::pi - angle, std::pow(10.0, m.uniform(-4, -0.5)));
            if (step < 1e-9) break;
            const double r = 3;
            m.add({centre, centre + (u * std::cos(angle) + v * std::sin(angle)) * r,
                   centre + (u * std::cos(angle + step) + v * std::sin(angle + step)) * r});
            angle += step;
            if (m.scene.polygons.size() > 150) break;
        }
    }
    for (int k = 0; k < 10; ++k) {
        const dvec3 a = m.point(4), b = m.point(4);
        m.add({a, b, (a + b) / 2.0 + m.direction() * std::pow(10.0, m.uniform(-5, -2))});
    }
    return m.done();
}

// Triangles reaching behind the eye, and vertices exactly in the eye's plane (w = 0 in clip space).
Scene behind_the_eye(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "vertices behind the eye and at w = 0");
    m.scene.camera.near = m.uniform(0.05, 1);
    const double eye_z = m.scene.camera.eye.z;
    for (int k = 0; k < 20; ++k) {
        const dvec3 front = m.point(3);
        const int kind = m.between(0, 2);
        const dvec3 behind(m.uniform(-6, 6), m.uniform(-6, 6), eye_z + (kind == 0 ? 0.0 : m.uniform(0.5, 6)));
        const dvec3 third = kind == 2 ? dvec3(m.uniform(-6, 6), m.uniform(-6, 6), eye_z) : front + m.point(2);
        m.add({front, behind, third});
    }
    return m.done();
}

// Closed boxes and spheres, some intersecting: back faces everywhere, shared edges everywhere.
Scene closed_meshes(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "closed meshes");
    for (int k = 0; k < 4; ++k) {
        const dvec3 lo = m.point(3.5), size(m.uniform(0.5, 3), m.uniform(0.5, 3), m.uniform(0.5, 3));
        algo::add_box(m.scene, lo, lo + size, {180, 120, 90}, m.next);
    }
    for (int k = 0; k < 2; ++k) algo::add_sphere(m.scene, m.point(3), m.uniform(0.5, 2), 12, 8, {90, 160, 200}, m.next);
    return m.done();
}

// Tilted walls of quads whose rows are split at different places: T-junctions, where a vertex of one quad lies
// on the edge of its neighbour; a backdrop behind shows through any crack.
Scene t_junctions(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "T-junctions");
    m.add({{-8, -8, -6}, {8, -8, -6}, {8, 8, -6}, {-8, 8, -6}});
    const dvec3 n = glm::normalize(m.direction() + dvec3(0, 0, 2)), origin = m.point(1);
    const auto [u, v] = plane_axes(n);
    const int rows = m.between(3, 6);
    const double row_height = 6.0 / rows;
    for (int r = 0; r < rows; ++r) {
        std::vector<double> cuts{-3};
        const int columns = m.between(1, 5);
        for (int c = 1; c < columns; ++c) cuts.push_back(-3 + 6.0 * c / columns + m.uniform(-0.2, 0.2));
        cuts.push_back(3);
        const double y0 = -3 + r * row_height, y1 = y0 + row_height;
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
            m.add({origin + u * cuts[c] + v * y0, origin + u * cuts[c + 1] + v * y0, origin + u * cuts[c + 1] + v * y1,
                   origin + u * cuts[c] + v * y1});
    }
    return m.done();
}

// A mesh as modellers export it, read through the OBJ loader: a UV sphere written as quads whose pole quads repeat a
// point (each ring of the pole is one point written once per slice), a face of welded vertices and one of three
// points on a line (left out, with a note), an octagon kept whole, CRLF line ends.
Scene obj_meshes(std::uint32_t seed, double aspect) {
    Maker m(seed, aspect, "OBJ meshes");
    std::ostringstream obj;
    obj << "# a modeller's export\r\no sphere\r\n";
    const dvec3 c = m.point(1.5);
    const double r = m.uniform(1, 3);
    const int slices = m.between(6, 14), stacks = m.between(4, 9);
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const double theta = std::numbers::pi * i / stacks, phi = 2 * std::numbers::pi * j / slices;
            const dvec3 p = c + r * dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            obj << "v " << p.x << ' ' << p.y << ' ' << p.z << "\r\n";
        }
    const auto index = [&](int i, int j) { return i * slices + (j % slices) + 1; };
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j)
            obj << "f " << index(i, j) << ' ' << index(i, j + 1) << ' ' << index(i + 1, j + 1) << ' ' << index(i + 1, j) << "\r\n";
    obj << "f 1 1 " << index(1, 0) << "\r\n";  // welded
    const int first = (stacks + 1) * slices;
    const dvec3 a = m.point(3), d = m.direction();
    for (int k = 0; k < 3; ++k) obj << "v " << (a + d * double(k)).x << ' ' << (a + d * double(k)).y << ' ' << (a + d * double(k)).z << "\r\n";
    obj << "f " << first + 1 << ' ' << first + 2 << ' ' << first + 3 << "\r\n";  // three points on a line
    obj << "g floor\r\nusemtl grey\r\n";
    const double floor_y = c.y - r - m.uniform(0.1, 1), floor_r = m.uniform(3, 6);
    for (int k = 0; k < 8; ++k)
        obj << "v " << floor_r * std::cos(k * std::numbers::pi / 4) << ' ' << floor_y << ' ' << floor_r * std::sin(k * std::numbers::pi / 4) - 2 << "\r\n";
    obj << "f";
    for (int k = 8; k >= 1; --k) obj << ' ' << -k;
    obj << "\r\n";
    const auto dir = std::filesystem::temp_directory_path() / ("hsrviz_obj_family_" + std::to_string(seed));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "m.obj", std::ios::binary) << obj.str();
    Scene s = algo::load_scene_text((dir / "s.toml").string(),
                                    "[camera]\neye = [0, 0, 10]\ntarget = [0, 0, 0]\nfov = 60\nnear = 1\nfar = 20\n[[meshes]]\nfile = \"m.obj\"\n");
    std::filesystem::remove_all(dir);
    s.name = m.scene.name, s.source = m.scene.source;
    s.camera.aspect = aspect;
    return s;
}

// The ordinary case: random triangles, some piercing.
Scene random_triangles(std::uint32_t seed, double aspect) {
    Scene s = algo::random_triangles({.count = 50, .seed = seed, .size = 2.5});
    s.camera.aspect = aspect;
    return s;
}

}  // namespace

const std::vector<SceneFamily>& scene_families() {
    static const std::vector<SceneFamily> families{
        {"subpixel-edges", "the fill's snapped short edges", subpixel_edges},
        {"orthographic", "orders taken from an eye point", orthographic},
        {"giant-tiny", "tolerances that follow the scene's extent", giant_and_tiny},
        {"interpenetrating", "depth sort's moves and splits", interpenetrating},
        {"cyclic", "cyclic overlaps", cyclic_overlaps},
        {"coplanar-stacks", "depth ties 1e-3 … 1e-7 apart", coplanar_stacks},
        {"slivers", "slivers and fans of slivers", slivers},
        {"behind-eye", "clipping at the near plane and w = 0", behind_the_eye},
        {"closed-meshes", "shared edges, back faces", closed_meshes},
        {"t-junctions", "cracks at T-junctions", t_junctions},
        {"obj-meshes", "a modeller's OBJ: points repeated at the poles, faces of no area", obj_meshes},
        {"random", "the ordinary case", random_triangles},
    };
    return families;
}

}  // namespace hsr::test
