// SPDX-License-Identifier: MIT
#include "state/families.h"

namespace hsr::viz {

FamilySession make_session(Lesson lesson, PlayerOptions options) {
    return with_family(lesson.algorithm, [&](auto family) {
        using S = typename decltype(family)::Session;
        return FamilySession(std::make_unique<S>(std::move(lesson), options));
    });
}

}  // namespace hsr::viz
