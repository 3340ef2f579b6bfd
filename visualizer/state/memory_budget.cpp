// SPDX-License-Identifier: MIT
#include "state/memory_budget.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace hsr::viz {

std::uint64_t available_memory() {
    std::uint64_t available = UINT64_MAX;
    std::ifstream meminfo("/proc/meminfo");
    for (std::string key; meminfo >> key;) {
        std::uint64_t kb = 0;
        meminfo >> kb;
        meminfo.ignore(64, '\n');
        if (key == "MemAvailable:") available = kb * 1024;
    }
    if (rlimit as{}; ::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) available = std::min<std::uint64_t>(available, as.rlim_cur);
    if (const char* limit = std::getenv("HSRVIZ_MEMORY_LIMIT"); limit && *limit) {
        char* end = nullptr;
        const unsigned long long bytes = std::strtoull(limit, &end, 10);
        if (*end == '\0') available = std::min<std::uint64_t>(available, bytes);
    }
    return available;
}

std::uint64_t memory_estimate(std::uint64_t triangles, std::uint64_t pixels) {
    return (64u << 20) + triangles * bytes_per_triangle + pixels * bytes_per_pixel;  // 64 MB: the program itself
}

std::string bytes_text(std::uint64_t bytes) {
    char s[32];
    if (bytes >= (1ull << 30)) std::snprintf(s, sizeof s, "%.1f GB", double(bytes) / double(1ull << 30));
    else std::snprintf(s, sizeof s, "%.0f MB", double(bytes) / double(1ull << 20));
    return s;
}

void require_memory(std::uint64_t bytes, const std::string& what) {
    const std::uint64_t available = available_memory();
    if (bytes <= available) return;
    throw std::runtime_error(what + " needs about " + bytes_text(bytes) + " of memory, and about " + bytes_text(available) +
                             " is available; choose a smaller scene or size");
}

}  // namespace hsr::viz
