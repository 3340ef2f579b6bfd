// SPDX-License-Identifier: MIT
// Links to a moment of a lesson (#lesson=05_bsp_traversal&step=12), the hash of the events played so far (the
// page and the desktop compare it), and which of several dropped files is opened.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "catch.h"
#include "state/families.h"
#include "state/place_link.h"
#include "state/trace.h"

using namespace hsr::viz;

TEST_CASE("a link names a lesson, a step, a language and the projector, a bad part is named and left out", "[state][link]") {
    std::string problems;
    PlaceLink link = read_place_link("#lesson=05_bsp_traversal&step=12", problems);
    CHECK(problems.empty());
    CHECK(link.lesson == "05_bsp_traversal");
    CHECK(link.step == 12u);
    CHECK(link.language.empty());
    CHECK_FALSE(link.projector);
    CHECK(place_link(link.lesson, *link.step) == "#lesson=05_bsp_traversal&step=12");

    link = read_place_link("lang=de&&projector&lesson=00_tour", problems);  // no '#', an empty part, any order
    CHECK(problems.empty());
    CHECK(link.lesson == "00_tour");
    CHECK_FALSE(link.step);
    CHECK(link.language == "de");
    CHECK(link.projector);

    // a path is not a lesson's name; a step must be a whole number; an unknown key is named: the rest still opens
    link = read_place_link("#lesson=../../etc/passwd&step=12", problems);
    CHECK(link.lesson.empty());
    CHECK(link.step == 12u);
    CHECK(problems.find("lesson=../../etc/passwd: not a lesson's name") != std::string::npos);
    problems.clear();
    link = read_place_link("#lesson=01_cohen_sutherland&step=-3&step=1e3&zoom=2&lang=DE", problems);
    CHECK(link.lesson == "01_cohen_sutherland");
    CHECK_FALSE(link.step);
    CHECK(problems.find("step=-3: not a step number") != std::string::npos);
    CHECK(problems.find("step=1e3: not a step number") != std::string::npos);
    CHECK(problems.find("zoom=2: unknown") != std::string::npos);
    CHECK(problems.find("lang=DE: not a language code") != std::string::npos);
    problems.clear();
    read_place_link("#step=99999999999999999999999", problems);  // beyond size_t
    CHECK(problems.find("not a step number") != std::string::npos);
    problems.clear();
    CHECK(read_place_link("", problems).lesson.empty());
    CHECK(problems.empty());

    // a shipped lesson has a name in links; another file has none
    CHECK(linked_lesson_name(linked_lesson_path("05_bsp_traversal")) == "05_bsp_traversal");
    CHECK(linked_lesson_name(data_dir() + "/lessons/../lessons/00_tour.toml") == "00_tour");
    CHECK(linked_lesson_name(data_dir() + "/assets/scenes/bsp_2d_segments.toml").empty());
    CHECK(linked_lesson_name("/tmp/05_bsp_traversal.toml").empty());
    CHECK(linked_lesson_name("").empty());
}

TEST_CASE("the played trace is the hash of the trace's first lines, as far as the player has gone", "[state][link][trace]") {
    for (const char* name : {"00_tour", "05_bsp_traversal", "13_depth_sort_cycle"}) {
        INFO(name);
        const Lesson lesson = load_lesson(linked_lesson_path(name));
        std::ostringstream whole;
        const TraceSummary all = trace_lesson(lesson, &whole);
        // the first n lines of the whole trace, hashed independently of the session
        const auto first_lines = [&](std::size_t n) {
            std::istringstream lines(whole.str());
            TraceSummary first;
            std::string line;
            for (; first.events < n && std::getline(lines, line); ++first.events) hash_line(first, line);
            return first.hash;
        };
        CHECK(first_lines(0) == TraceSummary{}.hash);
        const auto session = make_session(lesson);  // (some lessons open past their first events: 05 at its tree)
        CHECK(played_trace(*session).events == session->cursor());
        CHECK(played_trace(*session).hash == first_lines(session->cursor()));
        const std::size_t opened_at = session->cursor();
        session->step(), session->step(), session->step();
        session->step_back();
        REQUIRE(session->cursor() > opened_at);
        CHECK(played_trace(*session).events == session->cursor());
        CHECK(played_trace(*session).hash == first_lines(session->cursor()));
        CHECK(played_trace(*session).hash != first_lines(session->cursor() - 1));
        session->seek_end();
        CHECK(played_trace(*session).events == all.events);
        CHECK(played_trace(*session).hash == all.hash);
    }
}

TEST_CASE("of files dropped together, the lesson is opened, else a scene, else the first", "[state][link]") {
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_dropped_test";
    std::filesystem::create_directories(dir);
    const std::string lesson = (dir / "mine.toml").string(), scene = (dir / "room.toml").string(), mesh = (dir / "cube.obj").string();
    std::ofstream(lesson) << "# a lesson\ntitle = \"Mine\"\n  algorithm = \"bsp_build\"\nscene = \"room.toml\"\n";
    std::ofstream(scene) << "name = \"room\"\n# algorithm = \"not a key: a comment\"\nalgorithms_list = 1\n";
    std::ofstream(mesh) << "v 0 0 0\n";
    CHECK(file_to_open({scene, mesh, lesson}) == lesson);
    CHECK(file_to_open({mesh, scene}) == scene);
    CHECK(file_to_open({mesh}) == mesh);
    CHECK(file_to_open({(dir / "gone.toml").string(), scene}) == (dir / "gone.toml").string());  // the error is shown
    CHECK(file_to_open({}).empty());
    std::filesystem::remove_all(dir);
}
