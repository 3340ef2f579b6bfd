// SPDX-License-Identifier: MIT
// Lessons load and play to the end; traces are JSON Lines and the same input gives the same hash.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "catch.h"
#include "scene/toml_reader.h"
#include "state/families.h"
#include "state/trace.h"

using namespace hsr::viz;

TEST_CASE("every shipped lesson loads and plays to its end", "[lesson]") {
    int lessons = 0;
    for (const auto& e : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/lessons")) {
        if (e.path().extension() != ".toml") continue;
        INFO(e.path());
        const auto session = make_session(load_lesson(e.path().string()));
        session->seek_end();
        CHECK(session->complete());
        CHECK(session->cursor() >= 6);  // more than a start and an end: the shortest, depth sort's simple case, has 6
        CHECK_FALSE(session->narration().empty());
        CHECK(session->current_line() >= 0);
        CHECK(std::size_t(session->current_line()) < session->pseudocode().size());
        ++lessons;
    }
    CHECK(lessons >= 5);
}

TEST_CASE("the default lesson is Cohen–Sutherland", "[lesson]") {
    const Lesson lesson = load_lesson(default_lesson_path());
    CHECK(lesson.algorithm.id == "cohen_sutherland");
}

TEST_CASE("a lesson with an unknown algorithm or a missing scene names the field", "[lesson][errors]") {
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_lesson_test";
    std::filesystem::create_directories(dir);
    const auto write = [&](const char* name, const char* text) {
        const auto p = dir / name;
        std::ofstream(p) << text;
        return p.string();
    };
    const auto bad_algorithm = write("a.toml", "title = \"t\"\nalgorithm = \"cohen_sutherlund\"\nscene = \"x.toml\"\n");
    CHECK_THROWS_WITH(load_lesson(bad_algorithm), Catch::Contains("a.toml:2:") && Catch::Contains("'algorithm'") &&
                                                      Catch::Contains("cohen_sutherland"));
    const auto missing_scene = write("b.toml", "title = \"t\"\nalgorithm = \"liang_barsky\"\nscene = \"nope.toml\"\n");
    CHECK_THROWS_WITH(load_lesson(missing_scene), Catch::Contains("b.toml:3:") && Catch::Contains("'scene'"));
    const auto bad_display = write("c.toml", "title = \"t\"\nalgorithm = \"depth_sort\"\ndisplay = \"front-to-bak\"\nscene = \"x.toml\"\n");
    CHECK_THROWS_WITH(load_lesson(bad_display), Catch::Contains("c.toml:3:") && Catch::Contains("'display'") &&
                                                    Catch::Contains("front-to-back"));
}

TEST_CASE("a depth-sort lesson displayed front to back: the sort, then each pixel written once, stopping when the screen is full", "[lesson][depth_sort]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/28_depth_sort_front_to_back.toml");
    REQUIRE(lesson.front_to_back);
    std::ostringstream trace;
    trace_lesson(lesson, &trace);
    std::istringstream lines(trace.str());
    std::vector<nlohmann::json> events;
    for (std::string line; std::getline(lines, line);) events.push_back(nlohmann::json::parse(line));
    std::vector<std::string> kinds;
    for (const auto& e : events) kinds.push_back(e["kind"]);
    // every polygon joins the list before the display step draws; the two panels fill the screen; the last event closes
    const auto first_front = std::find(kinds.begin(), kinds.end(), "FrontPolygonDrawn");
    REQUIRE(first_front != kinds.end());
    CHECK(std::count(kinds.begin(), first_front, "PolygonPainted") == 5);
    CHECK(std::count(kinds.begin(), kinds.end(), "FrontPolygonDrawn") == 2);
    const auto filled = std::find(kinds.begin(), kinds.end(), "ScreenFilled");
    REQUIRE(filled != kinds.end());
    CHECK(events[std::size_t(filled - kinds.begin())]["left"] == 3);
    CHECK(kinds.back() == "DepthSortFinished");
    // the panels' pixels add up to the grid: written by the nearest only
    std::uint64_t written = 0;
    for (const auto& e : events)
        if (e["kind"] == "FrontPolygonDrawn") written += e["written"].get<std::uint64_t>();
    CHECK(written == std::uint64_t(lesson.grid.width) * std::uint64_t(lesson.grid.height));
}

TEST_CASE("a trace is one JSON object per event, and the same input gives the same hash", "[trace]") {
    const Lesson lesson = load_lesson(default_lesson_path());
    std::ostringstream first, second;
    const TraceSummary a = trace_lesson(lesson, &first);
    const TraceSummary b = trace_lesson(lesson, &second);
    CHECK(a.events > 20);
    CHECK(a.hash == b.hash);
    CHECK(first.str() == second.str());

    std::istringstream lines(first.str());
    std::string line;
    std::uint64_t step = 0;
    while (std::getline(lines, line)) {
        const auto j = nlohmann::json::parse(line);
        CHECK(j.at("step") == step++);
        CHECK(j.at("kind").is_string());
        CHECK_FALSE(j.at("text").get<std::string>().empty());
    }
    CHECK(step == a.events);

    // A different algorithm on the same scene is a different trace.
    CHECK(trace_lesson(load_lesson(default_lesson_path(), "liang_barsky"), nullptr).hash != a.hash);
}

TEST_CASE("a trace asked to stop (Ctrl+C) stops between two events, its output ending with a whole line", "[trace]") {
    std::ostringstream out;
    std::atomic<bool> stop{true};
    CHECK_THROWS_AS(trace_lesson(load_lesson(default_lesson_path()), &out, &stop), hsr::algo::WorkStopped);
    CHECK(out.str().empty());
    stop = false;
    CHECK(trace_lesson(load_lesson(default_lesson_path()), &out, &stop).events > 0);
}

TEST_CASE("a BSP lesson traces BSP events, with split parts named as the window names them", "[trace][bsp]") {
    std::ostringstream out;
    const TraceSummary t = trace_lesson(load_lesson(data_dir() + "/lessons/04_bsp_build.toml"), &out);
    CHECK(t.events > 20);
    std::istringstream lines(out.str());
    std::string line;
    int splits = 0, drawn = 0;
    while (std::getline(lines, line)) {
        const auto j = nlohmann::json::parse(line);
        if (j.at("kind") == "PolygonSplit") {
            ++splits;
            CHECK_THAT(j.at("text").get<std::string>(), Catch::Contains("f (front") && Catch::Contains("b (back"));
            CHECK(j.at("front").size() == 2);  // a 2D wall's part: two vertices
        }
        drawn += j.at("kind") == "PolygonDrawn";
        CHECK(j.at("kind") != "SegmentStarted");  // not a clipping machine
    }
    CHECK(splits == 2);
    CHECK(drawn == 7);
}
