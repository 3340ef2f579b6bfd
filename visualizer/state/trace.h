// Traces: a machine's events as JSON Lines, one event per line with its step, kind, fields and sentence:
//   {"step":0,"kind":"SegmentStarted","id":1,"p1":[…],"p2":[…],"text":"segment 1 from …"}
// and a hash of those bytes (64-bit FNV-1a), so that "same input, same trace" is one comparison.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "clipping/clip_events.h"
#include "core/steps.h"

namespace hsr::viz {

struct TraceSummary {
    std::uint64_t events = 0;
    std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis: the hash of an empty trace
};

// One JSON line (without the newline).
std::string trace_line(std::uint64_t step, const algo::ClipEvent& e, algo::ClipSpace s);

// Drains the machine, writing each event as a line. `out` may be null to only count and hash.
template <class Result>
TraceSummary write_trace(algo::Steps<algo::ClipEvent, Result>& machine, algo::ClipSpace s, std::ostream* out);

std::string hex(std::uint64_t hash);

// FNV-1a over the bytes of `line` and a newline.
void hash_line(TraceSummary& t, const std::string& line);

template <class Result>
TraceSummary write_trace(algo::Steps<algo::ClipEvent, Result>& machine, algo::ClipSpace s, std::ostream* out) {
    TraceSummary t;
    while (const algo::ClipEvent* e = machine.next()) {
        const std::string line = trace_line(t.events, *e, s);
        if (out) *out << line << '\n';
        hash_line(t, line);
        ++t.events;
    }
    return t;
}

}  // namespace hsr::viz
