// SPDX-License-Identifier: MIT
// The window's remembered settings: a round trip, the defaults when there is no file, and a broken file or field
// named (file and line) and the rest still used.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include "catch.h"
#include "state/output_folder.h"
#include "state/window_settings.h"

using namespace hsr::viz;

TEST_CASE("window settings round trip, default when missing, and name a broken field", "[state][settings]") {
    const std::string dir = (std::filesystem::temp_directory_path() / "hsrviz_settings_test").string();
    std::filesystem::remove_all(dir);
    const std::string path = dir + "/sub/window.toml";
    std::string warning;
    CHECK(read_window_settings(path, warning) == WindowSettings{});
    CHECK(warning.empty());

    const WindowSettings s{.width = 1600, .height = 900, .x = 40, .y = -20, .maximized = true, .side = 620, .language = "de",
                           .practice = {{"bsp", {7, 5, 3}}, {"cohen_sutherland", {2, 0, 0}}}};
    REQUIRE(write_window_settings(path, s).empty());
    CHECK(read_window_settings(path, warning) == s);
    CHECK(warning.empty());

    // the type's size (Ctrl+±) is remembered when chosen, and absent otherwise (the screen's then)
    WindowSettings sized = s;
    sized.scale = 1.21f;
    REQUIRE(write_window_settings(path, sized).empty());
    REQUIRE(read_window_settings(path, warning).scale);
    CHECK(*read_window_settings(path, warning).scale == 1.21f);
    CHECK_FALSE(read_window_settings(path, warning) == s);
    std::ofstream(path) << "type_size = 4000\nside = 700\n";
    CHECK_FALSE(read_window_settings(path, warning).scale);
    CHECK(warning.find("window.toml:1: field 'type_size'") != std::string::npos);

    std::ofstream(path) << "width = 1500\nheight = \"tall\"\nside = 700\n";
    const WindowSettings partly = read_window_settings(path, warning);
    CHECK(partly.width == 1500);
    CHECK(partly.height == 800);  // the default: the field is named
    CHECK(partly.side == 700);
    CHECK(warning.find("window.toml:2: field 'height'") != std::string::npos);

    // a practice score that cannot be (more right than answered), a topic named oddly: skipped and named, the rest kept
    std::ofstream(path) << "[practice.bsp]\nanswered = 4\nright = 3\nbest_streak = 2\n[practice.zbuffer]\nanswered = 1\nright = 5\n"
                           "best_streak = 0\n[practice.\"../x\"]\nanswered = 1\nright = 1\nbest_streak = 1\n";
    const WindowSettings scores = read_window_settings(path, warning);
    CHECK(scores.practice.size() == 1);
    CHECK(scores.practice.at("bsp") == PracticeRecord{4, 3, 2});
    CHECK(warning.find("field 'practice.") != std::string::npos);

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

TEST_CASE("the window's files go to the current directory, or under the data home when that is the home folder",
          "[state][output]") {
    namespace fs = std::filesystem;
    const fs::path before = fs::current_path();
    const fs::path root = fs::temp_directory_path() / ("hsrviz-output-" + std::to_string(::getpid()));
    fs::create_directories(root / "home" / "work");
    const auto saved = [](const char* v) { const char* x = std::getenv(v); return x ? std::optional<std::string>(x) : std::nullopt; };
    const auto home_before = saved("HOME"), data_before = saved("XDG_DATA_HOME");
    const auto restore = [&] {  // the rest of the process sees what it saw before
        fs::current_path(before);
        unsetenv("HSRVIZ_OUTPUT");
        for (const auto& [v, x] : {std::pair{"HOME", home_before}, std::pair{"XDG_DATA_HOME", data_before}})
            x ? setenv(v, x->c_str(), 1) : unsetenv(v);
        fs::remove_all(root);
    };
    setenv("HOME", (root / "home").c_str(), 1);
    setenv("XDG_DATA_HOME", (root / "data").c_str(), 1);
    unsetenv("HSRVIZ_OUTPUT");
    fs::current_path(root / "home" / "work");
    CHECK(output_folder("hsrviz-export") == "hsrviz-export");  // started from a shell in a folder of one's own
    fs::current_path(root / "home");
    CHECK(output_folder("hsrviz-export") == (root / "data" / "hsrviz" / "hsrviz-export").string());  // from the menu
    unsetenv("XDG_DATA_HOME");
    CHECK(output_folder("hsrviz-out") == (root / "home" / ".local/share" / "hsrviz" / "hsrviz-out").string());
    setenv("HSRVIZ_OUTPUT", (root / "chosen").c_str(), 1);
    CHECK(output_folder("hsrviz-export") == (root / "chosen" / "hsrviz-export").string());
    restore();
}
