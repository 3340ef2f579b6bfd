// SPDX-License-Identifier: MIT
// libFuzzer: any text as a lesson file (its chapters, questions, languages, options). It loads, or fails with a
// LoadError naming file and line (a scene it names is looked for beside the corpus, and is usually missing).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/numeric.h"
#include "state/lesson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        (void)hsr::viz::load_lesson_text(HSR_SOURCE_DIR "/lessons/fuzz.toml", text);
    } catch (const hsr::algo::LoadError&) {
    } catch (const hsr::algo::InvalidInput&) {
    }
    return 0;
}
