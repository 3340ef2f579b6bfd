// SPDX-License-Identifier: MIT
// The window's catalogues of words: the shipped languages complete and alike, every key the window's code asks for
// present, templates filled by name, and a teacher's broken or partial file named rather than crashing the window.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "catch.h"
#include "sayings.h"
#include "state/course.h"
#include "state/families.h"
#include "state/practice/practice.h"
#include "state/strings.h"
#include "zbuffer/depth_format.h"

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
    // every "section.key" literal in a tr( call, also the two sides of a choice: tr(right ? "a.yes" : "a.no"); and
    // every literal naming one of the catalogue's sections anywhere (a table of keys: {"Space", "keys.play"})
    const std::regex call(R"re(\btr\(([^;]*))re"), key_literal(R"re("([a-z_]+\.[a-z_.]+)")re");
    std::set<std::string> sections;
    for (const std::string& key : s.keys("en")) sections.insert(key.substr(0, key.find('.')));
    std::set<std::string> exercise_keys;
    for (const hsr::algo::Saying& saying : practice::practice_sayings()) exercise_keys.insert(std::string(saying.key));
    std::set<std::string> asked;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(HSR_SOURCE_DIR "/visualizer")) {
        if (entry.path().extension() != ".cpp" && entry.path().extension() != ".h") continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string source = text.str();
        for (auto it = std::sregex_iterator(source.begin(), source.end(), call); it != std::sregex_iterator(); ++it) {
            const std::string args = (*it)[1];
            for (auto k = std::sregex_iterator(args.begin(), args.end(), key_literal); k != std::sregex_iterator(); ++k)
                asked.insert((*k)[1]);
        }
        for (auto k = std::sregex_iterator(source.begin(), source.end(), key_literal); k != std::sregex_iterator(); ++k) {
            const std::string key = (*k)[1];
            // a practice question's template names its key under [exercise] (the test below holds those)
            if (sections.contains(key.substr(0, key.find('.'))) && !exercise_keys.contains(key)) asked.insert(key);
        }
    }
    CHECK(asked.size() >= 20);  // the migration is real: the timeline, the boxes, the practice box
    for (const std::string& key : asked) {
        INFO(key);
        CHECK(s.has(key));
    }
}

TEST_CASE("the names the code writes in English (topics, practice topics) are in the catalogue's [names]", "[strings]") {
    Strings s = Strings::load(HSR_SOURCE_DIR "/assets/strings");
    std::set<std::string> names{"Lessons that cannot be loaded"};
    for (const CourseLesson& l : load_course()) names.insert(l.topic);
    for (const practice::Topic& t : practice::topics()) names.insert(std::string(t.title));
    for (const auto f : {hsr::algo::DepthFormat::int16, hsr::algo::DepthFormat::int24, hsr::algo::DepthFormat::int32, hsr::algo::DepthFormat::float32,
                         hsr::algo::DepthFormat::float32_reversed, hsr::algo::DepthFormat::linear24})
        names.insert(std::string(hsr::algo::to_string(f)));
    CHECK(names.size() >= 20);
    s.use("de");
    std::size_t translated = 0;
    for (const std::string& name : names) {
        INFO(name);
        CHECK(s.has("names." + name));
        translated += s.name(name) != name;  // German keeps a few loan words: "Clipping", "Culling"
    }
    CHECK(translated + 2 >= names.size());
    s.use("en");
    CHECK(s.name("Depth sort") == "Depth sort");
    CHECK(s.name("no such name") == "no such name");
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

TEST_CASE("a language's missing, extra or differently filled keys are named, its gaps speak English", "[strings]") {
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

TEST_CASE("a catalogue with a syntax error is left out and named with its line, the window speaks English", "[strings]") {
    Strings s = Strings::from_texts({{"en", "[t]\nplay = \"Play\"\n"}, {"de", "[t]\nplay = \"Abspielen\n"}});
    REQUIRE_FALSE(s.problems().empty());
    CHECK_THAT(s.problems().front(), Catch::Contains("de.toml:2"));
    s.use("de");
    CHECK(s.text("t.play") == "Play");
}

TEST_CASE("the catalogue's English copy of the machines' sentences is the machines' own, key for key", "[strings]") {
    const Strings s = Strings::load(HSR_SOURCE_DIR "/assets/strings");
    std::set<std::string> said;
    for (const auto family : hsr::algo::machine_sayings())
        for (const hsr::algo::Saying& saying : family) {
            const std::string key = "machine." + std::string(saying.key);
            INFO(key);
            CHECK(said.insert(key).second);  // no key twice
            CHECK(s.english(key) == saying.english);
        }
    CHECK(said.size() >= 20);
    for (const std::string& key : s.keys("en"))
        if (key.rfind("machine.", 0) == 0) {
            INFO(key << " is in en.toml but no machine says it");
            CHECK(said.contains(key));
        }
}

TEST_CASE("the catalogue's English copy of the practice questions is the code's own, key for key", "[strings]") {
    const Strings s = Strings::load(HSR_SOURCE_DIR "/assets/strings");
    std::set<std::string> said;
    for (const hsr::algo::Saying& saying : practice::practice_sayings()) {
        const std::string key = "exercise." + std::string(saying.key);
        INFO(key);
        CHECK(said.insert(key).second);  // no key twice
        CHECK(s.english(key) == saying.english);
    }
    CHECK(said.size() >= 40);
    for (const std::string& key : s.keys("en"))
        if (key.rfind("exercise.", 0) == 0) {
            INFO(key << " is in en.toml but no practice question says it");
            CHECK(said.contains(key));
        }
}

TEST_CASE("practice asks in the language the window speaks, its answers and JSON stay English", "[strings]") {
    Strings s = Strings::load(HSR_SOURCE_DIR "/assets/strings");
    const std::regex unfilled(R"(\{[a-z_0-9]+[}?])");
    const auto in = [&](const practice::Wording& w) { return practice::said(w, [&](const hsr::algo::Saying& t) { return s.pattern("exercise", t); }); };
    for (const practice::Topic& topic : practice::topics())
        for (const practice::Level level : {practice::Level::easy, practice::Level::medium, practice::Level::hard})
            for (std::uint64_t i = 0; i < 12; ++i) {
                const practice::Exercise e = practice::exercise(topic, 7, i, level);
                INFO(topic.id << " exercise " << i << ": " << e.question);
                s.use("en");
                CHECK(in(e.asked) == e.question);  // English: what `hsrviz practice` prints, from the same template
                s.use("de");
                const std::string german = in(e.asked);
                CHECK(german != e.question);
                CHECK_FALSE(std::regex_search(german, unfilled));
                CHECK_FALSE(std::regex_search(e.question, unfilled));
                REQUIRE(e.offered.size() == e.choices.size());
                for (std::size_t k = 0; k < e.choices.size(); ++k) {
                    const practice::Wording* w = e.choice(e.choices[k]);
                    REQUIRE(w == &e.offered[k]);  // a reply given finds the words it was shown in
                    // in other words, unless the same in every language (an outcode's bits, a room's letter)
                    if (w->saying) CHECK(in(*w) != e.choices[k]);
                    CHECK_FALSE(std::regex_search(in(*w), unfilled));
                }
                if (!e.choices.empty()) CHECK(e.choice(e.answer) != nullptr);
            }
}

TEST_CASE("the machines narrate in the language the window speaks, their traces stay English", "[strings]") {
    Strings& strings = window_strings();
    const std::string before = strings.language();
    const std::regex unfilled(R"(\{[a-z_]+[}?])");
    // every machine says its events as templates (algorithms/sayings.cpp): every lesson narrates in German
    std::vector<std::filesystem::path> lessons;
    for (const auto& entry : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/lessons"))
        if (entry.path().extension() == ".toml") lessons.push_back(entry.path());
    std::sort(lessons.begin(), lessons.end());
    CHECK(lessons.size() >= 29);
    for (const std::filesystem::path& lesson : lessons) {
        auto session = make_session(load_lesson(lesson.string()));
        // a lesson narrated in German has its titles in German too, its own and each chapter's
        const Lesson& l = session->lesson();
        if (std::find(l.languages.begin(), l.languages.end(), "de") != l.languages.end()) {
            INFO(lesson.filename());
            CHECK(l.titles.contains("de"));
            for (const Chapter& c : l.chapters) CHECK((c.titles.contains("de") && c.narration.contains("de")));
        }
        session->prefetch(prefetch_events);
        REQUIRE(session->complete());
        std::size_t translated = 0;
        for (std::size_t k = 0; k < session->known(); ++k) {
            strings.use("de");
            const std::string german = session->spoken(k), english_still = session->sentence(k);
            strings.use("en");
            INFO(lesson.filename() << " step " << k << ": " << english_still);
            CHECK(session->spoken(k) == english_still);  // English: the machine's own words, as in the traces
            translated += german != english_still;  // a few are formulae alike in both ("t_enter 0 → 0.25")
            // every value named by the template was given (a set of cells, "{A, B}", is no unfilled name)
            CHECK_FALSE(std::regex_search(german, unfilled));
            CHECK_FALSE(std::regex_search(english_still, unfilled));
        }
        INFO(lesson.filename() << ": " << translated << " of " << session->known() << " sentences differ in German");
        CHECK(translated * 10 >= session->known() * 8);
    }
    // a lesson's choices that are a machine's words are shown in the student's language (the answer stays English)
    strings.use("de");
    CHECK(strings.word("entering") == "eintretend");
    CHECK(strings.word("rejected") == "verworfen");
    CHECK(strings.word("0.5") == "0,5");  // a number with the language's decimal separator
    CHECK(strings.word("#3") == "#3");
    CHECK(strings.word("true") == "wahr");  // the catalogue's own [words]
    strings.use("en");
    CHECK(strings.word("entering") == "entering");
    strings.use("de");
    {
        auto session = make_session(load_lesson(HSR_SOURCE_DIR "/lessons/13_depth_sort_cycle.toml"));
        session->prefetch(prefetch_events);
        bool cycle = false, test = false;
        for (std::size_t k = 0; k < session->known(); ++k) {
            const std::string g = session->spoken(k);
            cycle |= g.find("ein Zyklus. Stattdessen teilen.") != std::string::npos;
            test |= g.find("3. R ganz hinter der Ebene von Q: nein (2 Ecken auf der fernen Seite") != std::string::npos;
        }
        CHECK(cycle);
        CHECK(test);
    }
    strings.use(before);
}

TEST_CASE("numbers are written with the language's decimal separator, and nothing else is", "[strings]") {
    const Strings strings = Strings::from_texts({{"en", "language = \"English\"\ndecimal_separator = \".\"\n[a]\nb = \"{x} px\"\n"},
                                                 {"de", "language = \"Deutsch\"\ndecimal_separator = \",\"\n[a]\nb = \"{x} Pixel\"\n"}});
    CHECK(strings.problems().empty());
    for (const auto& [written, german] : std::vector<std::pair<std::string, std::string>>{
             {"11.1", "11,1"}, {"-0.25", "-0,25"}, {"1.5e-3", "1,5e-3"}, {"2", "2"}, {"0.9.1", "0.9.1"},
             {"(1.5, 2)", "(1,5; 2)"}, {"[-0.866025, 0)", "[-0,866025; 0)"}, {"(1.07225, -3.8781, -4.22186, -1.72619)", "(1,07225; -3,8781; -4,22186; -1,72619)"},
             {"(a, 2)", "(a, 2)"}, {"(1.5)", "(1.5)"}, {"(1.5,2)", "(1.5,2)"}, {"x.5", "x.5"}, {"1.", "1."}, {".5", ".5"}, {"scene.toml", "scene.toml"}}) {
        INFO(written);
        CHECK(strings.number("de", written) == german);
        CHECK(strings.number("en", written) == written);
        CHECK(strings.text_in("de", "a.b", {{"x", written}}) == german + " Pixel");
    }
    // the shipped German catalogue writes a decimal comma, the English one a point
    CHECK(window_strings().number("de", "4.7") == "4,7");
    CHECK(window_strings().number("en", "4.7") == "4.7");
}

TEST_CASE("every question's choice that has words is offered in German (a number, an id or a name stays as it is)", "[strings]") {
    Strings& strings = window_strings();
    const std::string before = strings.language();
    strings.use("de");
    // words alike in both languages, or names the lessons use as such
    const std::set<std::string> alike = {"Cohen–Sutherland", "Liang–Barsky"};
    const std::regex notation(R"(^[xyz] (min|max)$|^(in|out)→(in|out)$)");  // the notes' plane names and edge cases
    const std::regex no_words(R"(^[#P]?[-0-9.,/ ()]*$|^[a-z]?[0-9]+$|^[A-Z][0-9]*$)");  // "0", "#3", "P2", "1/4", "B1"
    for (const auto& entry : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/lessons")) {
        if (entry.path().extension() != ".toml") continue;
        const Lesson lesson = load_lesson(entry.path().string());
        for (const auto& chapter : lesson.chapters) {
            if (!chapter.question) continue;
            for (const std::string& choice : chapter.question->choices) {
                if (std::regex_match(choice, no_words) || std::regex_match(choice, notation) || alike.contains(choice)) continue;
                INFO(entry.path().filename().string() << ": \"" << choice << "\"");
                CHECK(strings.word(choice) != choice);
            }
        }
    }
    strings.use(before);
}
