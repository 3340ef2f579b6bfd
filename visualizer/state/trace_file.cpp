// SPDX-License-Identifier: MIT
#include "state/trace_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>

#include "scene/input_file.h"
#include "state/interrupt.h"
#include "state/lesson.h"
#include "state/trace.h"

namespace hsr::viz {
namespace {

// A trace cut short is no trace: the half-written file goes (a regular file only: /dev/stdout or a FIFO stays).
void remove_partial(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(path, ec))) std::filesystem::remove(path, ec);
}

}  // namespace

int run_trace(const TraceOptions& o) {
    const std::string out_name = algo::printable_name(o.out);
    bool opened = false;
    try {
        StopOnInterrupt ctrl_c;  // from the start: a Ctrl+C while the lesson loads stops at the first event
        const Lesson lesson = load_lesson(o.input, o.algorithm);
        for (const std::string& note : lesson.scene.notes) std::fprintf(stderr, "hsrviz: %s\n", algo::printable(note, 2000).c_str());
        if (ctrl_c.asked) throw algo::WorkStopped();  // before the file is made
        errno = 0;
        std::ofstream out(o.out, std::ios::binary);
        if (!out) {
            std::fprintf(stderr, "hsrviz: cannot write %s%s%s\n", out_name.c_str(), errno ? ": " : "", errno ? std::strerror(errno) : "");
            return 1;
        }
        opened = true;
        const TraceSummary t = trace_lesson(lesson, &out, &ctrl_c.asked);
        if (!out.flush()) {  // a full disk shows here (or at the event it stopped at), not at the open
            std::fprintf(stderr, "hsrviz: cannot write %s: %s; no trace written\n", out_name.c_str(), std::strerror(errno));
            out.close();
            remove_partial(o.out);
            return 1;
        }
        std::printf("%llu events, trace hash %s, written to %s\n", static_cast<unsigned long long>(t.events),
                    hex(t.hash).c_str(), out_name.c_str());
        return 0;
    } catch (const algo::WorkStopped&) {
        remove_partial(o.out);
        std::fprintf(stderr, "hsrviz: stopped (Ctrl+C); no trace written\n");
        return 130;  // the shell's code for a command ended by SIGINT
    } catch (const std::bad_alloc&) {
        if (opened) remove_partial(o.out);
        std::fprintf(stderr, "hsrviz: out of memory: the trace needs more than this machine (or its limits) allow\n");
        return 1;
    } catch (const std::exception& e) {
        if (opened) remove_partial(o.out);
        std::fprintf(stderr, "hsrviz: %s\n", algo::printable(e.what(), 2000).c_str());
        return 1;
    }
}

}  // namespace hsr::viz
