#include "cli/commands.h"

#include <cstdio>
#include <fstream>

#include "state/trace.h"

namespace hsr::viz {

int run_trace(const TraceOptions& o) {
    try {
        const Lesson lesson = load_lesson(o.input, o.algorithm);
        std::ofstream out(o.out, std::ios::binary);
        if (!out) {
            std::fprintf(stderr, "hsrviz: cannot write %s\n", o.out.c_str());
            return 1;
        }
        const TraceSummary t = trace_lesson(lesson, &out);
        std::printf("%llu events, trace hash %s, written to %s\n", static_cast<unsigned long long>(t.events),
                    hex(t.hash).c_str(), o.out.c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hsrviz: %s\n", e.what());
        return 1;
    }
}

}  // namespace hsr::viz
