// SPDX-License-Identifier: MIT
// libFuzzer: any bytes as an OBJ mesh placed by a scene ([[meshes]] file = "m.obj"). It loads, or fails with a
// LoadError naming the scene's line and the mesh's problem; a loaded scene goes through every machine.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_machines.h"
#include "scene/load_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("hsrviz_fuzz_mesh_" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    std::ofstream(dir / "m.obj", std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    try {
        const hsr::algo::Scene s = hsr::algo::load_scene_text((dir / "s.toml").string(),
                                                              "[camera]\neye = [0, 1, 5]\n[[meshes]]\nfile = \"m.obj\"\nid = 1\n");
        if (s.polygons.size() <= 2000) hsr::fuzz::run_machines(s);  // the loader's own work is what this target tests
    } catch (const hsr::algo::LoadError&) {
    } catch (const hsr::algo::InvalidInput&) {
    }
    return 0;
}
