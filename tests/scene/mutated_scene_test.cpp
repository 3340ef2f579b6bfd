// SPDX-License-Identifier: MIT
// A teacher's typos, at random: every byte-level mutation of a real scene file either loads or gives a LoadError
// with a file and a line; nothing else escapes, nothing crashes (the sanitizer build runs this too).
#include <fstream>
#include <random>
#include <sstream>

#include "catch.h"
#include "clipping/clip_scene.h"
#include "core/numeric.h"
#include "scene/load_scene.h"

using namespace hsr::algo;

TEST_CASE("every mutation of a scene file loads or fails with file and line", "[scene][errors][fuzz]") {
    std::ifstream in(HSR_SOURCE_DIR "/assets/scenes/cs_segments.toml");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string original = buffer.str();
    REQUIRE(original.size() > 500);

    std::mt19937_64 rng(99);
    const std::string alphabet = "[]{}=\",.#-+0123456789eEnaitf \n\t\\xyz";
    int loaded = 0, refused = 0;
    for (int n = 0; n < 3000; ++n) {
        std::string text = original;
        const int edits = 1 + int(rng() % 4);
        for (int k = 0; k < edits && !text.empty(); ++k) {
            const std::size_t at = rng() % text.size();
            switch (rng() % 4) {
                case 0: text.erase(at, 1 + rng() % 8); break;
                case 1: text[at] = alphabet[rng() % alphabet.size()]; break;
                case 2: text.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
                case 3: text.insert(at, text.substr(rng() % text.size(), 1 + rng() % 16)); break;
            }
        }
        try {
            const Scene s = load_scene_text("mutated.toml", text);
            // whatever loaded must also clip without trouble
            for (auto algorithm : {ClipAlgorithm::cohen_sutherland, ClipAlgorithm::sutherland_hodgman})
                clip_scene(clip_job(s), algorithm).run_to_end();
            ++loaded;
        } catch (const LoadError& e) {
            INFO(e.what());
            CHECK(e.file == "mutated.toml");
            CHECK(e.line >= 1);
            ++refused;
        } catch (const InvalidInput& e) {
            // a camera that maps a vertex to infinity (e.g. near ≈ far) is refused by the machine's door check
            INFO(e.what());
            SUCCEED();
            ++refused;
        }
    }
    INFO(loaded << " loaded, " << refused << " refused");
    CHECK(loaded > 100);
    CHECK(refused > 100);
}
