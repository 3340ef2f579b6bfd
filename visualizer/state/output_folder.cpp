// SPDX-License-Identifier: MIT
#include "state/output_folder.h"

#include <cstdio>
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

}  // namespace hsr::viz
