// SPDX-License-Identifier: MIT
// libFuzzer: the settings file's path and its neighbours (issue 53, items 3, 5, 6). The first bytes choose what lies
// at window.toml (nothing, a file of the remaining bytes, the same after hsrviz's first line, an empty file, a link to
// a file, a dangling link, a FIFO, a folder), at window.toml.bak and at the names a temporary file once had (a FIFO, a
// link to someone's file). Then the settings are read and written. Nothing but window.toml and a new window.toml.bak
// may change; a link's target, a FIFO, an existing .bak never; a new .bak holds hsrviz's own broken file; no
// temporary file stays; a FIFO never blocks (libFuzzer's timeout would say so).
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <toml++/toml.h>

#include "state/window_settings.h"

namespace fs = std::filesystem;

namespace {

const std::string ours = "# hsrviz remembers the window here between runs; delete the file to start afresh.\n";

std::string text_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Every entry of the folder: "file:CONTENT", "link:TARGET", "fifo", "folder".
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const auto st = fs::symlink_status(e.path());
        const std::string name = e.path().filename().string();
        out[name] = fs::is_symlink(st)   ? "link:" + fs::read_symlink(e.path()).string()
                    : fs::is_fifo(st)    ? "fifo"
                    : fs::is_directory(st) ? "folder"
                                           : "file:" + text_of(e.path());
    }
    return out;
}

// A file hsrviz may replace: settings keys only (what its reader takes as its own).
bool settings_only(const std::string& text) {
    try {
        const toml::table t = toml::parse(text);
        for (const auto& [key, value] : t)
            if (std::string k(key.str()); k != "width" && k != "height" && k != "x" && k != "y" && k != "side" && k != "maximized" &&
                                          k != "language" && k != "type_size" && k != "practice")
                return false;
        return true;
    } catch (const toml::parse_error&) {
        return false;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hsr::viz;
    if (size < 3) return 0;
    static const fs::path dir = fs::temp_directory_path() / ("hsrviz_fuzz_settings_path_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path path = dir / "window.toml";
    const std::string rest(reinterpret_cast<const char*>(data) + 3, size - 3);
    std::ofstream(dir / "someone.toml", std::ios::binary) << "title = \"a lesson\"\n";
    switch (data[0] % 8) {
        case 0: break;
        case 1: std::ofstream(path, std::ios::binary) << rest; break;
        case 2: std::ofstream(path, std::ios::binary) << ours << rest; break;
        case 3: std::ofstream{path}; break;
        case 4: fs::create_symlink("someone.toml", path); break;
        case 5: fs::create_symlink("gone.toml", path); break;
        case 6: mkfifo(path.c_str(), 0600); break;
        case 7: fs::create_directory(path); break;
    }
    switch (data[1] % 3) {
        case 0: break;
        case 1: std::ofstream(dir / "window.toml.bak") << "an older backup\n"; break;
        case 2: fs::create_symlink("someone.toml", dir / "window.toml.bak"); break;
    }
    if (data[2] & 1) mkfifo((dir / "window.toml.new").c_str(), 0600);
    if (data[2] & 2) fs::create_symlink("someone.toml", dir / "window.toml.tmp");
    const auto before = snapshot(dir);

    std::string warning;
    const WindowSettings read = read_window_settings(path.string(), warning);
    const bool written = write_window_settings(path.string(), read).empty();

    const auto after = snapshot(dir);
    for (const auto& [name, what] : before)  // every neighbour as it was
        if (name != "window.toml" && after.count(name) && after.at(name) != what) std::abort();
    for (const auto& [name, what] : before)
        if (name != "window.toml" && !after.count(name)) std::abort();
    for (const auto& [name, what] : after)  // nothing new but the settings and a .bak of hsrviz's own broken file
        if (!before.count(name) && name != "window.toml" && !(name == "window.toml.bak" && what.rfind("file:" + ours, 0) == 0)) std::abort();
    const std::string old = before.count("window.toml") ? before.at("window.toml") : "";
    if (old.rfind("file:", 0) != 0 && !old.empty() && after.count("window.toml") && after.at("window.toml") != old) std::abort();  // link, FIFO, folder
    if (written && old.rfind("file:", 0) == 0 && old.size() > 5 && !settings_only(old.substr(5)) && !after.count("window.toml.bak"))
        std::abort();  // replaced a file that was not a settings file and was not kept aside
    if (written && text_of(path).rfind(ours, 0) != 0) std::abort();
    return 0;
}
