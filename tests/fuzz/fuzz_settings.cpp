// SPDX-License-Identifier: MIT
// libFuzzer: any bytes as the window's settings file. Reading never throws; whatever was read, written back and
// read again gives the same settings with no warning (the round trip holds for anything the reader accepts), and a
// file that is not a settings file is never overwritten.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "state/window_settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hsr::viz;
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("hsrviz_fuzz_settings_" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::string path = (dir / "window.toml").string(), copy = (dir / "again.toml").string();
    std::filesystem::remove(path + ".bak");
    std::filesystem::remove(copy);
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    std::string warning;
    const WindowSettings read = read_window_settings(path, warning);
    if (write_window_settings(copy, read).empty()) {
        std::string again_warning;
        if (!(read_window_settings(copy, again_warning) == read) || !again_warning.empty()) std::abort();
    }
    // Writing over the fuzzed file: allowed only when it still is a settings file; otherwise it stays as it was
    if (std::filesystem::exists(path) && !write_window_settings(path, read).empty()) {
        std::ifstream in(path, std::ios::binary);
        if (std::string(std::istreambuf_iterator<char>(in), {}) != bytes) std::abort();
    }
    return 0;
}
