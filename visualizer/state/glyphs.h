// SPDX-License-Identifier: MIT
// The characters the window's font is built with: Latin (with Latin Extended-A and -B, for the languages of Europe
// written in Latin letters), Greek (ε, the lecture's symbols), Cyrillic, punctuation, super- and subscripts, arrows,
// mathematical operators and geometric shapes. DejaVu, the font the window loads, has all of them. A lesson that
// uses a character outside these shows it as the replacement mark �, so `hsrviz check` warns about it (glyphs_missing).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace hsr::viz {

struct GlyphRange {
    char32_t first, last;  // inclusive
};

inline constexpr std::array<GlyphRange, 10> font_glyphs{{
    {0x0020, 0x00FF},  // Basic Latin and Latin-1
    {0x0100, 0x024F},  // Latin Extended-A and -B
    {0x0370, 0x03FF},  // Greek
    {0x0400, 0x04FF},  // Cyrillic
    {0x2000, 0x206F},  // general punctuation (– — … ·)
    {0x2070, 0x209F},  // superscripts and subscripts
    {0x2190, 0x21FF},  // arrows
    {0x2200, 0x22FF},  // mathematical operators (≤ ≥ −)
    {0x25A0, 0x25FF},  // geometric shapes
    {0xFFFD, 0xFFFD},  // the replacement character
}};

bool in_font(char32_t c);

// The characters of `utf8` the font lacks, each once, in the order they first appear (tab and newline are not
// drawn and count as present).
std::vector<char32_t> glyphs_missing(std::string_view utf8);

// "U+4E2D 中": how a warning names a character.
std::string glyph_name(char32_t c);

}  // namespace hsr::viz
