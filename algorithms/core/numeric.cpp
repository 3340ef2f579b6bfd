#include "core/numeric.h"

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

}  // namespace hsr::algo
