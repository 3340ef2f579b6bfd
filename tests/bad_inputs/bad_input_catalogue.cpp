// SPDX-License-Identifier: MIT
// A catalogue of bad inputs, each handed to the real hsrviz binary through every front door that takes it (check,
// trace, render, the window's headless screenshot, the command line itself), with the outcome it must give: a clear
// error naming the file and line (and the field, or the operating system's reason), or a stated result. Nothing may
// crash, hang, write a partial output file, or print NaN. At the end it prints the counts by outcome.
//
//   bad_input_catalogue HSRVIZ WORK_DIR
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "catalogue.h"
#include "scene/renderer_names.h"

namespace bad_inputs {

std::string hsrviz;
fs::path work;

std::string shell_quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::map<std::string, int> outcomes;  // "refused (exit 1)", "usage error (exit 2)", "accepted with a warning", …
int failures = 0;

void run_case(const Case& c, std::size_t number) {
    const fs::path dir = work / ("case" + std::to_string(number));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& [name, text] : c.files) {
        fs::create_directories((dir / name).parent_path());
        std::ofstream(dir / name, std::ios::binary) << text;
    }
    if (c.make) c.make(dir);
    for (const Run& r : c.runs) {
        std::string command = "cd " + shell_quoted(dir.string()) + " && SDL_VIDEODRIVER=offscreen HSRVIZ_CONFIG=" + shell_quoted((dir / "window-settings.toml").string()) +
                              " " + r.env + (r.interrupt_after > 0 ? " timeout --preserve-status -s INT " + std::to_string(r.interrupt_after) + " "
                                                                   : " timeout 60 ") + shell_quoted(hsrviz);
        for (const std::string& a : r.args) command += " " + shell_quoted(a);
        command += r.stdout_to.empty() ? " > out.txt 2>&1" : " > " + shell_quoted(r.stdout_to) + " 2> out.txt";
        const int status = std::system(command.c_str());
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        const std::string out = read(dir / "out.txt");
        std::vector<std::string> wrong;
        const bool stopped = r.interrupt_after > 0 && code == 130;  // asked to stop by Ctrl+C, and it did (the says tell how)
        if (code == 124) wrong.push_back("hung (stopped after 60 s)");
        else if (code >= 128 && !(stopped && r.exit == 130)) wrong.push_back("crashed (exit " + std::to_string(code) + ")");
        else if (code != r.exit) wrong.push_back("exit " + std::to_string(code) + ", expected " + std::to_string(r.exit));
        for (const std::string& s : r.says)
            if (out.find(s) == std::string::npos) wrong.push_back("does not say \"" + s + "\"");
        for (const std::string& s : r.never_says)
            if (out.find(s) != std::string::npos) wrong.push_back("says \"" + s + "\"");
        for (const char* bad : {"Sanitizer", "runtime error:", "terminate called", "Assertion"})
            if (out.find(bad) != std::string::npos) wrong.push_back(std::string("prints \"") + bad + "\"");
        if (code == 0 && (out.find(" nan") != std::string::npos || out.find(" inf") != std::string::npos))
            wrong.push_back("an accepted run printed nan or inf");
        if (!r.no_output.empty() && fs::exists(dir / r.no_output)) wrong.push_back("left an output file " + r.no_output);
        std::string args;
        for (const std::string& a : r.args) args += " " + (a.size() > 60 ? a.substr(0, 60) + "…" : a);
        if (!wrong.empty()) {
            ++failures;
            std::cout << "FAIL  " << c.name << ":" << args << "\n";
            for (const std::string& w : wrong) std::cout << "        " << w << "\n";
            std::cout << "        output: " << out.substr(0, 600) << "\n";
        }
        ++outcomes[code == 0 ? (r.says.empty() ? "accepted" : "accepted, saying what it did") : code == 2 ? "usage error (exit 2)"
                   : stopped ? "stopped by Ctrl+C, nothing left (exit 130)" : "refused (exit 1)"];
    }
    if (const std::string why = c.after ? c.after(dir) : ""; !why.empty()) {
        ++failures;
        std::cout << "FAIL  " << c.name << ": afterwards " << why << "\n";
    }
}

// ── the base files every variation starts from ───────────────────────────────────────────────────────────────────
const std::string scene = R"(name = "a triangle"
description = "one triangle"
[camera]
eye = [0, 0.6, 4]
target = [0, 0, 0]
up = [0, 1, 0]
fov = 60
near = 0.5
far = 20
aspect = 1.333
[[polygons]]
id = 1
color = "#56b4e9"
opacity = 1
vertices = [[-2, -1, -1.5], [1.6, -0.8, 0.8], [-0.4, 1.6, -0.2]]
)";

const std::string mesh_scene = R"(name = "a mesh"
[camera]
eye = [0, 0, 5]
[[meshes]]
file = "m.obj"
id = 10
scale = 1
turn = 0
translate = [0, 0, 0]
)";

const std::string plan_scene = R"(name = "two rooms"
[camera]
fov = 70
near = 0.05
far = 40
[floor_plan]
height = 2.5
eye = [1, 1]
look = [3, 1]
[[floor_plan.cells]]
name = "A"
rect = [0, 0, 2, 2]
[[floor_plan.cells]]
name = "B"
rect = [2, 0, 4, 2]
[[floor_plan.portals]]
between = ["A", "B"]
from = [2, 0.5]
to = [2, 1.5]
)";

const std::string lesson = R"(title = "A lesson"
algorithm = "zbuffer_fill"
scene = "s.toml"
difficulty = 2
format = "int24"
grid = [32, 24]
summary = "A summary."
[[chapters]]
title = "The first polygon"
when = "PolygonFillStarted"
match = { index = 0 }
narration = "Polygon 1 fills."
[chapters.question]
ask = "Does pixel (16, 12) pass?"
event = "PixelTested"
field = "passes"
choices = ["true", "false"]
)";

// The text with the line that starts with `prefix` replaced (or removed, when `line` is empty).
std::string with(const std::string& text, const std::string& prefix, const std::string& line) {
    std::istringstream in(text);
    std::string out, l;
    bool found = false;
    while (std::getline(in, l)) {
        if (!found && l.rfind(prefix, 0) == 0) {
            found = true;
            if (!line.empty()) out += line + "\n";
            continue;
        }
        out += l + "\n";
    }
    if (!found) throw std::logic_error("no line starts with " + prefix);
    return out;
}

// A scene refused by check, trace and render, each naming the file and line and saying `says`.
Case bad_scene(const std::string& name, const std::string& text, std::vector<std::string> says) {
    Case c{name, {{"s.toml", text}}, {}, {}};
    says.push_back("s.toml:");
    c.runs.push_back({{"check", "s.toml"}, 1, says, ""});
    // a problem is reported once, where it is: not again as what removing it left (issue 53, item 10)
    if (std::none_of(says.begin(), says.end(), [](const std::string& s) { return s == "nothing in it"; }))
        c.runs.back().never_says = {"the scene has nothing in it"};
    c.runs.push_back({{"trace", "s.toml", "--out", "t.jsonl"}, 1, says, ""});
    c.runs.push_back({{"render", "s.toml", "--out", "o.png", "--size", "64x48"}, 1, says, "o.png"});
    return c;
}

// A lesson refused by check and trace (and shown as an error by the window, whose screenshot exits 1).
Case bad_lesson(const std::string& name, const std::string& text, std::vector<std::string> says,
                std::map<std::string, std::string> more = {}) {
    Case c{name, {{"l.toml", text}, {"s.toml", scene}}, {}, {}};
    for (auto& [f, t] : more) c.files[f] = t;
    c.runs.push_back({{"check", "l.toml"}, 1, says, ""});
    c.runs.back().never_says = {"field 'scene': missing", "nothing in it"};
    c.runs.push_back({{"trace", "l.toml", "--out", "t.jsonl"}, 1, says, ""});
    c.runs.push_back({{"l.toml", "--screenshot", "w.png", "--frames", "2", "--size", "640x400"}, 1, says, ""});
    return c;
}

Case bad_mesh(const std::string& name, const std::string& obj, std::vector<std::string> says, const std::string& scene_text) {
    Case c = bad_scene(name, scene_text, std::move(says));
    c.files["m.obj"] = obj;
    return c;
}

Case command(const std::string& name, std::vector<std::string> args, int exit, std::vector<std::string> says,
             const std::string& no_output) {
    Case c{name, {{"s.toml", scene}}, {}, {}};
    c.runs.push_back({std::move(args), exit, std::move(says), no_output});
    return c;
}

std::vector<Case> catalogue() {
    std::vector<Case> cs;
    // ── numbers that are not numbers, at every numeric field ────────────────────────────────────────────────────
    const std::vector<std::pair<std::string, std::string>> not_numbers{
        {"nan", "expected"}, {"inf", "expected"}, {"-inf", "expected"}, {"\"ten\"", "expected"},
        {"true", "expected"}, {"[1]", "expected"}, {"{ a = 1 }", "expected"}};
    for (const std::string field : {"fov", "near", "far", "aspect", "opacity"})
        for (const auto& [value, says] : not_numbers)
            cs.push_back(bad_scene(field + " = " + value, with(scene, field + " =", field + " = " + value), {says, field}));
    for (const auto& [value, says] : not_numbers)
        cs.push_back(bad_scene("id = " + value, with(scene, "id =", "id = " + value), {says, "polygons[0].id"}));
    // ── vectors that are not points ─────────────────────────────────────────────────────────────────────────────
    const std::vector<std::pair<std::string, std::string>> not_points{
        {"[nan, 0, 0]", "finite"}, {"[inf, 0, 0]", "finite"}, {"[1, 2]", "expected an array of 3"},
        {"[1, 2, 3, 4, 5]", "expected an array of 3"}, {"\"here\"", "expected an array"}, {"[true, 0, 0]", "expected a number"},
        {"[1e101, 0, 0]", "±1e100"}, {"[1e309, 0, 0]", "s.toml:"}};
    for (const std::string field : {"eye", "target", "up"})
        for (const auto& [value, says] : not_points)
            if (!(field == "up" && value == "[1e101, 0, 0]"))  // up is a direction: any length is one
                cs.push_back(bad_scene(field + " = " + value, with(scene, field + " =", field + " = " + value),
                                       {says, value == "[1e309, 0, 0]" ? "could not be interpreted" : "camera." + field}));
    for (const auto& [value, says] : not_points)
        cs.push_back(bad_scene("vertex " + value, with(scene, "vertices =", "vertices = [" + value + ", [1, 0, 0], [0, 1, 0]]"),
                               {says, value == "[1e309, 0, 0]" ? "could not be interpreted" : "polygons[0].vertices"}));
    // ── numbers out of range ────────────────────────────────────────────────────────────────────────────────────
    const std::vector<std::tuple<std::string, std::string, std::string>> out_of_range{
        {"fov =", "fov = 0", "0 < fov < 180"}, {"fov =", "fov = 180", "0 < fov < 180"}, {"fov =", "fov = -5", "0 < fov < 180"},
        {"fov =", "fov = 1e300", "0 < fov < 180"}, {"near =", "near = 0", "near > 0"}, {"near =", "near = -1", "near > 0"},
        {"far =", "far = 0.1", "far > near"}, {"far =", "far = 1e300", "at most 1e15"}, {"near =", "near = 1e-300", "at most 1e15"},
        {"aspect =", "aspect = 0", "aspect > 0"}, {"aspect =", "aspect = -1", "aspect > 0"}, {"opacity =", "opacity = -0.1", "opacity from 0 to 1"},
        {"opacity =", "opacity = 1.5", "opacity from 0 to 1"}, {"id =", "id = 0", "id from 1 to 65535"}, {"id =", "id = 65536", "id from 1 to 65535"},
        {"id =", "id = -3", "id from 1 to 65535"}, {"id =", "id = 1.5", "expected an integer"}, {"target =", "target = [0, 0.6, 4]", "target equals eye"},
        {"up =", "up = [0, -0.6, -4]", "parallel"}, {"up =", "up = [0, 0, 0]", "parallel"}};
    for (const auto& [prefix, line, says] : out_of_range) cs.push_back(bad_scene(line, with(scene, prefix, line), {says}));
    // ── polygons no algorithm can take ──────────────────────────────────────────────────────────────────────────
    const std::vector<std::tuple<std::string, std::string, std::string>> polygons{
        {"two vertices", "vertices = [[0, 0, 0], [1, 0, 0]]", "at least 3 vertices"},
        {"one point thrice", "vertices = [[1, 1, 1], [1, 1, 1], [1, 1, 1]]", "no area"},
        {"collinear", "vertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2]]", "no area"},
        {"tiny and collinear", "vertices = [[0, 0, 0], [1e-300, 0, 0], [2e-300, 0, 0]]", "no area"},
        {"bent (corners at z = ±2)", "vertices = [[-1, -1, 2], [1, -1, -2], [1, 1, 2], [-1, 1, -2]]", "not planar"},
        {"bent a little", "vertices = [[-1, -1, 0], [1, -1, 0], [1, 1, 0.01], [-1, 1, 0]]", "not planar"},
        {"giant", "vertices = [[-1e154, -1e154, 0], [1e154, -1e154, 0], [0, 1e154, 0]]", "±1e100"},
        {"not an array", "vertices = 3", "expected an array"},
        {"an array of numbers", "vertices = [1, 2, 3]", "expected an array of 3"},
        {"empty", "vertices = []", "at least 3 vertices"}};
    for (const auto& [name, line, says] : polygons) cs.push_back(bad_scene(name, with(scene, "vertices =", line), {says, "polygons[0].vertices"}));
    // A sliver of any area (decided exactly, issue 47) is drawn, by every algorithm: 1e-13 off the line is not on it
    {
        Case c{"collinear but for rounding: a sliver", {{"s.toml", with(scene, "vertices =", "vertices = [[0, 0, 0], [1, 1, 1], [3, 3, 3.0000000000001]]")}}, {}, {}};
        c.runs.push_back({{"check", "s.toml"}, 0, {"ok"}, ""});
        for (const std::string_view a : hsr::algo::renderer_names)  // every renderer the command line names
            c.runs.push_back({{"render", "s.toml", "--algorithm", std::string(a), "--out", "o.png", "--size", "64x48"}, 0, {"wrote o.png"}, ""});
        cs.push_back(std::move(c));
    }
    // A polygon of no area beside one with area: left out, and every front door says so (the scene still plays)
    {
        const std::string two = with(scene, "vertices =", "vertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2]]") +
                                "\n[[polygons]]\nid = 9\nvertices = [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]\n";
        Case c{"a polygon of no area beside one with area", {{"s.toml", two}}, {}, {}};
        const std::string said = "s.toml: 1 polygon of no area left out";
        c.runs.push_back({{"check", "s.toml"}, 0, {"warn", said}, ""});
        c.runs.push_back({{"trace", "s.toml", "--out", "t.jsonl"}, 0, {said}, ""});
        c.runs.push_back({{"render", "s.toml", "--out", "o.png", "--size", "64x48"}, 0, {said, "wrote o.png"}, ""});
        c.runs.push_back({{"s.toml", "--screenshot", "w.png", "--frames", "3"}, 0, {said}, ""});
        cs.push_back(std::move(c));
    }
    // Concave and self-crossing polygons: the clippers take them (check warns), render refuses with file and line
    for (const auto& [name, vertices, says] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"concave", "[[0, 0, 0], [2, 0, 0], [1, 0.3, 0], [2, 2, 0], [0, 2, 0]]", "is not convex"},
             {"pentagram", "[[0, 1, 0], [0.588, -0.809, 0], [-0.951, 0.309, 0], [0.951, 0.309, 0], [-0.588, -0.809, 0]]", "crosses itself"}}) {
        Case c{name, {{"s.toml", with(scene, "vertices =", "vertices = " + vertices)}}, {}, {}};
        c.runs.push_back({{"check", "s.toml"}, 0, {"warn", "s.toml:11:", says}, ""});
        for (const std::string_view a : hsr::algo::renderer_names)
            c.runs.push_back({{"render", "s.toml", "--algorithm", std::string(a), "--out", "o.png", "--size", "64x48"}, 1, {"s.toml:11:", says}, "o.png"});
        cs.push_back(c);
    }
    // ── TOML that is not TOML, and fields that do not exist ─────────────────────────────────────────────────────
    const std::vector<std::tuple<std::string, std::string, std::string>> syntax{
        {"unclosed string", "name = \"open\n[camera]\neye = [0, 0, 5]\n", "s.toml:1:"},
        {"unclosed array", "[camera]\neye = [0, 0, 5\n", "s.toml:2:"},
        {"duplicate key", scene + "name = \"again\"\n", "s.toml:"},
        {"duplicate table", scene + "[camera]\nfov = 40\n", "s.toml:"},
        {"bad escape", "name = \"a\\qb\"\n" + scene.substr(scene.find('\n') + 1), "s.toml:1:"},
        {"key without value", "name =\n", "s.toml:1:"},
        {"invalid UTF-8", "name = \"\xff\xfe\"\n" + scene.substr(scene.find('\n') + 1), "s.toml:1:"},
        {"a NUL byte", std::string("name = \"a\0b\"\n", 12) + scene.substr(scene.find('\n') + 1), "s.toml:1:"},
        {"binary garbage", std::string("\x7f" "ELF\x02\x01\x01\0\0\0\0\0\0\0\0\0", 16), "s.toml:1:"},
        {"unknown top-level field", scene + "colour = \"red\"\n", "unknown field"},
        {"unknown camera field", with(scene, "fov =", "fovy = 60"), "camera.fovy"},
        {"unknown polygon field", scene + "normal = [0, 0, 1]\n", "polygons[0].normal"},
        {"polygons not tables", "polygons = 3\n[camera]\neye = [0, 0, 5]\n", "polygons"},
        {"camera not a table", "camera = 3\n[[polygons]]\nid = 1\nvertices = [[0,0,0],[1,0,0],[0,1,0]]\n", "camera"},
        {"colour with 5 digits", with(scene, "color =", "color = \"#12345\""), "#rrggbb"},
        {"colour by name", with(scene, "color =", "color = \"red\""), "#rrggbb"},
        {"coordinates unknown", "coordinates = \"screen\"\n" + scene, "\"world\" or \"clip\""},
        {"coordinates a number", "coordinates = 3\n" + scene, "coordinates"},
        {"id twice", scene + "[[polygons]]\nid = 1\nvertices = [[0,0,0],[1,0,0],[0,1,0]]\n", "used twice"},
        {"vertices missing", with(scene, "vertices =", ""), "polygons[0].vertices"},
        {"only a camera", "[camera]\neye = [0, 0, 5]\n", "nothing in it"},
        {"only comments", "# a scene\n# to come\n", "nothing in it"},
        {"only blanks", "\n\n   \n", "nothing in it"},
        {"a key of a million characters", std::string(1000000, 'k') + " = 1\n", "keys are at most 100"},
        {"a name of 17,000 characters", "name = \"" + std::string(17000, 'n') + "\"\n" + scene.substr(scene.find('\n') + 1), "texts are at most 4000"},
        {"a description of 30,000 characters", with(scene, "description =", "description = \"" + std::string(30000, 'd') + "\""), "texts are at most 4000"},
        {"an escape sequence in the name", "name = \"\\u001b[2Jcleared\"\n" + scene.substr(scene.find('\n') + 1) + "bogus = 1\n", "unknown field"}};
    for (const auto& [name, text, says] : syntax) cs.push_back(bad_scene(name, text, {says}));
    // ── files that are not files ────────────────────────────────────────────────────────────────────────────────
    const auto file_case = [&](const std::string& name, std::function<void(const fs::path&)> make, const std::string& says) {
        Case c{name, {}, std::move(make), {}};
        c.runs.push_back({{"check", "s.toml"}, 1, {"s.toml:0:0:", says}, ""});
        c.runs.push_back({{"trace", "s.toml", "--out", "t.jsonl"}, 1, {says}, "t.jsonl"});
        c.runs.push_back({{"render", "s.toml", "--out", "o.png"}, 1, {"s.toml:0:0:", says}, "o.png"});
        c.runs.push_back({{"s.toml", "--screenshot", "w.png", "--frames", "2", "--size", "640x400"}, 1, {says}, ""});
        cs.push_back(c);
    };
    file_case("missing", [](const fs::path&) {}, "No such file or directory");
    file_case("a folder", [](const fs::path& d) { fs::create_directory(d / "s.toml"); }, "is a folder");
    file_case("empty", [](const fs::path& d) { std::ofstream(d / "s.toml"); }, "the file is empty");
    file_case("a FIFO", [](const fs::path& d) { mkfifo((d / "s.toml").c_str(), 0600); }, "FIFO");
    file_case("/dev/zero", [](const fs::path& d) { fs::create_symlink("/dev/zero", d / "s.toml"); }, "not a regular file");
    file_case("/dev/null", [](const fs::path& d) { fs::create_symlink("/dev/null", d / "s.toml"); }, "not a regular file");
    file_case("a symbolic-link loop", [](const fs::path& d) { fs::create_symlink("s.toml", d / "s.toml"); }, "symbolic links");
    file_case("a dangling link", [](const fs::path& d) { fs::create_symlink("gone.toml", d / "s.toml"); }, "No such file");
    file_case("65 MB", [](const fs::path& d) { std::ofstream(d / "s.toml"); fs::resize_file(d / "s.toml", std::uintmax_t(65) << 20); }, "up to 64 MB");
    file_case("a socket's name", [](const fs::path& d) { fs::create_symlink("/proc/self/fd/0", d / "s.toml"); }, "s.toml");
    // ── meshes ──────────────────────────────────────────────────────────────────────────────────────────────────
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const std::vector<std::tuple<std::string, std::string, std::string>> meshes{
        {"face past the vertices", tri + "f 1 2 100000000\n", "names vertex 100000000"},
        {"face index 99", tri + "f 1 2 99\n", "names vertex 99"},
        // Debian 12's tinyobjloader lets our check name the face ("m.obj: face 1 names …"); Debian 13's refuses the
        // line itself ("cannot read m.obj: Failed to parse `f' line … Line 4"), with "vertex index" for "face index"
        {"negative indices past the start", tri + "f -5 -6 -7\n", "m.obj"},
        {"index 0", tri + "f 0 1 2\n", "zero value for"},
        {"a NaN vertex", "v 0 nan 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 'nan'"},
        {"an infinite vertex", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 'inf'"},
        {"1e999", "v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n", "line 3: vertex coordinate '1e999'"},
        {"a word as a coordinate", "v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex coordinate 'zero'"},
        {"two-vertex faces", tri + "f 1 2\n", "no faces of 3 or more vertices"},
        {"no faces", tri, "no faces"},
        {"garbage", "this is not an obj file\n\x01\x02\x03\n", "no faces"},
        {"a face with no area", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n", "no area"},
        {"a bent quad", "v -1 -1 2\nv 1 -1 -2\nv 1 1 2\nv -1 1 -2\nf 1 2 3 4\n", "not planar"},
        {"empty", "", "the file is empty"}};
    for (const auto& [name, obj, says] : meshes) cs.push_back(bad_mesh("mesh: " + name, obj, {"meshes[0].file", says}));
    cs.push_back(bad_mesh("mesh: scaled past 1e100", tri + "f 1 2 3\n", {"±1e100"}, with(mesh_scene, "scale =", "scale = 1e200")));
    cs.push_back(bad_mesh("mesh: scale 0", tri + "f 1 2 3\n", {"scale > 0"}, with(mesh_scene, "scale =", "scale = 0")));
    cs.push_back(bad_mesh("mesh: turn nan", tri + "f 1 2 3\n", {"meshes[0].turn"}, with(mesh_scene, "turn =", "turn = nan")));
    cs.push_back(bad_mesh("mesh: ids past 65535", tri + "f 1 2 3\nf 1 3 2\n", {"65535"}, with(mesh_scene, "id =", "id = 65535")));
    for (const auto& [file, says] : std::vector<std::pair<std::string, std::string>>{
             {"../../etc/passwd", "ends in .obj"}, {"/etc/passwd", "ends in .obj"}, {"../outside.obj", "scene's folder"},
             {"/tmp/anywhere.obj", "scene's folder"}, {"missing.obj", "No such file"}, {"folder.obj", "is a folder"}, {"fifo.obj", "FIFO"}}) {
        Case c = bad_scene("mesh file " + file, with(mesh_scene, "file =", "file = \"" + file + "\""), {"meshes[0].file", says});
        c.make = [](const fs::path& d) {
            fs::create_directory(d / "folder.obj");
            mkfifo((d / "fifo.obj").c_str(), 0600);
        };
        cs.push_back(c);
    }
    // ── floor plans ─────────────────────────────────────────────────────────────────────────────────────────────
    const std::vector<std::tuple<std::string, std::string, std::string, std::string>> plans{
        {"a concave cell", "rect = [0, 0, 2, 2]", "outline = [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]", "not convex"},
        {"a star cell", "rect = [0, 0, 2, 2]", "outline = [[1, 2], [1.6, 0.2], [0.05, 1.3], [1.95, 1.3], [0.4, 0.2]]", "floor_plan.cells[0]"},
        {"a cell of 2 corners", "rect = [0, 0, 2, 2]", "outline = [[0, 0], [2, 0]]", "3 corners"},
        {"an inverted rect", "rect = [0, 0, 2, 2]", "rect = [2, 2, 0, 0]", "x0 < x1"},
        {"a rect of nan", "rect = [0, 0, 2, 2]", "rect = [0, 0, nan, 2]", "floor_plan.cells[0].rect"},
        {"overlapping cells", "rect = [2, 0, 4, 2]", "rect = [1, 0, 4, 2]", "overlap"},
        {"a portal to no cell", "between = [\"A\", \"B\"]", "between = [\"A\", \"Z\"]", "Z"},
        {"a portal off the wall", "from = [2, 0.5]", "from = [3, 0.5]", "floor_plan.portals[0]"},
        {"a negative height", "height = 2.5", "height = -1", "floor_plan.height"},
        {"two cells of one name", "name = \"B\"", "name = \"A\"", "floor_plan.cells[1].name"}};
    for (const auto& [name, prefix, line, says] : plans) cs.push_back(bad_scene("plan: " + name, with(plan_scene, prefix, line), {says}));
    // A stated result, not an error: the portal machines say the eye is in no cell and draw nothing
    cs.push_back(Case{"plan: an eye outside every cell", {{"s.toml", with(plan_scene, "eye =", "eye = [10, 10]")}}, {},
                      {{{"check", "s.toml"}, 0, {"ok"}, ""}, {{"render", "s.toml", "--out", "o.png"}, 0, {"wrote o.png"}, ""}}});
    // ── lessons ─────────────────────────────────────────────────────────────────────────────────────────────────
    const std::vector<std::tuple<std::string, std::string, std::string, std::string>> lessons{
        {"unknown algorithm", "algorithm =", "algorithm = \"zbufer\"", "zbufer"},
        {"algorithm a number", "algorithm =", "algorithm = 3", "algorithm"},
        {"missing scene", "scene =", "scene = \"none.toml\"", "No such file"},
        {"scene a folder", "scene =", "scene = \".\"", "is a folder"},
        {"scene /dev/zero", "scene =", "scene = \"/dev/zero\"", "not a regular file"},
        {"a title of 20,000 characters", "title =", "title = \"" + std::string(20000, 't') + "\"", "texts are at most 4000"},
        {"difficulty a word", "difficulty =", "difficulty = \"hard\"", "difficulty"},
        {"unknown format", "format =", "format = \"int12\"", "int12"},
        {"grid of nan", "grid =", "grid = [nan, 24]", "grid"},
        {"grid of 0", "grid =", "grid = [0, 24]", "grid"},
        {"grid of a million", "grid =", "grid = [1000000, 1000000]", "grid"},
        {"a chapter with neither when nor step", "when =", "", "when = \"EventKind\" or step = N"},
        {"a chapter on an event never told", "when =", "when = \"PixelPainted\"", "PixelPainted"},
        {"a question on a field the event lacks", "field =", "field = \"pases\"", "has no field \"pases\""},
        {"a question whose answer is not a choice", "choices =", "choices = [\"yes\", \"no\"]", "not among them"},
        {"ten choices", "choices =", "choices = [\"1\",\"2\",\"3\",\"4\",\"5\",\"6\",\"7\",\"8\",\"9\",\"10\"]", "at most 9 choices"},
        {"a question on an event never told", "event =", "event = \"PixelPainted\"", "PixelPainted"},
        {"narration in a language not listed", "narration =", "narration = { fr = \"Bonjour\" }", "fr"},
        {"narration a number", "narration =", "narration = 3", "narration"},
        {"a question without ask", "ask =", "", "ask"},
        {"an unknown chapter field", "narration =", "narrate = \"x\"", "narrate"},
        {"chapters not tables", "[[chapters]]", "chapters = 3", "chapters"},
        {"a step of -1", "when =", "step = -1", "step"}};
    for (const auto& [name, prefix, line, says] : lessons) {
        std::string text = with(lesson, prefix, line);
        if (name == "chapters not tables") text = text.substr(0, text.find("title = \"The first"));
        if (name == "a step of -1") text = with(text, "match =", "");
        Case c = bad_lesson("lesson: " + name, text, {says});
        // Chapters that cannot work as written: the machine still runs (trace), and the window plays the lesson
        // and says what is wrong, as check does.
        if (says == "PixelPainted" || says == "has no field \"pases\"" || says == "not among them") {
            c.runs[1].exit = 0, c.runs[1].says = {"written to t.jsonl"};
            c.runs[2].exit = 0;
        }
        cs.push_back(c);
    }
    cs.push_back(bad_lesson("lesson: its scene is bad", lesson, {"s.toml:", "0 < fov < 180"}, {{"s.toml", with(scene, "fov =", "fov = 0")}}));
    cs.push_back(bad_lesson("lesson: its scene is empty", lesson, {"l.toml:3:9: field 'scene': s.toml: the file is empty"}, {{"s.toml", ""}}));
    // ── the command line ────────────────────────────────────────────────────────────────────────────────────────
    for (const std::string size : {"4294967297x1", "x", "10x", "0x5", "12x12x1", " 5x5", "-5x5", "16385x1", "1e3x1e3", "axb"}) {
        cs.push_back(command("render --size " + size, {"render", "s.toml", "--size", size, "--out", "o.png"}, 1, {"--size"}, "o.png"));
        cs.push_back(command("window --size " + size, {"s.toml", "--size", size, "--screenshot", "w.png"}, 2, {"--size"}, "w.png"));
    }
    for (const std::string eye : {"nan,nan,nan", "inf,0,0", "1,2", "1,2,3,4", "1e101,0,0", "a,b,c", "0,0,0", "0,5,0", ""})
        cs.push_back(command("render --eye " + eye, {"render", "s.toml", "--eye", eye, "--out", "o.png"}, 1, {"--eye"}, "o.png"));
    for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
             {"--algorithm", "zbufer"}, {"--format", "int12"}, {"--accel", "kdtree"}, {"--splitter", "random"}, {"--cull", "everything"}, {"--occluders", "solids"}})
    {
        std::vector<std::string> args{"render", "s.toml", option, value, "--out", "o.png"};
        if (option != "--algorithm") args.insert(args.begin() + 2, {"--algorithm", option == "--accel" ? "raycast" : option == "--splitter" ? "bsp" : "zbuffer"});
        cs.push_back(command("render " + option + " " + value, args, 1, {value}, "o.png"));
    }
    cs.push_back(command("render of a generated scene too small", {"render", "city:-5", "--out", "o.png"}, 1, {"city:-5"}, "o.png"));
    cs.push_back(command("render of a generated scene too large", {"render", "field:99999999999", "--out", "o.png"}, 1, {"field:99999999999"}, "o.png"));
    cs.push_back(command("render --out /dev/full", {"render", "s.toml", "--out", "/dev/full"}, 1, {"cannot write /dev/full"}));
    cs.push_back(command("render --out into no folder", {"render", "s.toml", "--out", "no/such/o.png"}, 1, {"cannot write no/such/o.png"}));
    cs.push_back(command("render --ids /dev/full", {"render", "s.toml", "--out", "o.png", "--ids", "/dev/full"}, 1, {"cannot write /dev/full"}));
    cs.push_back(command("trace --out /dev/full", {"trace", "s.toml", "--out", "/dev/full"}, 1, {"cannot write /dev/full"}));
    cs.push_back(command("trace --out a folder", {"trace", "s.toml", "--out", "."}, 1, {"cannot write"}));
    cs.push_back(command("trace of no file", {"trace", "none.toml", "--out", "t.jsonl"}, 1, {"none.toml:0:0: cannot open the file: No such file or directory"}, "t.jsonl"));
    cs.push_back(command("--screenshot /dev/full", {"s.toml", "--screenshot", "/dev/full", "--frames", "2", "--size", "640x400"}, 1, {"cannot write /dev/full"}));
    cs.push_back(command("--record under /proc", {"s.toml", "--record", "/proc/hsrviz", "--size", "640x400"}, 1, {"cannot make the folder /proc/hsrviz"}));
    cs.push_back(command("--record onto a file", {"s.toml", "--record", "s.toml", "--size", "640x400"}, 1, {"cannot make the folder s.toml"}));
    cs.push_back(command("--frame-log under /proc", {"s.toml", "--frame-log", "/proc/x", "--screenshot", "w.png", "--frames", "2", "--size", "640x400"}, 1, {"cannot write /proc/x"}));
    cs.push_back(command("report --out under /dev/null", {"report", "--quick", "--out", "/dev/null/sub"}, 1, {"/dev/null/sub"}));
    cs.push_back(command("--frames 0", {"s.toml", "--frames", "0", "--screenshot", "w.png"}, 2, {"--frames"}, "w.png"));
    cs.push_back(command("--frames -1", {"s.toml", "--frames", "-1", "--screenshot", "w.png"}, 2, {"--frames"}, "w.png"));
    cs.push_back(command("--gif from after to", {"s.toml", "--gif", "g.gif", "--from", "50", "--to", "10"}, 2, {"--from 50 is after --to 10"}, "g.gif"));
    cs.push_back(command("--scale 100", {"s.toml", "--scale", "100", "--screenshot", "w.png"}, 2, {"--scale"}, "w.png"));
    cs.push_back(command("--keys Drag of nan", {"s.toml", "--keys", "Drag:4:1:nan:nan", "--screenshot", "w.png", "--size", "640x400"}, 2, {"Drag:4:1:nan:nan"}));
    cs.push_back(command("--keys Drag far away", {"s.toml", "--keys", "Drag:4:1:1e30:1", "--screenshot", "w.png", "--size", "640x400"}, 2, {"Drag:4:1:1e30:1"}));
    cs.push_back(command("--keys an unknown key", {"s.toml", "--keys", "Hyper+Q", "--screenshot", "w.png", "--size", "640x400"}, 2, {"Hyper+Q"}));
    cs.push_back(command("an unknown option", {"s.toml", "--colour", "red"}, 2, {"--colour"}));
    cs.push_back(command("an unknown subcommand option", {"check", "s.toml", "--fix"}, 2, {"--fix"}));
    cs.push_back(command("a control character in a file name", {"check", "a\x1b[31mred.toml"}, 1, {"a\\x1b[31mred.toml"}));
    // ── issue 53's last points: what a lesson needs, checked before the work; bounds that agree; tiny triangles ───
    {
        const std::string no_ray = "title = \"t\"\nalgorithm = \"intersection_test\"\nscene = \"field:20000000\"\n";
        Case c{"lesson: an intersection test on a generated scene (no ray), refused before it is generated", {{"s.toml", scene}, {"l.toml", no_ray}}, {}, {}};
        // with the memory for it held back, the missing ray must be what is said: it is looked at first
        c.runs.push_back({{"check", "l.toml"}, 1, {"l.toml:3:9:", "needs a ray"}, "", "HSRVIZ_MEMORY_LIMIT=2000000000", 0, {"needs about"}});
        cs.push_back(c);
        cs.push_back(bad_lesson("lesson: an intersection test on a scene without segments",
                                "title = \"t\"\nalgorithm = \"intersection_test\"\nscene = \"s.toml\"\n", {"l.toml:3:9:", "needs a ray"}));
        cs.push_back(bad_lesson("lesson: the floating horizon on a scene without a terrain",
                                "title = \"t\"\nalgorithm = \"floating_horizon\"\nscene = \"city:1000\"\n", {"l.toml:3:9:", "needs a scene with a [terrain]"}));
    }
    for (const auto& [name, terrain] : std::vector<std::pair<std::string, std::string>>{
             {"a million rows of 2, generated", "[terrain]\ngenerate = \"hills\"\ncolumns = 2\nrows = 1000000\n"},
             {"78,126 rows of 2", [] {
                  std::string t = "[terrain]\nheights = [\n";
                  for (int j = 0; j < 78'126; ++j) t += "[0, 1],\n";
                  return t + "]\n";
              }()}}) {
        Case c{"terrain: " + name + " (more rows than the floating horizon can draw on 256 columns)",
               {{"s.toml", "name = \"hills\"\n" + terrain}}, {}, {}};
        c.runs.push_back({{"check", "s.toml"}, 1, {"s.toml:", "a terrain has at most 78125 rows"}, ""});
        c.runs.push_back({{"trace", "s.toml", "--out", "t.jsonl"}, 1, {"s.toml:", "a terrain has at most 78125 rows"}, "t.jsonl"});
        cs.push_back(c);
    }
    {
        const std::string tiny = with(scene, "vertices =", "vertices = [[-2e-160, -1e-160, -1.5e-160], [1.6e-160, -0.8e-160, 0.8e-160], [-0.4e-160, 1.6e-160, -0.2e-160]]");
        Case c{"a triangle 1e-160 across: every algorithm takes it, the BSP too", {{"s.toml", tiny}}, {}, {}};
        for (const char* algorithm : {"bsp", "zbuffer", "scanline", "scanline-classic", "raycast", "depth-sort"})
            c.runs.push_back({{"render", "s.toml", "--algorithm", algorithm, "--size", "64x48", "--out", "o.png"}, 0, {"wrote o.png"}, "", "", 0, {"degenerate"}});
        cs.push_back(c);
    }
    {
        // Ctrl+C while a 16384² picture is compressed (seconds): it stops, leaving no file (it was ignored for 30 s)
        Case c{"render: Ctrl+C while the picture is written", {{"s.toml", scene}}, {}, {}};
        // 16384², the largest size: its write takes longer than the 4 s before the Ctrl+C on an idle machine too (at
        // 16384×8192 render and write were done in under 4 s once the machine was quiet, exit 0); under the sanitizers
        // the Ctrl+C may come while it renders, which stops it the same way
        c.runs.push_back({{"render", "s.toml", "--size", "16384x16384", "--out", "o.png"}, 130, {"stopped (Ctrl+C); no image written"}, "o.png", "", 4.0});
        cs.push_back(c);
    }
    {
        // the estimate from each algorithm's measured bytes per triangle, before anything is generated: the z-buffer on
        // city:20000000 needs about 9.8 GB (it said 22.4 GB for every algorithm, refusing it on a 23 GB machine)
        Case c{"render of city:20000000 with the z-buffer: its own estimate", {{"s.toml", scene}}, {}, {}};
        c.runs.push_back({{"render", "city:20000000", "--algorithm", "zbuffer", "--out", "o.png"}, 1, {"needs about 9.8 GB of memory"}, "o.png",
                          "HSRVIZ_MEMORY_LIMIT=2000000000"});
        cs.push_back(c);
    }
    // ── work no machine of the class can do: refused before it starts, with the figures ─────────────────────────
    for (const auto& [name, args] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"render at 16384×16384", {"render", "s.toml", "--size", "16384x16384", "--out", "o.png"}},
             {"render of city:2000000", {"render", "city:2000000", "--out", "o.png"}},
             {"check of a lesson on field:20000000", {"check", "l.toml"}},
             {"the window on a lesson on field:20000000", {"l.toml", "--screenshot", "w.png", "--frames", "2", "--size", "640x400"}}}) {
        Case c{name, {{"s.toml", scene}, {"l.toml", "title = \"t\"\nalgorithm = \"cull_bounds\"\nscene = \"field:20000000\"\n"}}, {}, {}};
        c.runs.push_back({args, 1, {"needs about", "of memory, and about 1.9 GB is available"}, "o.png", "HSRVIZ_MEMORY_LIMIT=2000000000"});
        cs.push_back(c);
    }
    return cs;
}

}  // namespace bad_inputs

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: bad_input_catalogue HSRVIZ WORK_DIR\n";
        return 2;
    }
    using namespace bad_inputs;
    hsrviz = fs::absolute(argv[1]).string();
    work = fs::absolute(argv[2]);
    fs::create_directories(work);
    std::vector<Case> cs = catalogue();
    for (auto* family : {output_cases, settings_cases, option_cases})
        for (Case& c : family()) cs.push_back(std::move(c));
    for (std::size_t k = 0; k < cs.size(); ++k) run_case(cs[k], k);
    std::size_t runs = 0;
    for (const auto& [outcome, n] : outcomes) runs += std::size_t(n);
    std::cout << cs.size() << " bad inputs, " << runs << " runs through check, trace, render, the window and the command line:\n";
    for (const auto& [outcome, n] : outcomes) std::cout << "  " << n << " " << outcome << "\n";
    std::cout << failures << " runs gave the wrong outcome\n";
    return failures == 0 ? 0 : 1;
}
