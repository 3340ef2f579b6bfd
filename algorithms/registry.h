// Every algorithm the tool can step through: one line each in registry.cpp.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace hsr::algo {

enum class Family : unsigned char { clipping, bsp, backface, zbuffer, raycast, scanline, zmerge, depth_sort, portals, culling };

struct AlgorithmInfo {
    std::string_view id;          // as lessons and the command line name it
    std::string_view title;
    int difficulty;               // 1 (first week) … 5
    Family family;
    int variant;                  // the family's own enum value (ClipAlgorithm, BspLesson, BackfaceTest, Acceleration)
};

std::span<const AlgorithmInfo> algorithms();
std::optional<AlgorithmInfo> find_algorithm(std::string_view id);

}  // namespace hsr::algo
