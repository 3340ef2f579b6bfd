// SPDX-License-Identifier: MIT
// A scene: geometry with ids and colours, a camera, and the answers expected of it ([expect]).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace hsr::algo {

using SceneId = std::int32_t;

struct Color {
    std::uint8_t r = 200, g = 200, b = 200;
    bool operator==(const Color&) const = default;
};

enum class Projection : std::uint8_t { perspective, orthographic };

struct Camera {
    Projection projection = Projection::perspective;
    glm::dvec3 eye{0, 0, 5};     // world space
    glm::dvec3 target{0, 0, 0};  // world space
    glm::dvec3 up{0, 1, 0};      // world space, need not be unit
    double fov_y = 60;           // degrees, perspective only
    double aspect = 1;           // width / height of the image plane
    double near = 1, far = 10;   // distances from the eye along the view direction, world units
    double box[4] = {-1, 1, -1, 1};  // left, right, bottom, top: orthographic only, eye-space units
};

// Where a scene's vertices live: world space (3 numbers each) or clip space before the divide (4 numbers each).
enum class Coordinates : std::uint8_t { world, clip };

struct ScenePoint {
    SceneId id;
    Color color;
    glm::dvec4 p;  // in the scene's Coordinates (w = 1 for world)
};
struct SceneSegment {
    SceneId id;
    Color color;
    glm::dvec4 a, b;
};
struct ScenePolygon {
    SceneId id;
    Color color;
    std::vector<glm::dvec4> vertices;
    double opacity = 1;  // 0 … 1: drawn with "over" by the painter's algorithms; the z-buffer draws it opaque
    int line = 0;        // where the scene file writes it (its [[polygons]] or [[meshes]] table); 0: generated
};

// A cells-and-portals scene in the lecture's simplest form: a floor plan of convex cells joined by portals
// (openings in a shared wall), extruded to rooms. Plan coordinates (x, y) are the world's (x, −z); heights are
// the world's y, the floor at 0.
struct SceneCell {
    std::string name;
    std::vector<glm::dvec2> outline;  // convex, counter-clockwise in the plan
    int line;
};
struct ScenePortal {
    std::string between[2];   // the names of the two cells it joins
    glm::dvec2 from, to;      // the opening, on the wall the two cells share (plan)
    double bottom = 0, top = 0;  // heights of the opening (top 0: up to the ceiling)
    // Or any convex shape: points (s, h), s from 0 at `from` to 1 at `to` along the wall, h the height (empty: the
    // rectangle from bottom to top)
    std::vector<glm::dvec2> shape;
    int line;
};
struct FloorPlan {
    double height = 3;                  // of every room, world units
    std::vector<SceneCell> cells;
    std::vector<ScenePortal> portals;
    std::optional<glm::dvec2> eye;      // the viewer in the plan, at eye_height; the camera looks at `look`
    glm::dvec2 look{0};
    double eye_height = 1.6;
};

// A terrain for the floating horizon: a height field sampled on a grid, seen in parallel projection along +z,
// tilted down by `elevation`. Row 0 is the curve nearest the eye; a curve is the heights of one row across x.
// Between samples the surface is bilinear, so its section at any x is linear in z between two rows.
struct Terrain {
    int columns = 0, rows = 0;     // samples across (x) and in depth (z); no rows: not a terrain scene
    double dx = 1, dz = 1;         // sample spacing, world units
    double elevation = 30;         // degrees, 0 (level) … 90 (straight down)
    std::vector<double> heights;   // world y, rows × columns, row-major: heights[row * columns + column]
    int line = 0;                  // where the scene file writes it

    double height(int column, int row) const { return heights[std::size_t(row) * std::size_t(columns) + std::size_t(column)]; }
    double width() const { return double(columns - 1) * dx; }  // from x = 0 to the last column
};

// [expect.pvs]: each cell's potentially visible set, by name.
struct ExpectPvs {
    std::string cell;
    std::vector<std::string> visible;
    int line;
};

// [[expect.clip]]: what clipping must make of one primitive.
struct ExpectClip {
    SceneId id;
    std::string outcome;                              // "inside", "clipped" or "rejected"
    std::optional<std::vector<glm::dvec4>> vertices;  // the visible part in clip space, in order
    int line;                                         // where it is written, for test messages
    std::optional<double> max_error;  // the largest relative error against the exact (GMP) answer we promise
};
// [[expect.bsp]]: what a BSP built with one splitter rule must give.
struct ExpectBsp {
    std::string splitter;                    // "first", "balanced", "fewest-splits" or "weighted"
    std::optional<glm::dvec3> eye;           // with `order`: the eye the traversal is run from
    std::optional<std::vector<SceneId>> order;  // the scene ids painted, back to front (a split polygon once per part)
    std::optional<int> splits;
    int line;
};
// [[expect.cull]]: the faces back-face culling keeps, seen from the scene's camera (every test form, or one).
struct ExpectCull {
    std::optional<std::string> test;  // "view_vector", "plane_equation" or "screen_winding"; all three if absent
    std::vector<SceneId> kept;
    int line;
};
// [[expect.image]]: a hidden-surface algorithm's image of the scene against the double-precision ray cast.
struct ExpectImage {
    std::string algorithm;        // "zbuffer", "scanline", "bsp" or "depth-sort"
    std::string format = "int24";   // zbuffer and scanline: the depth format
    std::string splitter = "first"; // bsp
    int width = 64, height = 48;
    std::optional<double> max_differing, min_differing;  // share of pixels whose visible id differs from the ray cast
    std::vector<SceneId> visible;  // ids that must be seen at some pixel
    int line;
};
// [[expect.rejects]]: a machine refuses the scene with a clear error (its message contains `message`).
struct ExpectRejects {
    std::string algorithm;  // "zbuffer", "scanline", "bsp", "depth-sort" or "raycast"
    std::string message;
    int line;
};
// [[expect.horizon]]: the floating horizon on the scene's terrain at `columns` screen columns agrees with the exact ray
// walk at every point (but within a relative 1e-12 of a tie), and sees `visible` points where that is given.
struct ExpectHorizon {
    int columns = 20;
    std::optional<std::uint64_t> visible;
    int line;
};
struct Expect {
    std::vector<ExpectClip> clip;
    std::vector<ExpectImage> image;
    std::vector<ExpectRejects> rejects;
    std::vector<ExpectBsp> bsp;
    std::vector<ExpectCull> cull;
    std::vector<ExpectPvs> pvs;
    std::vector<ExpectHorizon> horizon;
};

struct Scene {
    std::string name;
    std::string description;
    std::string promise;  // extreme cases: the behaviour we promise, in words ([expect] tables check it)
    std::string source;  // the file it came from
    Coordinates coordinates = Coordinates::world;
    Camera camera;
    std::vector<ScenePoint> points;
    std::vector<SceneSegment> segments;
    std::vector<ScenePolygon> polygons;
    FloorPlan floor_plan;  // no cells: not a cells-and-portals scene
    Terrain terrain;       // no rows: not a terrain scene
    Expect expect;
    // What the reader left out, in sentences for the command line, `check` and the window ("city.obj: 3 faces of no
    // area left out (face 2243 first)").
    std::vector<std::string> notes;
};

// World → clip space: projection × view of the camera (OpenGL conventions, right-handed, looking down −z).
glm::dmat4 view_projection(const Camera& c);
// A scene vertex in clip space.
glm::dvec4 to_clip(const Scene& s, const glm::dvec4& v);
// A clip-space point back in world space (defined for w ≠ 0 in world terms: every point of a segment between two
// world points is, whatever its clip-space w).
glm::dvec3 clip_to_world(const Camera& c, const glm::dvec4& clip);

}  // namespace hsr::algo
