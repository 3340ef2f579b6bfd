// SPDX-License-Identifier: MIT
// Work no classroom machine can do is refused before it starts, with the figures: a lesson on field:20000000 or a
// render at 16384×16384 asks for many gigabytes, and running out half-way froze the window or ended in
// "std::bad_alloc". The estimates are upper bounds measured on the machines (bytes per triangle of the ray cast's
// scene and grid, the heaviest; bytes per pixel of a frame with its depth and ids).
#pragma once

#include <cstdint>
#include <string>

namespace hsr::viz {

inline constexpr std::uint64_t bytes_per_triangle = 1200, bytes_per_pixel = 24;

// What this process may still allocate: the system's available memory (MemAvailable), lowered by the address-space
// limit (ulimit -v) and by $HSRVIZ_MEMORY_LIMIT (bytes; for tests and shared lab machines).
std::uint64_t available_memory();
// A rough upper bound of what running any machine on `triangles` triangles into `pixels` pixels needs.
std::uint64_t memory_estimate(std::uint64_t triangles, std::uint64_t pixels);
// Throws std::runtime_error("WHAT needs about 5.1 GB of memory; about 3.2 GB is available …") when the estimate is
// more than what is available.
void require_memory(std::uint64_t bytes, const std::string& what);
// "5.1 GB", "310 MB"
std::string bytes_text(std::uint64_t bytes);

}  // namespace hsr::viz
