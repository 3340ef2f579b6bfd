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

    std::ofstream(path) << "# hsrviz remembers the window here between runs; delete the file to start afresh.\nwidth = [1\n";
    CHECK(read_window_settings(path, warning) == WindowSettings{});
    CHECK(warning.find("window.toml:2:") != std::string::npos);
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

namespace {

std::string text_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("the settings file's neighbours are never written through, moved over or replaced (issue 53, items 3, 5, 6)",
          "[state][settings]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("hsrviz_settings_neighbours_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string path = (dir / "window.toml").string();
    const std::string ours = "# hsrviz remembers the window here between runs; delete the file to start afresh.\n";
    const WindowSettings s{.width = 1600, .height = 900};
    std::string warning;

    SECTION("a FIFO or a link at the old temporary name is not touched, and no temporary file is left") {
        REQUIRE(mkfifo((path + ".new").c_str(), 0600) == 0);  // open() of it for writing waited for a reader
        std::ofstream(dir / "lesson.toml") << "title = \"Mine\"\n";
        fs::create_symlink(dir / "lesson.toml", path + ".tmp");
        REQUIRE(write_window_settings(path, s).empty());
        CHECK(read_window_settings(path, warning) == s);
        CHECK(fs::is_fifo(path + ".new"));
        CHECK(text_of((dir / "lesson.toml").string()) == "title = \"Mine\"\n");
        CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 4);
    }
    SECTION("a symbolic link at the path itself, dangling or not, is neither read through nor replaced") {
        std::ofstream(dir / "lesson.toml") << "title = \"Mine\"\n";
        fs::create_symlink(dir / "lesson.toml", path);
        CHECK(read_window_settings(path, warning) == WindowSettings{});
        CHECK(warning.find("is a symbolic link; it is left alone") != std::string::npos);
        CHECK_FALSE(write_window_settings(path, s).empty());
        CHECK(fs::is_symlink(path));
        CHECK(text_of((dir / "lesson.toml").string()) == "title = \"Mine\"\n");
        fs::remove(path);
        fs::create_symlink(dir / "gone.toml", path);
        CHECK(read_window_settings(path, warning) == WindowSettings{});
        CHECK(warning.find("settings are not saved there") != std::string::npos);
        CHECK_FALSE(write_window_settings(path, s).empty());
        CHECK(fs::is_symlink(fs::symlink_status(path)));
        CHECK_FALSE(fs::exists(dir / "gone.toml"));
    }
    SECTION("a file that does not parse and is not ours (notes, a half-saved lesson) is left alone, its .bak too") {
        std::ofstream(path) << "these are my notes\n";
        std::ofstream(path + ".bak") << "older notes\n";
        CHECK(read_window_settings(path, warning) == WindowSettings{});
        CHECK(warning.find("window.toml:1:") != std::string::npos);
        CHECK(warning.find("left alone") != std::string::npos);
        CHECK_FALSE(write_window_settings(path, s).empty());
        CHECK(text_of(path) == "these are my notes\n");
        CHECK(text_of(path + ".bak") == "older notes\n");
    }
    SECTION("a broken settings file of ours is kept as .bak, but never over a .bak that exists") {
        std::ofstream(path) << ours << "width = [1\n";
        std::ofstream(path + ".bak") << "older\n";
        CHECK(read_window_settings(path, warning) == WindowSettings{});
        CHECK(warning.find("exists already") != std::string::npos);
        CHECK(text_of(path + ".bak") == "older\n");
        CHECK(text_of(path) == ours + "width = [1\n");
        CHECK_FALSE(write_window_settings(path, s).empty());
        fs::remove(path + ".bak");
        CHECK(read_window_settings(path, warning) == WindowSettings{});
        CHECK(warning.find("kept as") != std::string::npos);
        CHECK(text_of(path + ".bak") == ours + "width = [1\n");
        CHECK(write_window_settings(path, s).empty());
    }
    SECTION("an empty file is the defaults, and may be written") {
        std::ofstream{path};
        CHECK(read_window_settings(path, warning) == WindowSettings{});
        CHECK(warning.empty());
        CHECK(write_window_settings(path, s).empty());
        CHECK(read_window_settings(path, warning) == s);
    }
    SECTION("every bad field is named, not only the last") {
        std::string text;
        for (const char* topic : {"a", "b", "c", "d", "e", "f"}) text += std::string("[practice.") + topic + "]\nanswered = 1\nright = 5\nbest_streak = 0\n";
        std::ofstream(path) << text;
        read_window_settings(path, warning);
        for (const char* topic : {"a", "b", "c", "d", "e", "f"}) CHECK(warning.find(std::string("'practice.") + topic + "'") != std::string::npos);
    }
    SECTION("bad practice records are kept in the file when the settings are saved, and the warning says so") {
        std::ofstream(path) << "[practice.bsp]\nanswered = 4\nright = 3\nbest_streak = 2\n[practice.zbuffer]\nanswered = 1\nright = 5\n"
                               "best_streak = 0\n[practice.\"Odd Name\"]\nanswered = \"many\"\n";
        WindowSettings read = read_window_settings(path, warning);
        CHECK(warning.find("'practice.zbuffer'") != std::string::npos);
        CHECK(warning.find("'practice.Odd Name'") != std::string::npos);
        CHECK(warning.find("kept in the file as it is") != std::string::npos);
        read.width = 1000;
        REQUIRE(write_window_settings(path, read).empty());
        const std::string saved = text_of(path);
        CHECK(saved.find("[practice.zbuffer]") != std::string::npos);  // they vanished from the file (issue 53, item 11)
        CHECK(saved.find("right = 5") != std::string::npos);
        CHECK(saved.find("Odd Name") != std::string::npos);  // toml++ quotes the key as it likes
        CHECK((saved.find("answered = 'many'") != std::string::npos || saved.find("answered = \"many\"") != std::string::npos));
        CHECK(read_window_settings(path, warning).practice.at("bsp") == PracticeRecord{4, 3, 2});
        // practising a bad record's topic starts it afresh: this run's record replaces the bad one
        read.practice["zbuffer"] = {2, 1, 1};
        REQUIRE(write_window_settings(path, read).empty());
        CHECK(read_window_settings(path, warning).practice.at("zbuffer") == PracticeRecord{2, 1, 1});
        CHECK(warning.find("'practice.zbuffer'") == std::string::npos);
    }
    fs::remove_all(dir);
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
