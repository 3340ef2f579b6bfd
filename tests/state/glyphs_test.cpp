// SPDX-License-Identifier: MIT
// The window's font ranges and the check that warns about characters outside them.
#include "catch.h"

#include <filesystem>
#include <fstream>

#include "state/glyphs.h"
#include "state/lesson.h"
#include "state/lesson_check.h"

using hsr::viz::glyph_name;
using hsr::viz::glyphs_missing;

TEST_CASE("the font covers Latin, Latin Extended, Greek, Cyrillic and the maths a lesson writes", "[glyphs]") {
    CHECK(glyphs_missing("Őrült Straße ł ç ε π Δ Отсечение → ≤ ≥ − · … x² v₁ ■").empty());
    CHECK(glyphs_missing("line one\n\tline two").empty());
    // CJK, a check mark, an emoji, a combining accent (ImGui draws no combining marks)
    const auto missing = glyphs_missing("中文 ✓ 😀 v̂ 中");
    REQUIRE(missing.size() == 5);  // each once, in order
    CHECK(missing[0] == U'中');
    CHECK(missing[1] == U'文');
    CHECK(missing[2] == U'✓');
    CHECK(missing[3] == U'😀');
    CHECK(missing[4] == char32_t(0x0302));
    CHECK(glyph_name(U'中') == "U+4E2D 中");
    CHECK(glyph_name(U'😀') == "U+1F600 😀");
    // malformed UTF-8 does not read past the text, and counts as the replacement character (in the font)
    CHECK(glyphs_missing(std::string("ab\xE4", 3)).empty());
    CHECK(glyphs_missing(std::string("\xF0\x9F", 2)).empty());
}

TEST_CASE("hsrviz check warns about characters the font lacks, naming the field, and still passes the lesson", "[glyphs][lesson]") {
    // in the temporary folder, not wherever the test runs (a run from the source root once committed it)
    const std::string path = (std::filesystem::temp_directory_path() / "hsrviz_glyph_lesson.toml").string();
    std::ofstream(path) << "title = \"Clipping 中\"\nalgorithm = \"cohen_sutherland\"\nscene = \"" HSR_SOURCE_DIR
                           "/assets/scenes/cs_segments.toml\"\nlanguages = [\"en\", \"ru\"]\n[[chapters]]\ntitle = \"x\"\n"
                           "step = 1\nnarration.en = \"fine\"\nnarration.ru = \"Отсечение ✓\"\n";
    const hsr::viz::CheckResult r = hsr::viz::check_file(path);
    CHECK(r.problems.empty());
    REQUIRE(r.warnings.size() == 2);
    CHECK(r.warnings[0] == path + ": title: U+4E2D 中 is not in the window's font (the window draws � instead)");
    CHECK(r.warnings[1] == path + ": chapters[0].narration.ru: U+2713 ✓ is not in the window's font (the window draws � instead)");
    std::filesystem::remove(path);
}

TEST_CASE("no shipped lesson uses a character the font lacks", "[glyphs][lesson]") {
    for (const std::string& f : hsr::viz::shipped_lessons()) {
        INFO(f);
        CHECK(hsr::viz::check_file(f).warnings.empty());
    }
}
