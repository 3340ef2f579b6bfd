// SPDX-License-Identifier: MIT
// libFuzzer: any text as the command line's values (--size, --eye). Each is refused, or read as values in range
// that print back to text the parser reads the same way.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/load_scene.h"
#include "state/arguments.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hsr::viz;
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (const auto wh = parse_size(text)) {
        if (wh->first < 1 || wh->first > 16384 || wh->second < 1 || wh->second > 16384) std::abort();
        if (parse_size(std::to_string(wh->first) + "x" + std::to_string(wh->second)) != wh) std::abort();
    }
    if (const auto p = parse_point(text)) {
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite((*p)[k]) || std::abs((*p)[k]) > hsr::algo::max_world_coordinate) std::abort();
        char again[128];
        std::snprintf(again, sizeof again, "%.17g,%.17g,%.17g", p->x, p->y, p->z);
        if (parse_point(again) != p) std::abort();
    }
    return 0;
}
