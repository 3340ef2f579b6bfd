// SPDX-License-Identifier: MIT
#include "scene/load_mesh.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <tiny_obj_loader.h>

#include "core/plane.h"
#include "scene/input_file.h"
#include "scene/load_scene.h"
#include "scene/obj_faces.h"

namespace hsr::algo {
namespace {

bool meshes_anywhere() {
    const char* v = std::getenv("HSRVIZ_MESHES_ANYWHERE");
    return v && std::string(v) == "1";
}

// "" when the path may be read, else why not.
std::string refused_mesh_path(const std::string& file) {
    const std::filesystem::path p = std::filesystem::path(file).lexically_normal();
    std::string ext = p.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".obj") return "a mesh is an OBJ file (its name ends in .obj)";
    if (meshes_anywhere()) return "";
    if (p.is_absolute() || (!p.empty() && *p.begin() == ".."))
        return "a mesh must lie in the scene's folder or below it (set HSRVIZ_MESHES_ANYWHERE=1 to allow any path)";
    return "";
}

// tinyobjloader reads "nan", "inf" or "1e999" as a number it chose (0, or inf): every vertex line is read here first,
// so a coordinate that is not a finite number is refused with its line.
std::string bad_vertex_line(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
        std::istringstream words(line.substr(2));
        std::string word;
        for (int k = 0; k < 3 && words >> word; ++k) {
            char* end = nullptr;
            const double x = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0' || !std::isfinite(x))
                return "line " + std::to_string(number) + ": vertex coordinate '" + printable(word, 40) +
                       "' is not a finite number";
        }
    }
    return "";
}

// "" when tinyobjloader's faces are the file's face lines, each of the size counted there (tinyobjloader keeps a face's
// size modulo 256 in Debian 12's version, whole in Debian 13's, and all its indices); else why not.
std::string faces_disagree(const tinyobj::ObjReader& obj, const std::vector<ObjFace>& faces) {
    std::size_t face = 0;
    for (const tinyobj::shape_t& shape : obj.GetShapes()) {
        std::size_t indices = 0;
        for (const auto size : shape.mesh.num_face_vertices) {  // unsigned char in tinyobjloader 1.0, unsigned int later
            if (face == faces.size() || faces[face].vertices % 256 != std::size_t(size) % 256)
                return "face " + std::to_string(face + 1) + (face < faces.size() ? " (line " + std::to_string(faces[face].line) + ")" : "") +
                       " is not read as its line has it (a face is 'f' and its vertices, separated by spaces)";
            indices += faces[face++].vertices;
        }
        if (indices != shape.mesh.indices.size()) return "its faces do not hold the vertices their lines name";
    }
    if (face != faces.size()) return "line " + std::to_string(faces[face].line) + ": a face line that was not read as a face";
    return "";
}

}  // namespace

void read_meshes(const TomlReader& r, Scene& scene) {
    const toml::array* meshes = r.array(r.root(), "meshes", "", false);
    if (!meshes) return;
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        const std::string f = index("meshes", m);
        const toml::table* t = meshes->get(m)->as_table();
        if (!t) r.fail(meshes->get(m), f, "expected a table");
        r.only_keys(*t, f, {"file", "id", "color", "translate", "scale", "turn"});
        const std::string file = r.text(*t, "file", f);
        if (const std::string why = refused_mesh_path(file); !why.empty()) r.fail(t->get("file"), join(f, "file"), why);
        const auto path = (std::filesystem::path(r.path()).parent_path() / file).lexically_normal();
        std::string text;
        try {
            text = read_input_file(path.string());
        } catch (const LoadError& e) {
            r.fail(t->get("file"), join(f, "file"), path.string() + ": " + e.message);
        }
        if (const std::string why = bad_vertex_line(text); !why.empty())
            r.fail(t->get("file"), join(f, "file"), path.filename().string() + ": " + why);
        tinyobj::ObjReader obj;
        tinyobj::ObjReaderConfig config;
        config.triangulate = false;  // keep quads and n-gons as the file has them
        if (!obj.ParseFromString(text, "", config)) r.fail(t->get("file"), join(f, "file"), "cannot read " + path.string() + ": " + obj.Error());
        std::int64_t id = r.integer(*t, "id", f, 1);
        const double scale = r.number(*t, "scale", f, 1.0), turn = r.number(*t, "turn", f, 0.0) * M_PI / 180;
        if (!(scale > 0)) r.fail(t->get("scale"), join(f, "scale"), "expected a scale > 0");
        const glm::dvec4 move = t->get("translate") ? r.vector(*t->get("translate"), join(f, "translate"), 3, 3) : glm::dvec4(0, 0, 0, 1);
        Color color{200, 200, 200};
        if (t->contains("color")) {
            const std::string hex = r.text(*t, "color", f);
            unsigned rgb = 0;
            if (hex.size() != 7 || hex[0] != '#' || std::sscanf(hex.c_str() + 1, "%6x", &rgb) != 1)
                r.fail(t->get("color"), join(f, "color"), "expected a colour \"#rrggbb\"");
            color = {std::uint8_t(rgb >> 16), std::uint8_t(rgb >> 8), std::uint8_t(rgb)};
        }
        const auto& v = obj.GetAttrib().vertices;
        const std::vector<ObjFace> faces = obj_faces(text);
        if (const std::string why = faces_disagree(obj, faces); !why.empty())
            r.fail(t->get("file"), join(f, "file"), "cannot read " + path.filename().string() + ": " + why);
        const std::size_t before = scene.polygons.size();
        std::size_t face = 0, no_area = 0;
        std::string first_no_area;
        for (const tinyobj::shape_t& shape : obj.GetShapes()) {
            std::size_t at = 0;
            for (std::size_t k = 0; k < shape.mesh.num_face_vertices.size(); ++k, ++face) {
                ScenePolygon p{SceneId(id), color, {}};
                p.line = int(t->source().begin.line);
                if (id < 1 || id > 65535) r.fail(t->get("id"), join(f, "id"), "the mesh's faces need ids from 1 to 65535");
                ++id;
                const std::string face_name = path.filename().string() + ": line " + std::to_string(faces[face].line) + ": face " + std::to_string(face + 1);
                for (std::size_t n = 0; n < faces[face].vertices; ++n) {
                    // tinyobjloader passes indices past the vertex list through: check each before reading
                    const int index = shape.mesh.indices[at++].vertex_index;
                    if (index < 0 || 3 * std::size_t(index) + 2 >= v.size())
                        r.fail(t->get("file"), join(f, "file"),
                               face_name + (index < 0 ? " names a vertex before the first (a negative index counts back from the last)"
                                                      : " names vertex " + std::to_string(std::int64_t(index) + 1)) +
                                   ", but the file has " + std::to_string(v.size() / 3) + " vertices");
                    const auto vi = std::size_t(index);
                    const glm::dvec3 q = glm::dvec3(v[3 * vi], v[3 * vi + 1], v[3 * vi + 2]) * scale;
                    p.vertices.emplace_back(q.x * std::cos(turn) + q.z * std::sin(turn) + move.x, q.y + move.y,
                                            -q.x * std::sin(turn) + q.z * std::cos(turn) + move.z, 1.0);
                    if (!(glm::length(glm::dvec3(p.vertices.back())) <= max_world_coordinate))
                        r.fail(t->get("file"), join(f, "file"), face_name + ": a vertex lies beyond ±1e100 (after scale and translate)");
                }
                if (!has_area(p.vertices)) {  // welded vertices, a sphere's pole: it covers no pixel, left out and said
                    if (no_area++ == 0) first_no_area = "face " + std::to_string(face + 1) + ", line " + std::to_string(faces[face].line);
                    continue;
                }
                if (p.vertices.size() > 3 && bend(p.vertices) > max_bend)
                    r.fail(t->get("file"), join(f, "file"), face_name + ": " + not_planar(bend(p.vertices)));
                scene.polygons.push_back(std::move(p));
            }
        }
        if (scene.polygons.size() == before && no_area > 0)
            r.fail(t->get("file"), join(f, "file"), "every face of " + path.filename().string() + " has no area (its vertices on one line or at one point)");
        if (scene.polygons.size() == before)  // garbage, or only points and lines: tinyobjloader reads them as nothing
            r.fail(t->get("file"), join(f, "file"), path.filename().string() + " has no faces of 3 or more vertices");
        if (no_area > 0) scene.notes.push_back(left_out_of_no_area(path.filename().string(), no_area, "face", first_no_area));
    }
}

}  // namespace hsr::algo
