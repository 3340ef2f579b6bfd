// SPDX-License-Identifier: MIT
#include "state/arguments.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "scene/load_scene.h"

namespace hsr::viz {
namespace {

// The parts of `text` between `separator`s (an empty part stays, to be refused).
std::vector<std::string> parts(const std::string& text, char separator) {
    std::vector<std::string> out(1);
    for (const char c : text) {
        if (c == separator) out.emplace_back();
        else out.back().push_back(c);
    }
    return out;
}

}  // namespace

std::optional<std::pair<int, int>> parse_size(const std::string& text, int largest) {
    const std::vector<std::string> wh = parts(text, 'x');
    if (wh.size() != 2) return std::nullopt;
    int v[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const std::string& s = wh[std::size_t(k)];
        const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v[k]);
        if (s.empty() || error != std::errc() || end != s.data() + s.size() || v[k] < 1 || v[k] > largest) return std::nullopt;
    }
    return std::pair{v[0], v[1]};
}

std::optional<glm::dvec3> parse_point(const std::string& text) {
    const std::vector<std::string> xyz = parts(text, ',');
    if (xyz.size() != 3) return std::nullopt;
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) {
        const std::string& s = xyz[std::size_t(k)];
        char* end = nullptr;
        p[k] = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !(std::abs(p[k]) <= algo::max_world_coordinate)) return std::nullopt;
    }
    return p;
}

}  // namespace hsr::viz
