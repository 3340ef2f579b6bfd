// SPDX-License-Identifier: MIT
#include "state/output_folder.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace hsr::viz {

bool make_folder(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (!ec && std::filesystem::is_directory(dir, ec)) return true;
    std::fprintf(stderr, "hsrviz: cannot make the folder %s: %s\n", dir.c_str(), ec ? ec.message().c_str() : "a file of that name is in the way");
    return false;
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
