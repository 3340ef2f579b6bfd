// SPDX-License-Identifier: MIT
#include "core/numeric.h"

#include <cstdio>

namespace hsr::algo {

void require_finite(double value, const std::string& where) {
    if (std::isnan(value)) throw InvalidInput(where + " is NaN");
    if (std::isinf(value)) throw InvalidInput(where + " is infinite");
}

void require_finite(const glm::dvec4& p, const std::string& where) {
    static constexpr const char* axis[] = {"x", "y", "z", "w"};
    for (int i = 0; i < 4; ++i)
        if (!std::isfinite(p[i])) require_finite(p[i], where + "." + axis[i]);  // the name is made only to throw
}

void require_clippable(const glm::dvec4& p, const std::string& where) {
    require_finite(p, where);
    static constexpr const char* axis[] = {"x", "y", "z", "w"};
    for (int i = 0; i < 4; ++i)
        if (std::fabs(p[i]) > ClipTolerance::largest_coordinate) {
            char text[160];
            std::snprintf(text, sizeof text, ".%s is %.17g, beyond ±%g, where differences of boundary values would overflow",
                          axis[i], p[i], ClipTolerance::largest_coordinate);
            throw InvalidInput(where + text);
        }
}

}  // namespace hsr::algo
