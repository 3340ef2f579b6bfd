// SPDX-License-Identifier: MIT
// OBJ faces of any size: tinyobjloader keeps a face's size in an unsigned char (400 vertices read as 144, and the
// faces after it took the big face's indices); the loader counts each `f` line itself (issue 53, item 4).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "catch.h"
#include "scene/load_scene.h"
#include "scene/obj_faces.h"

using namespace hsr::algo;

namespace {

// A regular n-gon on the unit circle in z = 0, as one face, then `more` lines.
std::string ngon(std::size_t n, const std::string& more = "") {
    std::string obj;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = 2 * M_PI * double(k) / double(n);
        obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    obj += "f";
    for (std::size_t k = 1; k <= n; ++k) obj += " " + std::to_string(k);
    return obj + "\n" + more;
}

}  // namespace

TEST_CASE("the face lines of an OBJ file are counted as tinyobjloader splits its lines", "[scene][mesh]") {
    const auto faces = obj_faces("v 0 0 0\r\n  f 1 2 3\rf\t1/1 2/2/2   3//3 4 \nf 1 2\n# f 1 2 3\nfo 1 2 3\nf 1 2 3");
    REQUIRE(faces.size() == 3);
    CHECK((faces[0].line == 2 && faces[0].vertices == 3));
    CHECK((faces[1].line == 3 && faces[1].vertices == 4));  // a lone \r ends a line, and a tab follows the f
    CHECK((faces[2].line == 7 && faces[2].vertices == 3));  // the two-vertex face, the comment and 'fo' are no faces
    CHECK(obj_faces("").empty());
}

TEST_CASE("OBJ faces of 3 to 100000 vertices are read whole, and the faces after them keep their own vertices",
          "[scene][mesh]") {
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_obj_faces_test";
    std::filesystem::create_directories(dir);
    const std::string scene = (dir / "s.toml").string();
    const std::string text = "[camera]\neye = [0, 0, 5]\n[[meshes]]\nfile = \"m.obj\"\nid = 10\n";
    for (const std::size_t n : {3, 255, 256, 257, 300, 400, 512, 100000}) {
        INFO(n << " vertices");
        std::ofstream(dir / "m.obj") << ngon(n, "v 0 0 1\nv 1 0 1\nv 0 1 1\nf " + std::to_string(n + 1) + " " + std::to_string(n + 2) + " " +
                                                    std::to_string(n + 3) + "\n");
        const Scene s = load_scene_text(scene, text);
        REQUIRE(s.polygons.size() == 2);
        CHECK(s.polygons[0].vertices.size() == n);
        CHECK(s.polygons[0].id == 10);
        REQUIRE(s.polygons[1].vertices.size() == 3);  // the triangle after it: its own three corners at z = 1
        for (const auto& v : s.polygons[1].vertices) CHECK(v.z == 1);
    }
    // a bad index in a big face is named with its line
    std::ofstream(dir / "m.obj") << ngon(300, "f 1 2 999\n");
    try {
        load_scene_text(scene, text);
        FAIL("a face naming vertex 999 of 300 loaded");
    } catch (const LoadError& e) {
        CHECK_THAT(e.what(), Catch::Contains("m.obj: line 302: face 2 names vertex 999, but the file has 300 vertices"));
    }
    std::filesystem::remove_all(dir);
}
