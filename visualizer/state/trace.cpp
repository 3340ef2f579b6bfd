// SPDX-License-Identifier: MIT
#include "state/trace.h"

#include <cstdio>

#include "state/families.h"
#include "state/session.h"

namespace hsr::viz {

void hash_line(TraceSummary& t, const std::string& line) {
    auto mix = [&](unsigned char c) {
        t.hash ^= c;
        t.hash *= 1099511628211ull;  // FNV-1a 64-bit prime
    };
    for (char c : line) mix(static_cast<unsigned char>(c));
    mix('\n');
}

std::string hex(std::uint64_t hash) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

namespace {
template <class V>
struct KindsOf;
template <class... E>
struct KindsOf<std::variant<E...>> {
    static std::vector<std::string> list() { return {std::string(E::kind)...}; }
};
}  // namespace

std::vector<std::string> event_kinds(const Lesson& lesson) {
    return with_family(lesson.algorithm, [](auto family) {
        return KindsOf<typename decltype(family)::Session::EventType>::list();
    });
}

TraceSummary played_trace(const Session& s) {
    TraceSummary t;
    for (std::size_t k = 0; k < s.cursor(); ++k, ++t.events) hash_line(t, s.event_line(k));
    return t;
}

std::string played_trace_text(const Session& s) {
    const TraceSummary played = played_trace(s);
    return hex(played.hash) + " " + std::to_string(played.events);
}

TraceSummary trace_lesson(const Lesson& lesson, std::ostream* out, const std::atomic<bool>* stop) {
    return with_family(lesson.algorithm, [&](auto family) {
        using S = typename decltype(family)::Session;
        // the machine the window plays, its view folded alongside so that sentences name things as the window does
        auto run = S::machine(lesson);
        return write_trace(
            run.machine,
            [&](const auto& e) {
                reduce(run.initial, e);
                return S::sentence_of(e, run.initial);
            },
            out, stop);
    });
}

}  // namespace hsr::viz
