// SPDX-License-Identifier: MIT
// The window's catalogues of words: the shipped languages complete and alike, every key the window's code asks for
// present, templates filled by name, and a teacher's broken or partial file named rather than crashing the window.
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "catch.h"
#include "state/strings.h"

using namespace hsr::viz;

TEST_CASE("the shipped catalogues: English and German, the same keys, the same values in each template", "[strings]") {
    const Strings s = Strings::load(HSR_SOURCE_DIR "/assets/strings");
    INFO(s.problems().size() << " problems, the first: " << (s.problems().empty() ? "" : s.problems().front()));
    CHECK(s.problems().empty());
    const auto languages = s.languages();
    REQUIRE(languages.size() >= 2);
    CHECK(languages.front() == "en");
    CHECK(std::find(languages.begin(), languages.end(), "de") != languages.end());
}

TEST_CASE("every key the window's code asks for is in the English catalogue", "[strings]") {
    const Strings s = Strings::load(HSR_SOURCE_DIR "/assets/strings");
    const std::regex call(R"re(\btr\("([a-z_]+\.[a-z_.]+)")re");
    std::set<std::string> asked;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(HSR_SOURCE_DIR "/visualizer")) {
        if (entry.path().extension() != ".cpp" && entry.path().extension() != ".h") continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string source = text.str();
        for (auto it = std::sregex_iterator(source.begin(), source.end(), call); it != std::sregex_iterator(); ++it) asked.insert((*it)[1]);
    }
    CHECK(asked.size() >= 20);  // the migration is real: the timeline, the boxes, the practice box
    for (const std::string& key : asked) {
        INFO(key);
        CHECK(s.has(key));
    }
}

TEST_CASE("a template names its values: filled in any order, a missing one left as written", "[strings]") {
    CHECK(fill("step {step} of {steps}", {{"steps", "12"}, {"step", "3"}}) == "step 3 of 12");
    CHECK(fill("Schritt {step} von {steps}", {{"step", "3"}}) == "Schritt 3 von {steps}");
    CHECK(fill("no values", {{"x", "1"}}) == "no values");
    CHECK(fill("an open {brace", {}) == "an open {brace");
    // a plural: the form for one, else the other; its name counts once among the template's values
    CHECK(fill("{n} {n?pair|pairs} examined", {{"n", "1"}}) == "1 pair examined");
    CHECK(fill("{n} {n?pair|pairs} examined", {{"n", "0"}}) == "0 pairs examined");
    CHECK(fill("{n} {n?Paar|Paare}", {{"n", "12"}}) == "12 Paare");
    CHECK(value_names("{n} {n?pair|pairs} and {m}") == std::vector<std::string>{"m", "n"});
    CHECK(value_names("{b} and {a} and {b}") == std::vector<std::string>{"a", "b"});
}

TEST_CASE("a language's missing, extra or differently filled keys are named; its gaps speak English", "[strings]") {
    Strings s = Strings::from_texts({{"en", "[t]\nplay = \"Play\"\nstep = \"step {step} of {steps}\"\nend = \"End\"\n"},
                                     {"fr", "[t]\nplay = \"Jouer\"\nstep = \"étape {n} sur {steps}\"\nextra = \"?\"\n"}});
    const auto& p = s.problems();
    const auto said = [&](const std::string& part) {
        return std::any_of(p.begin(), p.end(), [&](const std::string& line) { return line.find(part) != std::string::npos; });
    };
    CHECK(said("fr.toml: key 't.end' is missing (English: 'End')"));
    CHECK(said("fr.toml: key 't.step' names other values"));
    CHECK(said("fr.toml: key 't.extra' is not in English's catalogue"));
    s.use("fr");
    CHECK(s.text("t.play") == "Jouer");
    CHECK(s.text("t.end") == "End");            // the gap: English
    CHECK(s.text("t.nothing") == "t.nothing");  // no such key anywhere: the key itself, never a crash
    s.use("xx");
    CHECK(s.text("t.play") == "Play");
}

TEST_CASE("a catalogue with a syntax error is left out and named with its line; the window speaks English", "[strings]") {
    Strings s = Strings::from_texts({{"en", "[t]\nplay = \"Play\"\n"}, {"de", "[t]\nplay = \"Abspielen\n"}});
    REQUIRE_FALSE(s.problems().empty());
    CHECK_THAT(s.problems().front(), Catch::Contains("de.toml:2"));
    s.use("de");
    CHECK(s.text("t.play") == "Play");
}
