// SPDX-License-Identifier: MIT
// The window's remembered settings: a round trip, the defaults when there is no file, and a broken file or field
// named (file and line) and the rest still used.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/stat.h>

#include "catch.h"
#include "state/window_settings.h"

using namespace hsr::viz;

TEST_CASE("window settings round trip, default when missing, and name a broken field", "[state][settings]") {
    const std::string dir = (std::filesystem::temp_directory_path() / "hsrviz_settings_test").string();
    std::filesystem::remove_all(dir);
    const std::string path = dir + "/sub/window.toml";
    std::string warning;
    CHECK(read_window_settings(path, warning) == WindowSettings{});
    CHECK(warning.empty());

    const WindowSettings s{.width = 1600, .height = 900, .x = 40, .y = -20, .maximized = true, .side = 620, .language = "de"};
    REQUIRE(write_window_settings(path, s).empty());
    CHECK(read_window_settings(path, warning) == s);
    CHECK(warning.empty());

    std::ofstream(path) << "width = 1500\nheight = \"tall\"\nside = 700\n";
    const WindowSettings partly = read_window_settings(path, warning);
    CHECK(partly.width == 1500);
    CHECK(partly.height == 800);  // the default: the field is named
    CHECK(partly.side == 700);
    CHECK(warning.find("window.toml:2: field 'height'") != std::string::npos);

    std::ofstream(path) << "width = 15e20\nheight = 900.0\n";  // floats are not whole numbers (15e20 was undefined behaviour)
    const WindowSettings floats = read_window_settings(path, warning);
    CHECK(floats.width == 1280);
    CHECK(floats.height == 800);
    CHECK(warning.find("expected a whole number") != std::string::npos);

    std::ofstream(path) << "width = [1\n";
    CHECK(read_window_settings(path, warning) == WindowSettings{});
    CHECK(warning.find("window.toml:") != std::string::npos);
    CHECK(warning.find("kept as") != std::string::npos);  // the broken file is kept aside, not replaced unseen
    CHECK(std::filesystem::exists(path + ".bak"));
    CHECK_FALSE(std::filesystem::exists(path));

    // HSRVIZ_CONFIG pointed at a lesson: read as nothing, and never overwritten
    const std::string lesson = dir + "/lesson.toml", text = "title = \"Mine\"\nalgorithm = \"zbuffer_fill\"\n";
    std::ofstream(lesson) << text;
    CHECK(read_window_settings(lesson, warning) == WindowSettings{});
    CHECK(warning.find("is not an hsrviz settings file (it has 'algorithm')") != std::string::npos);
    CHECK_FALSE(write_window_settings(lesson, s).empty());
    std::ifstream in(lesson);
    CHECK(std::string(std::istreambuf_iterator<char>(in), {}) == text);
    // A FIFO or a folder at the path: neither read (no hang) nor replaced
    const std::string fifo = dir + "/fifo.toml";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(read_window_settings(fifo, warning) == WindowSettings{});
    CHECK(warning.find("FIFO") != std::string::npos);
    CHECK_FALSE(write_window_settings(fifo, s).empty());
    CHECK(std::filesystem::is_fifo(fifo));
    CHECK_FALSE(write_window_settings(dir + "/sub", s).empty());

    CHECK(clamp_side(100, 1280) == 320);
    CHECK(clamp_side(2000, 1280) == 960);
    CHECK(clamp_side(500, 500) == 320);
    std::filesystem::remove_all(dir);
}
