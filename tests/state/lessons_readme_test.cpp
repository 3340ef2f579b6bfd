// SPDX-License-Identifier: MIT
// lessons/README.md is the course's index for a teacher: it must say what the lesson files say. Every shipped lesson
// has a row, and each row's algorithm, difficulty, prerequisites, chapter and question counts and languages are the
// lesson's own (a lesson listed with chapters it lacks, or a question count that is out of date, fails here).
#include "catch.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bsp/bsp_events.h"
#include "registry.h"
#include "state/lesson.h"
#include "scene/renderer_names.h"

using hsr::viz::Lesson;

namespace {

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::vector<std::string> cells_of(const std::string& row) {  // "| a | b |" → {"a", "b"}
    std::vector<std::string> cells;
    std::stringstream in(row.substr(1));
    for (std::string cell; std::getline(in, cell, '|');) cells.push_back(trim(cell));
    return cells;
}

std::string joined(const std::vector<std::string>& v, const std::string& separator) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : separator) + x;
    return s;
}

}  // namespace

TEST_CASE("lessons/README.md lists every lesson as its file says it is", "[lesson][readme]") {
    std::ifstream readme(HSR_SOURCE_DIR "/lessons/README.md");
    REQUIRE(readme);
    std::map<std::string, std::vector<std::string>> rows;  // file → cells
    std::vector<std::string> header;
    for (std::string line; std::getline(readme, line);) {
        if (line.rfind("| file |", 0) == 0) header = cells_of(line);
        else if (line.rfind("| ", 0) == 0 && line.find(".toml |") != std::string::npos) rows[cells_of(line)[0]] = cells_of(line);
    }
    REQUIRE(header == std::vector<std::string>{"file", "title", "algorithm", "difficulty", "prerequisites", "chapters", "questions", "languages"});
    const std::vector<std::string> shipped = hsr::viz::shipped_lessons();
    REQUIRE(shipped.size() >= 27);
    CHECK(rows.size() == shipped.size());
    for (const std::string& path : shipped) {
        const std::string file = std::filesystem::path(path).filename().string();
        INFO(file);
        REQUIRE(rows.count(file) == 1);
        const std::vector<std::string>& row = rows[file];
        REQUIRE(row.size() == header.size());
        const Lesson l = hsr::viz::load_lesson(path);
        CHECK(row[2] == l.algorithm.id);
        CHECK(row[3] == std::to_string(l.difficulty));
        std::vector<std::string> prerequisites;  // the README names a prerequisite by its number: "07"
        for (const std::string& p : l.prerequisites) prerequisites.push_back(std::filesystem::path(p).filename().string().substr(0, 2));
        CHECK(row[4] == (prerequisites.empty() ? std::string("—") : joined(prerequisites, ", ")));
        CHECK(row[5] == std::to_string(l.chapters.size()));
        const auto questions = std::count_if(l.chapters.begin(), l.chapters.end(), [](const auto& c) { return c.question.has_value(); });
        CHECK(row[6] == std::to_string(questions));
        CHECK(row[7] == joined(l.languages, ", "));
    }
}

// A lesson that tells the student to try `--algorithm X` or `--splitter Y` names something the command line takes
// (lesson 04 once sent students to `--algorithm` for the splitter rules, which it refuses).
TEST_CASE("the command lines the lessons quote name real algorithms and splitter rules", "[lesson]") {
    const std::regex algorithm_option(R"((render[^.;"]*?)?--algorithm\s+([a-z_-]+))"), splitter_option(R"(--splitter\s+([a-z_-]+))");

    int quoted = 0;
    for (const std::string& file : hsr::viz::shipped_lessons()) {
        std::ifstream in(file);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (auto m = std::sregex_iterator(text.begin(), text.end(), algorithm_option); m != std::sregex_iterator(); ++m, ++quoted) {
            INFO(file << ": " << m->str());
            if ((*m)[1].matched) CHECK(hsr::algo::is_renderer((*m)[2].str()));
            else CHECK(hsr::algo::find_algorithm((*m)[2].str()).has_value());
        }
        for (auto m = std::sregex_iterator(text.begin(), text.end(), splitter_option); m != std::sregex_iterator(); ++m, ++quoted) {
            INFO(file << ": " << m->str());
            CHECK(hsr::algo::parse_splitter_rule((*m)[1].str()).has_value());
        }
    }
    CHECK(quoted >= 4);  // the lessons do quote them (06, 09, 20, 04)
}
