#include "cli/commands.h"

#include <cstdio>
#include <fstream>

#include "state/clip_session.h"
#include "state/trace.h"

namespace hsr::viz {

int run_trace(const TraceOptions& o) {
    try {
        const Lesson lesson = load_lesson(o.input, o.algorithm);
        const auto algorithm = algo::ClipAlgorithm(lesson.algorithm.variant);
        const algo::ClipJob job = algo::clip_job(lesson.scene);
        const algo::ClipSpace space = job.space;
        auto machine = algo::clip_scene(job, algorithm);
        std::ofstream out(o.out, std::ios::binary);
        if (!out) {
            std::fprintf(stderr, "hsrviz: cannot write %s\n", o.out.c_str());
            return 1;
        }
        const TraceSummary t = write_trace(machine, space, &out);
        std::printf("%llu events, trace hash %s, written to %s\n", static_cast<unsigned long long>(t.events),
                    hex(t.hash).c_str(), o.out.c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hsrviz: %s\n", e.what());
        return 1;
    }
}

}  // namespace hsr::viz
