// SPDX-License-Identifier: MIT
// Outputs: every command that writes, with a folder in the way, a full disk (/dev/full), a data folder without its
// scenes, a Ctrl+C halfway, and its standard output going nowhere. A run says so and exits non-zero; no half file.
#include <sys/stat.h>

#include <fstream>

#include "catalogue.h"

namespace bad_inputs {
namespace {

const std::string big_lesson = "title = \"t\"\nalgorithm = \"zbuffer_fill\"\nscene = \"field:3000000\"\n";

Case with_files(const std::string& name, std::function<void(const fs::path&)> make, Run run) {
    Case c{name, {{"s.toml", scene}, {"big.toml", big_lesson}}, std::move(make), {}};
    c.runs.push_back(std::move(run));
    return c;
}

}  // namespace

std::vector<Case> output_cases() {
    std::vector<Case> cs;
    // ── report: checked before minutes of measuring, written whole or not at all ──────────────────────────────────
    cs.push_back(with_files("report: report.md is a folder", [](const fs::path& d) { fs::create_directories(d / "r/report.md"); },
                            {{"report", "--quick", "--out", "r"}, 1, {"r/report.md is a folder; nothing measured"}}));
    cs.push_back(with_files("report: report.csv is a folder", [](const fs::path& d) { fs::create_directories(d / "r/report.csv"); },
                            {{"report", "--quick", "--out", "r"}, 1, {"r/report.csv is a folder"}}));
    cs.push_back(with_files("report: a full disk (report.md on /dev/full)",
                            [](const fs::path& d) { fs::create_directories(d / "r"), fs::create_symlink("/dev/full", d / "r/report.md"); },
                            {{"report", "--quick", "--out", "r"}, 1, {"cannot write r/report.md: No space left on device"}, "r/report.csv"}));
    cs.push_back(with_files("report: --out onto a file", {}, {{"report", "--quick", "--out", "s.toml"}, 1, {"cannot make the folder s.toml"}}));
    for (const std::string command : {"report", "check"}) {
        Run r{{command}, 1, {"HSRVIZ_DATA"}, "r"};
        if (command == "report") r.args = {"report", "--quick", "--out", "r"};
        r.env = "HSRVIZ_DATA=\"$PWD/empty\"";
        r.says.push_back(command == "report" ? "cannot read the shipped scenes in" : "cannot read the shipped lessons and scenes in");
        cs.push_back(with_files(command + ": HSRVIZ_DATA names an empty folder", [](const fs::path& d) { fs::create_directory(d / "empty"); }, r));
        r.env = "HSRVIZ_DATA=\"$PWD/none\"";
        cs.push_back(with_files(command + ": HSRVIZ_DATA names no folder", {}, r));
    }
    // ── trace: a Ctrl+C, a full disk, an output in the way ──────────────────────────────────────────────────────
    Run ctrl_c{{"trace", "big.toml", "--out", "t.jsonl"}, 130, {"stopped (Ctrl+C); no trace written"}, "t.jsonl"};
    ctrl_c.interrupt_after = 3;
    cs.push_back(with_files("trace: Ctrl+C on a lesson of 3,000,000 triangles", {}, ctrl_c));
    cs.push_back(with_files("trace: --out a link to /dev/full", [](const fs::path& d) { fs::create_symlink("/dev/full", d / "t.jsonl"); },
                            {{"trace", "s.toml", "--out", "t.jsonl"}, 1, {"cannot write t.jsonl: No space left on device"}}));
    cs.push_back(with_files("trace: --out into a missing folder", {}, {{"trace", "s.toml", "--out", "no/t.jsonl"}, 1, {"cannot write no/t.jsonl"}}));
    // ── render: an output in the way ────────────────────────────────────────────────────────────────────────────
    cs.push_back(with_files("render: --out a folder", [](const fs::path& d) { fs::create_directory(d / "o.png"); },
                            {{"render", "s.toml", "--out", "o.png", "--size", "64x48"}, 1, {"cannot write o.png"}}));
    // ── the standard output going to a full disk: said, exit 1, never 0 with everything lost ────────────────────
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"practice", "bsp", "--count", "1000"}, {"practice", "list"}, {"check", "s.toml"}, {"trace", "s.toml", "--out", "t.jsonl"},
             {"render", "s.toml", "--out", "o.png", "--size", "64x48"}, {"--help"}, {"--version"}, {"--lesson-list"}}) {
        Run r{args, 1, {"cannot write the standard output"}};
        r.stdout_to = "/dev/full";
        std::string name = "stdout on /dev/full:";
        for (const std::string& a : args) name += " " + a;
        cs.push_back(with_files(name, {}, r));
    }
    // ── the window's outputs ────────────────────────────────────────────────────────────────────────────────────
    Run record{{"s.toml", "--record", "/proc/hsrviz-frames", "--size", "640x400"}, 1, {"cannot make the folder /proc/hsrviz-frames"}};
    record.never_says = {"wrote 0 frames"};
    cs.push_back(with_files("--record under /proc says nothing was written", {}, record));
    cs.push_back(with_files("--gif --from past the lesson's end", {},
                            {{"s.toml", "--gif", "g.gif", "--from", "1000000", "--to", "2000000", "--size", "640x400"}, 2,
                             {"--from 1000000 is past the lesson's last step"}, "g.gif"}));
    return cs;
}

}  // namespace bad_inputs
