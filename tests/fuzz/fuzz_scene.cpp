// SPDX-License-Identifier: MIT
// libFuzzer: any text as a scene file. It loads, or fails with a LoadError naming file and line; a loaded scene
// goes through every machine (run_machines.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "run_machines.h"
#include "scene/load_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const hsr::algo::Scene s = hsr::algo::load_scene_text("fuzz.toml", text);
        hsr::fuzz::run_machines(s);
    } catch (const hsr::algo::LoadError&) {
    } catch (const hsr::algo::InvalidInput&) {
    }
    return 0;
}
