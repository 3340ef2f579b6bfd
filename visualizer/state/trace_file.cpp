// SPDX-License-Identifier: MIT
#include "state/trace_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>

#include "scene/input_file.h"
#include "state/lesson.h"
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
        if (!out.flush()) {  // a full disk shows here, not at the open
            std::fprintf(stderr, "hsrviz: cannot write %s: %s\n", o.out.c_str(), std::strerror(errno));
            return 1;
        }
        std::printf("%llu events, trace hash %s, written to %s\n", static_cast<unsigned long long>(t.events),
                    hex(t.hash).c_str(), o.out.c_str());
        return 0;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "hsrviz: out of memory: the trace needs more than this machine (or its limits) allow\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hsrviz: %s\n", algo::printable(e.what(), 2000).c_str());
        return 1;
    }
}

}  // namespace hsr::viz
