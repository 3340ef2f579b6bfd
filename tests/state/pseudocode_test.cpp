// SPDX-License-Identifier: MIT
// Pseudocode tables: an event lights the first line that names it (by kind, and by its fields where a line asks),
// and every event of every shipped lesson, played with every algorithm of its family, lights a line of the
// pseudocode that is shown when it happens.
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "catch.h"
#include "state/families.h"
#include "state/pseudocode.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("a pseudocode table finds an event's line and stride by its kind and fields", "[state][pseudocode]") {
    const Pseudocode<ZMergeEvent> table = {
        {"for each column x:", {}},
        {"  merge the column's first pixel", {step<PixelMerged>([](const PixelMerged& e) { return e.y == 0; })}},
        {"  merge the others", {micro<PixelMerged>()}},
        {"done", {step<MergeFinished>()}},
    };
    REQUIRE(table.text().size() == 4);
    CHECK(table.text()[2] == "  merge the others");
    const ZMergeEvent top = PixelMerged{.x = 3, .y = 0}, below = PixelMerged{.x = 3, .y = 5}, end = MergeFinished{};
    CHECK(table.line_of(top) == 1);
    CHECK(table.is_major(top) == std::optional(true));
    CHECK(table.line_of(below) == 2);
    CHECK(table.is_major(below) == std::optional(false));
    CHECK(table.line_of(end) == 3);
    const Pseudocode<ZMergeEvent> without_end = {{"merge", {micro<PixelMerged>()}}};
    CHECK(without_end.line_of(end) == -1);
    CHECK_FALSE(without_end.is_major(end).has_value());
    CHECK(without_end.kinds() == std::vector<std::string_view>{"PixelMerged"});
}

TEST_CASE("every event of every lesson lights a line of the pseudocode shown for it", "[state][pseudocode]") {
    int runs = 0;
    std::size_t total = 0;
    for (const auto& entry : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/lessons")) {
        if (entry.path().extension() != ".toml") continue;
        const Lesson lesson = load_lesson(entry.path().string());
        for (const AlgorithmInfo& a : algorithms()) {
            if (a.machine.index() != lesson.algorithm.machine.index()) continue;  // the lesson's family only
            INFO(entry.path().filename().string() << " with " << a.id);
            const FamilySession session = make_session(load_lesson(entry.path().string(), std::string(a.id)));
            session->seek(0);
            std::set<std::string> unlit;  // the kinds of events that light no line of the table shown
            std::size_t events = 0;
            while (!session->at_end() && events < 20'000) {
                session->micro_step();
                if (session->cursor() == events) break;  // no event at all (Sutherland–Hodgman on segments only)
                ++events;
                const int line = session->current_line();
                if (line < 0 || std::size_t(line) >= session->pseudocode().size())
                    unlit.insert(nlohmann::json::parse(session->event_line(session->cursor() - 1))["kind"].get<std::string>());
            }
            total += events;
            for (const std::string& k : unlit) UNSCOPED_INFO("an event that lights no line: " << k);
            CHECK(unlit.empty());
            ++runs;
        }
    }
    CHECK(runs >= 27);
    CHECK(total > 10'000);
}
