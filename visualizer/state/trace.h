// SPDX-License-Identifier: MIT
// Traces: a machine's events as JSON Lines, one event per line with its step, kind, fields and sentence:
//   {"step":0,"kind":"SegmentStarted","id":1,"p1":[…],"p2":[…],"text":"segment 1 from …"}
// and a hash of those bytes (64-bit FNV-1a), so that "same input, same trace" is one comparison.
#pragma once

#include <atomic>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "core/steps.h"
#include "core/work_meter.h"
#include "state/lesson.h"

namespace hsr::viz {

struct TraceSummary {
    std::uint64_t events = 0;
    std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis: the hash of an empty trace
};

std::string hex(std::uint64_t hash);

// FNV-1a over the bytes of `line` and a newline.
void hash_line(TraceSummary& t, const std::string& line);

// One JSON line (without the newline): step, kind, the event's fields, and its sentence. Made for each family's
// event variant by its <family>_trace.cpp (state/trace_json.h).
template <class Event>
std::string trace_line(std::uint64_t step, const Event& e, const std::string& sentence);

// The kinds of event the lesson's machine can tell (its event variant's alternatives).
std::vector<std::string> event_kinds(const Lesson& lesson);

// Drains the machine, writing each event as a line with the sentence `describe(event)` gives. `out` may be null
// to only count and hash. Between two events it stops when `out` fails (a full disk: the caller says so) and throws
// algo::WorkStopped when `stop` is set (Ctrl+C), so the output ends with a whole line.
template <class Event, class Result, class Describe>
TraceSummary write_trace(algo::Steps<Event, Result>& machine, Describe describe, std::ostream* out,
                         const std::atomic<bool>* stop = nullptr) {
    TraceSummary t;
    while (const Event* e = machine.next()) {
        if (stop && stop->load(std::memory_order_relaxed)) throw algo::WorkStopped();
        if (out && !*out) break;
        const std::string line = trace_line(t.events, *e, describe(*e));
        if (out) *out << line << '\n';
        hash_line(t, line);
        ++t.events;
    }
    return t;
}


class Session;
// The events a session has played so far (0 … cursor − 1), counted and hashed as their trace's lines: the same
// hash as the first `cursor` lines of trace_lesson's, so that two windows (the desktop's, the page's) that pressed
// the same keys can show that they stand at the same place of the same run.
TraceSummary played_trace(const Session& s);
// "HASH EVENTS" (16 hex digits, a count): how a screenshot prints it and the page answers it.
std::string played_trace_text(const Session& s);

// Runs the lesson's machine (whatever its family) to completion, writing its trace to `out` (may be null);
// `stop`: as write_trace's.
TraceSummary trace_lesson(const Lesson& lesson, std::ostream* out, const std::atomic<bool>* stop = nullptr);

}  // namespace hsr::viz
