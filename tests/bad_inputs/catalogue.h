// SPDX-License-Identifier: MIT
// The bad-input catalogue's parts: a case is files in a folder of its own and runs of the real hsrviz binary with
// the outcome each must give (bad_input_catalogue.cpp runs them and counts the outcomes). The families live in
// files of their own: the first catalogue in bad_input_catalogue.cpp, outputs and full disks, the settings file's
// neighbours, OBJ faces and the numeric options in output_cases.cpp, settings_cases.cpp and option_cases.cpp.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace bad_inputs {

namespace fs = std::filesystem;

// One run of the binary: its arguments, the exit code it must give, and what its output must contain.
struct Run {
    std::vector<std::string> args;
    int exit = 1;
    std::vector<std::string> says;
    std::string no_output;       // a file that must not exist afterwards (no partial output)
    std::string env;             // VARIABLE=value before the command
    double interrupt_after = 0;  // seconds: a Ctrl+C (SIGINT) then, as a person would press it
    std::vector<std::string> never_says;  // what its output must not contain
    std::string stdout_to;       // where its standard output goes (/dev/full, say); its stderr alone is then read
};

struct Case {
    std::string name;
    std::map<std::string, std::string> files;         // written into the case's folder
    std::function<void(const fs::path&)> make;        // files that text cannot make (FIFOs, links, sparse files)
    std::vector<Run> runs;
    std::function<std::string(const fs::path&)> after;  // what must hold of the folder after the runs: "" or why not
};

// The base files every variation starts from: a scene of one triangle, a scene placing m.obj, a lesson on s.toml.
extern const std::string scene, mesh_scene, lesson;

// The text with the line that starts with `prefix` replaced (or removed, when `line` is empty).
std::string with(const std::string& text, const std::string& prefix, const std::string& line);
// A scene refused by check, trace and render, each naming the file and line and saying `says`.
Case bad_scene(const std::string& name, const std::string& text, std::vector<std::string> says);
// A scene (mesh_scene unless given) placing m.obj = `obj`, refused as bad_scene is.
Case bad_mesh(const std::string& name, const std::string& obj, std::vector<std::string> says, const std::string& scene_text = mesh_scene);
// One run of the command line in a folder holding s.toml.
Case command(const std::string& name, std::vector<std::string> args, int exit, std::vector<std::string> says,
             const std::string& no_output = "");
std::string read(const fs::path& p);

std::vector<Case> output_cases();    // every command that writes: folders in the way, /dev/full, Ctrl+C, stdout
std::vector<Case> settings_cases();  // the settings file and its neighbours: FIFO, links, .bak, lessons, notes
std::vector<Case> option_cases();    // every numeric option at and past its range, and NaN; OBJ faces of 3 to 10^5

}  // namespace bad_inputs
