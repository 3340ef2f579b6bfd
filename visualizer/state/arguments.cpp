// SPDX-License-Identifier: MIT
#include "state/arguments.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scene/input_file.h"
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

// 1000000 → "1000000", 0.5 → "0.5": a range said as a person writes it (not 1.797…e308)
std::string plain(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.15g", x);
    return s;
}

}  // namespace

std::string whole_number_in(const std::string& text, std::uint64_t lo, std::uint64_t hi) {
    const std::string range = "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    std::uint64_t v = 0;
    const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (!digits || error != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
        return range + ", got " + algo::printable(text, 40);
    return "";
}

std::string number_in(const std::string& text, double lo, double hi) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v >= lo && v <= hi))
        return "expected a number from " + plain(lo) + " to " + plain(hi) + ", got " + algo::printable(text, 40);
    return "";
}

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
