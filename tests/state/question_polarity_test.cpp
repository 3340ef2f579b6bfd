// SPDX-License-Identifier: MIT
// A yes/no question is graded on a true/false field of the event that decides it, and "true" must mean yes to the
// question as it is asked. Lesson 15 once asked "Do their projections overlap?" and graded it on the test
// "5. projections apart": a student who answered right was told wrong. Each field has the words that say what its
// "true" means; the English question must ask in those words. A new yes/no question on a field not listed here fails
// until someone has read it against the field and added the field's words.
#include "catch.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "registry.h"
#include "state/lesson.h"

namespace {

// field → the words (any one of them) that an English question graded on it uses for what "true" means
const std::map<std::string, std::vector<std::string>> true_means = {
    {"passes", {"pass the test", "pass the depth test"}},                 // PixelTested: nearer than what is stored
    {"entering", {"come in (true)"}},                                     // EdgeCrossed: the polygon comes in
    {"from_a", {"A's colour win (true)"}},                                // PixelMerged: part A's colour wins
    {"found", {"sightline pass", "is there a sightline", "can a see"}},   // SightlineTested: a sightline exists
    {"naive_associative", {"is the naive blend associative"}},            // AssociativityChecked
    {"hides", {"hide", "hidden"}},                                        // EdgeTested / PrimitivesCompared: hidden
    {"same_before", {"on one projection ray"}},                           // PairCompared: x/z and y/z equal
    {"same_after", {"on one projection ray"}},                            // PairCompared: x′ and y′ equal
};

// TestTried's field `passed` is true when the test named in the question's match holds: the question names it
std::vector<std::string> test_words(const std::string& test) {
    if (test.find("apart") != std::string::npos) return {"apart"};
    if (test.find("behind") != std::string::npos) return {"behind"};
    if (test.find("in front") != std::string::npos) return {"in front"};
    return {};
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

}  // namespace

TEST_CASE("every yes/no question asks in the words of what its field's true means", "[lesson][questions]") {
    std::size_t checked = 0;
    for (const std::string& path : hsr::viz::shipped_lessons()) {
        const hsr::viz::Lesson l = hsr::viz::load_lesson(path);
        for (const auto& chapter : l.chapters) {
            if (!chapter.question) continue;
            const auto& q = *chapter.question;
            std::vector<std::string> choices = q.choices;
            std::sort(choices.begin(), choices.end());
            if (choices != std::vector<std::string>{"false", "true"}) continue;
            INFO(path << ": \"" << chapter.title << "\", graded on " << q.answer_event.kind << "." << q.field);
            const auto ask = q.ask.find("en");
            REQUIRE(ask != q.ask.end());
            std::vector<std::string> words;
            if (q.field == "passed") {
                for (const auto& [key, value] : q.answer_event.match)
                    if (key == "test") words = test_words(value);
            } else if (const auto it = true_means.find(q.field); it != true_means.end()) {
                words = it->second;
            }
            REQUIRE_FALSE(words.empty());  // a field no one has read a question against yet
            const std::string asked = lower(ask->second);
            CHECK(std::any_of(words.begin(), words.end(), [&](const std::string& w) { return asked.find(lower(w)) != std::string::npos; }));
            ++checked;
        }
    }
    CHECK(checked >= 15);  // the shipped course has 18 such questions
}

TEST_CASE("the polarity check catches lesson 15's old wording", "[lesson][questions]") {
    // the question as it was: it asked about overlap and was graded on "apart"
    const std::string old_ask = lower("Do their projections overlap? (test 5)");
    const std::vector<std::string> words = test_words("5. projections apart");
    CHECK_FALSE(std::any_of(words.begin(), words.end(), [&](const std::string& w) { return old_ask.find(w) != std::string::npos; }));
}
