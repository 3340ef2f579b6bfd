// SPDX-License-Identifier: MIT
#include "state/output_folder.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "scene/input_file.h"

namespace hsr::viz {

bool make_folder(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (!ec && std::filesystem::is_directory(dir, ec)) return true;
    std::fprintf(stderr, "hsrviz: cannot make the folder %s: %s\n", algo::printable_name(dir).c_str(), ec ? ec.message().c_str() : "a file of that name is in the way");
    return false;
}

std::string write_whole_file(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) return "cannot write " + path + ": it is a folder";
    errno = 0;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    if (!f) return "cannot write " + path + (errno ? std::string(": ") + std::strerror(errno) : "");
    f << text << std::flush;  // a full disk shows at the flush
    if (f) return "";
    const std::string why = errno ? std::string(": ") + std::strerror(errno) : "";
    f.close();
    if (fs::is_regular_file(path, ec)) fs::remove(path, ec);  // no half file
    return "cannot write " + path + why;
}

std::string why_not_writable(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path p(path);
    if (fs::is_directory(p, ec)) return path + " is a folder";
    if (fs::exists(p, ec)) return access(p.c_str(), W_OK) == 0 ? "" : path + ": " + std::strerror(errno);
    const fs::path folder = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    if (access(folder.c_str(), W_OK | X_OK) != 0) return "cannot make files in " + folder.string() + ": " + std::strerror(errno);
    return "";
}

std::string output_folder(const std::string& name) {
    namespace fs = std::filesystem;
    const auto env = [](const char* variable) {
        const char* value = std::getenv(variable);
        return value && *value ? std::string(value) : std::string();
    };
    if (const std::string chosen = env("HSRVIZ_OUTPUT"); !chosen.empty()) return (fs::path(chosen) / name).string();
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    const std::string home = env("HOME");
    const bool at_home = !home.empty() && fs::equivalent(here, home, ec);
    if (!here.empty() && !at_home && access(here.c_str(), W_OK) == 0) return name;
    const std::string data = env("XDG_DATA_HOME");
    const fs::path base = !data.empty() ? fs::path(data) : !home.empty() ? fs::path(home) / ".local/share" : fs::temp_directory_path(ec);
    return (base / "hsrviz" / name).string();
}

}  // namespace hsr::viz
