// SPDX-License-Identifier: MIT
// The panel column's arithmetic: boxes get what they hold when it fits and fair shares when it does not; text wraps
// at spaces only, so a number is never broken.
#include <numeric>

#include "catch.h"
#include "state/column_fit.h"
#include "state/text_wrap.h"
#include "state/toasts.h"

using namespace hsr::viz;

namespace {

std::array<BoxAsk, box_count> asks(BoxAsk lesson, BoxAsk code, BoxAsk state, BoxAsk narration, BoxAsk question = {}) {
    return {lesson, code, state, narration, question};
}
float sum(const std::array<float, box_count>& h) { return std::accumulate(h.begin(), h.end(), 0.0f); }
// one unit per character: a monospace measure
float chars(std::string_view s) { return float(s.size()); }

}  // namespace

TEST_CASE("when everything fits, each box gets what it holds and the rest goes to the state box", "[column]") {
    const auto h = ColumnFit::share(asks({60, 60}, {100, 200}, {50, 80}, {40, 90}), 700);
    CHECK(h[0] == 60);
    CHECK(h[1] == 200);
    CHECK(h[3] == 90);
    CHECK(h[2] == 700 - 60 - 200 - 90);  // a one-line box is one line; the state box takes the slack
    CHECK(h[4] == 0);
    CHECK(sum(h) == 700);
}

TEST_CASE("a family without a state box gives the slack to the narration", "[column]") {
    const auto h = ColumnFit::share(asks({60, 60}, {100, 100}, {}, {40, 90}), 500);
    CHECK(h[2] == 0);
    CHECK(h[3] == 500 - 160);
}

TEST_CASE("when it does not fit: the question, the lesson's text, then what each box must show", "[column]") {
    const auto h = ColumnFit::share(asks({200, 200}, {150, 400}, {300, 300}, {80, 200}, {120, 120}), 704);
    CHECK(h[4] == 120);              // the question in full
    CHECK(h[0] == 200);              // the lesson's text in full
    CHECK(h[3] >= 80);               // the narration's current sentence
    CHECK(h[1] >= 150);              // five lines of pseudocode
    CHECK(sum(h) == Approx(704));    // no pixel of the column wasted, none beyond it
    CHECK(h[2] > 0);
}

TEST_CASE("a question never takes more than 60 % of the column, and needs beyond the column are shared fairly", "[column]") {
    const auto h = ColumnFit::share(asks({900, 900}, {900, 900}, {900, 900}, {900, 900}, {900, 900}), 800);
    CHECK(h[4] == Approx(480));
    CHECK(h[0] == Approx(160));  // the lesson: up to half of what is left
    CHECK(h[1] == Approx(160.0f / 3));
    CHECK(h[2] == Approx(160.0f / 3));
    CHECK(h[3] == Approx(160.0f / 3));
    CHECK(sum(h) == Approx(800));
}

TEST_CASE("while a question is open, the state box's rows come before more narration and pseudocode", "[column]") {
    // lesson 01's second question at 1280×800: the outcode table's last rows fell below its box while the
    // narration kept two blank lines and the pseudocode its lines above and below
    const auto h = ColumnFit::share(asks({240, 240}, {110, 230}, {60, 150}, {60, 140}, {90, 90}), 700);
    CHECK(h[2] == 150);               // the table in full
    CHECK(h[3] >= 60);                // the narration's sentence
    CHECK(h[1] >= 110);               // the running line with its neighbours
    CHECK(sum(h) == Approx(700));
    const auto without = ColumnFit::share(asks({240, 240}, {110, 230}, {60, 150}, {60, 140}), 610);
    CHECK(without[2] < 150);          // no question: the boxes share fairly as before
}

TEST_CASE("a box whose slot holds what it asked for is drawn without a scrollbar", "[column]") {
    // a scrollbar shown for one frame narrowed the German end card's text, which then asked for a line more, and
    // the column swung between two arrangements frame after frame (the lesson box's last line cut in one of them)
    ColumnFit fit;
    fit.arrange(700, "a.toml");
    fit.asked(Box::lesson, {250, 250}), fit.asked(Box::pseudocode, {100, 100});
    fit.asked(Box::state, {150, 150}), fit.asked(Box::narration, {60, 60}), fit.asked(Box::question, {106, 106});
    fit.arrange(700, "a.toml");
    CHECK(fit.holds(Box::question));
    CHECK(fit.holds(Box::lesson));
    fit.asked(Box::lesson, {250, 250}), fit.asked(Box::pseudocode, {100, 100});
    fit.asked(Box::state, {400, 400}), fit.asked(Box::narration, {60, 60}), fit.asked(Box::question, {106, 106});
    fit.arrange(700, "a.toml");
    CHECK_FALSE(fit.holds(Box::state));  // squeezed: it scrolls, with its scrollbar showing
}

TEST_CASE("a question that opens after the column was arranged is not settled until it has its room", "[column]") {
    // its first frame has no slot (drawn out of sight to be measured); a screenshot taken then showed it hung below
    // the column over the timeline: the frame is not settled, and the next arrangement gives it its room
    ColumnFit fit;
    const auto draw_the_other_boxes = [&] {
        fit.asked(Box::lesson, {100, 100}), fit.asked(Box::pseudocode, {100, 100});
        fit.asked(Box::state, {150, 150}), fit.asked(Box::narration, {60, 60});
    };
    for (int frame = 0; frame < 2; ++frame) fit.arrange(700, "a.toml"), draw_the_other_boxes();
    fit.arrange(700, "a.toml");
    CHECK_FALSE(fit.moved());
    CHECK(fit.slot(Box::question).h == 0);
    fit.asked(Box::question, {120, 120});  // the question opened this frame
    CHECK(fit.moved());
    draw_the_other_boxes();
    fit.arrange(700, "a.toml");
    CHECK(fit.slot(Box::question).h == 120);
    CHECK(fit.slot(Box::question).y + fit.slot(Box::question).h <= 700);
}

TEST_CASE("the fitted column keeps the state and narration boxes' largest size for the lesson", "[column]") {
    ColumnFit fit;
    fit.arrange(700, "a.toml");
    fit.asked(Box::lesson, {50, 50}), fit.asked(Box::pseudocode, {100, 100});
    fit.asked(Box::state, {200, 200}), fit.asked(Box::narration, {80, 80});
    fit.arrange(700, "a.toml");
    CHECK(fit.slot(Box::lesson).h == 50);
    CHECK(fit.slot(Box::pseudocode).y == 50);
    fit.asked(Box::lesson, {30, 30}), fit.asked(Box::pseudocode, {100, 100});
    fit.asked(Box::state, {120, 120}), fit.asked(Box::narration, {60, 60});  // smaller this step
    fit.arrange(700, "a.toml");
    CHECK(fit.slot(Box::lesson).h == 30);          // the lesson box follows its text
    CHECK(fit.slot(Box::narration).h == 80);       // the narration keeps its height: no jumping
    CHECK(fit.slot(Box::question).h == 0);         // no question drawn, no room kept
    fit.asked(Box::lesson, {30, 30}), fit.asked(Box::pseudocode, {100, 100});
    fit.asked(Box::narration, {60, 60});           // no state box drawn this frame
    fit.arrange(700, "a.toml");
    CHECK(fit.slot(Box::state).h == 0);
    fit.arrange(700, "b.toml");                    // another lesson: the default shares again
    CHECK(fit.slot(Box::lesson).h == Approx(700 * 150.0f / 704));
}

TEST_CASE("text wraps at spaces only: a number is never broken", "[column][wrap]") {
    const auto lines = wrap_at_spaces("the segment meets x ≤ w at t = 0.481125: i = (-1.73205, 0.416667, 4.14286, 5)", 24, chars);
    for (const std::string& line : lines) {
        INFO(line);
        CHECK(chars(line) <= 24);
        CHECK(line.front() != ' ');
    }
    std::string joined;
    for (const std::string& line : lines) joined += (joined.empty() ? "" : " ") + line;
    CHECK(joined == "the segment meets x ≤ w at t = 0.481125: i = (-1.73205, 0.416667, 4.14286, 5)");
    for (const char* number : {"0.481125:", "(-1.73205,", "0.416667,", "4.14286,"}) {
        bool whole = false;
        for (const std::string& line : lines) whole = whole || line.find(number) != std::string::npos;
        CHECK(whole);
    }
}

TEST_CASE("a word wider than a line is broken only as a last resort, and counted", "[column][wrap]") {
    int forced = 0;
    const auto lines = wrap_at_spaces("a 0123456789012345 b", 8, chars, &forced);
    CHECK(forced == 1);
    CHECK(lines == std::vector<std::string>{"a", "01234567", "89012345", "b"});
    forced = 0;
    CHECK(wrap_at_spaces("line one\nline two", 100, chars, &forced) == std::vector<std::string>{"line one", "line two"});
    CHECK(forced == 0);
    CHECK(wrap_at_spaces("", 10, chars) == std::vector<std::string>{""});
}

TEST_CASE("lesson text is reflowed: a single line break is a space, an empty line a paragraph", "[column][wrap]") {
    CHECK(reflow("\nEach endpoint gets a\n6-bit outcode.\n\nIn clip space\nthe planes.\n") ==
          "Each endpoint gets a 6-bit outcode.\nIn clip space the planes.");
}

TEST_CASE("the window's notes show for a few seconds, the newest three, a repeat only once", "[toasts]") {
    Toasts t;
    CHECK(t.showing(0).empty());
    CHECK(t.until() == 0);
    t.say("exported a.png", 10);
    t.say("saved b.toml", 11);
    REQUIRE(t.showing(11).size() == 2);
    CHECK(t.showing(11)[0].text == "exported a.png");
    CHECK(t.showing(12)[0].faded == Approx(2 / Toasts::seconds));
    CHECK(t.until() == 11 + Toasts::seconds);
    CHECK(t.showing(10 + Toasts::seconds).size() == 1);  // the first has gone, the second not yet
    t.say("saved b.toml", 12);                            // said again: shown once, from now
    t.say("c", 12), t.say("d", 12);
    const auto now = t.showing(12);
    REQUIRE(now.size() == Toasts::most);
    CHECK(now.back().text == "d");
    CHECK(t.showing(20).empty());
}

TEST_CASE("at the lesson's end what it built comes first: the state box in full, before the other boxes' needs", "[column]") {
    // a PVS matrix of 190 px, with a question, the lesson's text, the pseudocode and the narration that do not fit
    const auto during = ColumnFit::share(asks({160, 160}, {150, 300}, {190, 190}, {80, 200}, {200, 200}), 700);
    CHECK(during[2] < 190);  // during the lesson the needs are shared: the matrix scrolls
    const auto end = ColumnFit::share(asks({160, 160}, {150, 300}, {190, 190}, {80, 200}, {200, 200}), 700, true);
    CHECK(end[4] == 200);
    CHECK(end[0] == 160);
    CHECK(end[2] == 190);  // the whole matrix
    CHECK(end[3] >= 80);   // then the narration's last sentence
    CHECK(end[1] >= 0);    // the pseudocode gets what is left
    CHECK(sum(end) == Approx(700));
    // a result taller than the column gets what the question, the lesson and the narration's need leave
    const auto huge = ColumnFit::share(asks({160, 160}, {150, 300}, {2000, 2000}, {80, 200}, {200, 200}), 700, true);
    CHECK(huge[2] == Approx(700 - 200 - 160 - 80));
    CHECK(huge[1] == 0);  // the pseudocode is not drawn (its panel draws no box in a slot without one row)
    // but at least 70 % of it, when the narration's need is long
    const auto talk = ColumnFit::share(asks({160, 160}, {150, 300}, {2000, 2000}, {200, 400}, {200, 200}), 700, true);
    CHECK(talk[2] == Approx(0.7f * (700 - 200 - 160)));
    CHECK(huge[3] >= 80);
}

TEST_CASE("at the lesson's end the pseudocode gives way: its box keeps what it asked for while it is not drawn", "[column]") {
    // lesson 31's end at 1280x800: a long chapter text, tall tables, a narration of three lines
    const auto end = ColumnFit::share(asks({251, 251}, {132, 284}, {429, 429}, {121, 184}, {106, 106}), 704, true);
    CHECK(end[2] == Approx(0.7f * (704 - 106 - 251)));  // 70 % of what the question and the lesson leave
    CHECK(end[3] == Approx(0.3f * (704 - 106 - 251)));  // the rest to the narration, none to the pseudocode
    CHECK(sum(end) == Approx(704));
    // a box not drawn at the end (ColumnFit::keep) has its ask back when the class steps back into the lesson
    ColumnFit fit;
    fit.arrange(700, "a.toml");
    for (Box b : {Box::lesson, Box::pseudocode, Box::state, Box::narration}) fit.asked(b, {100, 150});
    fit.arrange(700, "a.toml", true);
    fit.keep(Box::pseudocode);
    for (Box b : {Box::lesson, Box::state, Box::narration}) fit.asked(b, {100, 150});
    fit.arrange(700, "a.toml");
    CHECK(fit.slot(Box::pseudocode).h >= 150);
}
