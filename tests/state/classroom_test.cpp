// SPDX-License-Identifier: MIT
// Chapters and questions: every shipped lesson and scene checks out (chapters start, questions are answered by the
// machine, answers are among the choices); a question answered wrongly on purpose gets "wrong" with the machine's
// own answer and sentence; playback pauses at a chapter; a teacher's typo names the file and line.
#include <filesystem>
#include <fstream>

#include "catch.h"
#include "state/classroom.h"
#include "state/families.h"
#include "state/file_watch.h"
#include "state/lesson_check.h"

using namespace hsr::viz;

TEST_CASE("every shipped lesson and scene checks out", "[lesson][check]") {
    int files = 0, questions = 0;
    for (const char* dir : {"/lessons", "/assets/scenes"})
        for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(HSR_SOURCE_DIR) + dir)) {
            if (e.path().extension() != ".toml") continue;
            const CheckResult r = check_file(e.path().string());
            INFO(e.path().string());
            for (const auto& p : r.problems) INFO(p);
            CHECK(r.problems.empty());
            ++files, questions += int(r.questions);
        }
    CHECK(files > 50);
    CHECK(questions >= 3);
}

TEST_CASE("a question is judged by the machine's next event, right or wrong, and scored", "[lesson][classroom]") {
    auto s = make_session(load_lesson(HSR_SOURCE_DIR "/lessons/01_cohen_sutherland.toml"));
    s->prefetch(prefetch_events);
    Classroom room;
    room.attach(*s);
    CHECK(room.questions() == 3);
    CHECK(room.language() == "en");
    // play from the start: the first pausing chapter stops playback where segment 3 starts
    std::size_t before = s->cursor();
    while (!room.crossed_a_pause(*s, before)) {
        before = s->cursor();
        s->step();
    }
    REQUIRE(room.open_question(*s) != nullptr);
    CHECK(room.open_question(*s)->ask.at("en") == "How does segment 3 end?");
    CHECK(room.first_pause_crossed(*s, 0) == s->cursor());  // a jump over it would stop here, the question not yet answered
    CHECK(s->cursor() < *room.script()->places()[1].answered);
    const auto wrong = room.answer(*s, "clipped");  // on purpose
    REQUIRE(wrong);
    CHECK_FALSE(wrong->right);
    CHECK(wrong->answer == "inside");
    CHECK_THAT(wrong->because, Catch::Contains("segment 3 inside"));
    CHECK(room.verdict(*s).has_value());
    CHECK(room.open_question(*s) == nullptr);  // answered: asked no more
    // the next chapter's question, answered right
    room.next_chapter(*s);
    REQUIRE(room.open_question(*s) != nullptr);
    const auto right = room.answer(*s, "000010");
    REQUIRE(right);
    CHECK(right->right);
    CHECK(room.right() == 1);
    CHECK(room.answered() == 2);
    // languages: English, then German
    room.next_language();
    CHECK(room.language() == "de");
    const auto c = room.chapter(*s);
    REQUIRE(c);
    CHECK_THAT(in_language(s->lesson().chapters[*c].narration, room.language(), s->lesson().languages), Catch::Contains("Segment 4"));
}

TEST_CASE("a question holds: nothing forward leaves the step where it is asked until it is answered", "[lesson][classroom]") {
    auto s = make_session(load_lesson(HSR_SOURCE_DIR "/lessons/01_cohen_sutherland.toml"));
    s->prefetch(prefetch_events);
    Classroom room;
    room.attach(*s);
    const ChapterPlace& first = room.script()->places()[1];  // chapter 1 asks how segment 3 ends
    REQUIRE(first.answered);
    REQUIRE(first.held);
    const std::size_t hold = *first.held;  // where it is asked: the events after it give the answer away (a
    CHECK(hold == *first.starts);          // CodesCompared sentence says "accepted" before the deciding event)
    CHECK(hold < *first.answered - 1);
    CHECK(room.hold(0) == hold);
    CHECK(room.hold(hold) == hold);
    // End from the start would show the answer: it stops before the deciding event, the question open
    s->seek_end();
    CHECK(s->cursor() > hold);
    s->seek(*room.hold(0));
    REQUIRE(room.open_question(*s) != nullptr);
    room.close_revealed(*s);  // nothing shown yet: nothing closed
    CHECK(room.open_question(*s) != nullptr);
    // one more event gives the answer away: then the question is no longer asked, and it scores nothing
    s->micro_step();
    CHECK(s->cursor() == hold + 1);
    CHECK(room.open_question(*s) == nullptr);
    room.close_revealed(*s);
    const auto v = room.verdict(*s);
    REQUIRE(v);
    CHECK(v->revealed);
    CHECK_FALSE(v->right);
    CHECK(v->answer == "inside");
    CHECK(room.answered() == 0);
    CHECK(room.right() == 0);
    // that question holds no more; the next one does, further on
    const auto next = room.hold(s->cursor());
    REQUIRE(next);
    CHECK(*next > hold);
    // answered in time, a question holds nothing and the player moves to its deciding event
    s->seek(*next);
    REQUIRE(room.open_question(*s) != nullptr);
    const auto right = room.answer(*s, "000010");
    REQUIRE(right);
    CHECK(right->right);
    const ChapterPlace& asked = room.script()->places()[*room.chapter(*s)];
    CHECK(s->cursor() == *asked.answered);  // the deciding event, shown (it lies past the step where it was asked)
    CHECK(*asked.answered > *next + 1);
    CHECK(room.verdict(*s).has_value());
    CHECK(room.answered() == 1);
    CHECK(room.hold(*next) != next);
}

TEST_CASE("a chapter naming an event the machine never tells is a problem with file and line", "[lesson][check][errors]") {
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_check_test";
    std::filesystem::create_directories(dir);
    const auto file = dir / "typo.toml";
    std::ofstream(file) << "title = \"t\"\nalgorithm = \"cohen_sutherland\"\nscene = \"" << HSR_SOURCE_DIR
                        << "/assets/scenes/cs_segments.toml\"\n\n[[chapters]]\nwhen = \"OutcodeComputd\"\nnarration = \"x\"\n";
    const CheckResult r = check_file(file.string());
    REQUIRE(r.problems.size() == 1);
    CHECK_THAT(r.problems[0], Catch::Contains("typo.toml:5") && Catch::Contains("OutcodeComputd") && Catch::Contains("OutcodeComputed"));
    std::ofstream(file) << "title = \"t\"\nalgorithm = \"cohen_sutherland\"\nscene = \"" << HSR_SOURCE_DIR
                        << "/assets/scenes/cs_segments.toml\"\n\n[[chapters]]\nstep = 2\nnarrative = \"x\"\n";
    const CheckResult bad_key = check_file(file.string());
    REQUIRE(bad_key.problems.size() == 1);
    CHECK_THAT(bad_key.problems[0], Catch::Contains("typo.toml:7") && Catch::Contains("narrative"));
}

TEST_CASE("a chapter's pause and opens are true or false, and anything else is an error naming the field", "[lesson][errors]") {
    const std::string head = "title = \"t\"\nalgorithm = \"cohen_sutherland\"\nscene = \"" HSR_SOURCE_DIR "/assets/scenes/cs_segments.toml\"\n";
    const Lesson ok = load_lesson_text(HSR_SOURCE_DIR "/lessons/b.toml", head + "[[chapters]]\nstep = 2\nopens = true\nnarration = \"x\"\n");
    REQUIRE(ok.chapters.size() == 1);
    CHECK(ok.chapters[0].opens);
    CHECK_FALSE(ok.chapters[0].pause);
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/b.toml", head + "[[chapters]]\nstep = 2\nopens = \"yes\"\n"),
                      Catch::Contains("b.toml:6") && Catch::Contains("chapters[0].opens") && Catch::Contains("true or false"));
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/b.toml", head + "[[chapters]]\nstep = 2\npause = 1\n"),
                      Catch::Contains("chapters[0].pause"));
}

TEST_CASE("a file edited on disk is noticed once, and not before half a second", "[lesson][watch]") {
    const auto file = std::filesystem::temp_directory_path() / "hsrviz_watch_test.toml";
    std::ofstream(file) << "title = \"a\"\n";
    FileWatch watch;
    watch.watch({file.string()});
    CHECK_FALSE(watch.changed(1.0));
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(2));
    CHECK_FALSE(watch.changed(0.1));  // looked at no more than twice a second
    CHECK(watch.changed(0.5));
    CHECK_FALSE(watch.changed(1.0));  // once per change
    std::filesystem::remove(file);
    CHECK(watch.changed(1.0));        // gone (being rewritten) is a change too
}

TEST_CASE("a lesson naming a scene too long for the file system is an error, not a crash (found by fuzz_lesson)", "[lesson][errors]") {
    const std::string text = "title = \"t\"\nalgorithm = \"cohen_sutherland\"\nscene = \"" + std::string(3000, 'x') + "\"\n";
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/long.toml", text), Catch::Contains("long.toml:3") && Catch::Contains("File name too long"));
}

TEST_CASE("check reports every problem of a file, each with its line and the field as the file numbers it", "[lesson][errors]") {
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_check_all";
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "many.toml").string();
    std::ofstream(file) << "name = \"many problems\"\n[camera]\neye = [0, 0, 5]\nfov = 0\nnear = -1\n"
                           "[[polygons]]\nid = 1\nvertices = [[0,0,0],[1,0,0]]\n"
                           "[[polygons]]\nid = 2\ncolor = \"red\"\nvertices = [[0,0,0],[1,0,0],[0,1,0]]\n"
                           "[[polygons]]\nid = 3\nvertices = [[0,0,0],[1,0,0],[0,1,nan]]\n"
                           "[[polygons]]\nid = 4\nvertices = [[0,0,0],[1,0,0],[0,1,0]]\n";
    const CheckResult r = check_file(file);
    REQUIRE(r.problems.size() == 5);
    CHECK_THAT(r.problems[0], Catch::Contains("many.toml:4:7: field 'camera.fov'"));
    CHECK_THAT(r.problems[1], Catch::Contains("many.toml:5:8: field 'camera.near'"));
    CHECK_THAT(r.problems[2], Catch::Contains("many.toml:8:12: field 'polygons[0].vertices'"));
    CHECK_THAT(r.problems[3], Catch::Contains("many.toml:11:9: field 'polygons[1].color'"));
    CHECK_THAT(r.problems[4], Catch::Contains("many.toml:15:34: field 'polygons[2].vertices[2][2]'"));
    // A problem is reported once, where it is: not again as what its removal left (issue 53, item 10)
    for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
             {"[camera]\neye = [0, 0, 5]\nfov = nan\n[[polygons]]\nid = 1\nvertices = [[0,0,0],[1,0,0]]\n", "field 'polygons[0].vertices'"},
             {"[camera]\neye = [nan, 0, 5]\ntarget = [0, 0, 0]\n[[polygons]]\nid = 1\nvertices = [[0,0,0],[1,0,0],[0,1,0]]\n", "field 'camera.eye[0]'"},
             {"[camera]\nnear = -1\nfar = 0.5\n[[polygons]]\nid = 1\nvertices = [[0,0,0],[1,0,0],[0,1,0]]\n", "field 'camera.near'"}}) {
        std::ofstream(file) << text;
        const CheckResult once = check_file(file);
        INFO(text);
        for (const auto& p : once.problems) INFO(p);
        CHECK(once.problems.size() == (text.find("fov = nan") != std::string::npos ? 2u : 1u));
        CHECK_THAT(once.problems.back(), Catch::Contains(says));
    }
    // A lesson whose algorithm is unknown stops there (removed, the lesson would read as a scene)
    std::ofstream(file) << "title = \"t\"\nalgorithm = \"zbufer\"\nscene = \"none.toml\"\nformat = \"int12\"\n";
    REQUIRE(check_file(file).problems.size() == 1);
    std::filesystem::remove_all(dir);
}

TEST_CASE("the student's language is kept across lessons, the narration follows it where the lesson has it", "[lesson][classroom]") {
    auto german = make_session(load_lesson(HSR_SOURCE_DIR "/lessons/01_cohen_sutherland.toml"));
    // a lesson narrated only in English (every shipped lesson is narrated in English and German)
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_english_only_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "english.toml") << "title = \"English only\"\nalgorithm = \"portal_render\"\nscene = \"" << HSR_SOURCE_DIR
                                        << "/assets/scenes/cells_lecture.toml\"\n[[chapters]]\ntitle = \"One\"\nstep = 0\nnarration = \"Words.\"\n";
    auto english_only = make_session(load_lesson((dir / "english.toml").string()));
    std::filesystem::remove_all(dir);
    REQUIRE(english_only->lesson().languages == std::vector<std::string>{"en"});
    Classroom room;
    room.attach(*english_only);
    CHECK(room.language() == "en");
    // L in a lesson narrated only in English still reaches the languages the window's words have
    room.next_language({"en", "de"});
    CHECK(room.chosen_language() == "de");
    CHECK(room.language() == "en");  // the narration: the lesson's only language
    room.next_language({"en", "de"});
    CHECK(room.chosen_language() == "en");
    room.next_language({"en", "de"});
    // another lesson: the choice stays, and this one is narrated in it
    room.restart();
    CHECK(room.chosen_language() == "de");
    room.attach(*german);
    CHECK(room.language() == "de");
    // back to the English-only lesson: narrated in English, the choice still German
    room.restart();
    room.attach(*english_only);
    CHECK(room.language() == "en");
    CHECK(room.chosen_language() == "de");
    // a remembered choice the lesson lacks (French) leaves the narration in the lesson's first language
    room.choose_language("fr");
    CHECK(room.language() == "en");
}

TEST_CASE("a lesson's and its chapters' titles and summary may be given per language, like the narration", "[lesson][errors]") {
    const Lesson shipped = load_lesson(HSR_SOURCE_DIR "/lessons/13_depth_sort_cycle.toml");
    CHECK(shipped.title == "Depth sort: three bars in a cycle");  // the first language's, for the command line
    CHECK(in_language(shipped.titles, "de", shipped.languages) == "Tiefensortierung: drei Balken im Zyklus");
    REQUIRE_FALSE(shipped.chapters.empty());
    CHECK(shipped.chapters[0].title == "R = #0 against Q = #1");
    CHECK(in_language(shipped.chapters[0].titles, "de", shipped.languages) == "R = #0 gegen Q = #1");
    CHECK(in_language(shipped.chapters[0].titles, "fr", shipped.languages) == "R = #0 against Q = #1");  // else the first language

    const std::string scene = "scene = \"" HSR_SOURCE_DIR "/assets/scenes/cs_segments.toml\"\nalgorithm = \"cohen_sutherland\"\n";
    const Lesson both = load_lesson_text(HSR_SOURCE_DIR "/lessons/t.toml",
                                         "languages = [\"en\", \"de\"]\ntitle = { en = \"Clip\", de = \"Clippen\" }\nsummary.de = \"Nur deutsch\"\n" + scene);
    CHECK(both.title == "Clip");
    CHECK(in_language(both.summaries, "de", both.languages) == "Nur deutsch");
    CHECK(both.summary == "Nur deutsch");  // no English summary: the one there is
    // a language the lesson does not list, a title that is no text, and no title at all: errors naming the field
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/t.toml", "title = { en = \"a\", fr = \"b\" }\n" + scene),
                      Catch::Contains("t.toml:1") && Catch::Contains("title.fr"));
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/t.toml", "title = 3\n" + scene), Catch::Contains("title"));
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/t.toml", scene), Catch::Contains("title"));
    CHECK_THROWS_WITH(load_lesson_text(HSR_SOURCE_DIR "/lessons/t.toml", "title = \"t\"\n" + scene + "[[chapters]]\nstep = 1\ntitle.xx = \"?\"\n"),
                      Catch::Contains("chapters[0].title.xx"));
}

TEST_CASE("every lesson stepped with the right arrow, each question answered as it opens, asks all its questions", "[lesson][classroom][order]") {
    int lessons = 0;
    for (const auto& e : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/lessons")) {
        if (e.path().extension() != ".toml") continue;
        INFO(e.path().filename().string());
        auto s = make_session(load_lesson(e.path().string()));
        s->prefetch(prefetch_events);
        s->seek(0);  // where the window opens a lesson
        Classroom room;
        room.attach(*s);
        // what the window does on →, and on a number key while a question is open (its first choice, right or not)
        int asked = 0;
        std::size_t moves = 0;
        while (!s->at_end() && moves++ < 100000) {
            if (const Question* q = room.open_question(*s)) {
                const auto chapter = room.chapter(*s);
                REQUIRE(room.answer(*s, q->choices.empty() ? std::string("0") : q->choices.front()));
                ++asked;
                CHECK(room.chapter(*s) == chapter);  // the answer stays in the chapter that asked
                room.close_revealed(*s);
                continue;
            }
            const std::size_t before = s->cursor();
            s->step();
            if (const auto stop = room.stop_forward(*s, before, true, true)) s->seek(*stop);
            room.close_revealed(*s);
            REQUIRE(s->cursor() > before);  // never held where no question is open
        }
        CHECK(asked == room.questions());
        CHECK(room.answered() == room.questions());
        ++lessons;
    }
    CHECK(lessons >= 39);
}
