// SPDX-License-Identifier: MIT
#include "state/glyphs.h"

#include <algorithm>
#include <cstdio>

namespace hsr::viz {
namespace {

// The next code point of `s` from `at` (advancing it); U+FFFD for a malformed sequence (the TOML reader refuses
// invalid UTF-8 before this is reached, so that is only for text from elsewhere).
char32_t next_code_point(std::string_view s, std::size_t& at) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b = byte(at++);
    if (b < 0x80) return b;
    const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : -1;
    if (extra < 0 || at + std::size_t(extra) > s.size()) return 0xFFFD;
    char32_t c = b & (0x3F >> extra);
    for (int k = 0; k < extra; ++k) {
        if ((byte(at) & 0xC0) != 0x80) return 0xFFFD;
        c = (c << 6) | (byte(at++) & 0x3F);
    }
    return c;
}

}  // namespace

bool in_font(char32_t c) {
    return std::any_of(font_glyphs.begin(), font_glyphs.end(), [c](const GlyphRange& r) { return c >= r.first && c <= r.last; });
}

std::vector<char32_t> glyphs_missing(std::string_view utf8) {
    std::vector<char32_t> missing;
    for (std::size_t at = 0; at < utf8.size();) {
        const char32_t c = next_code_point(utf8, at);
        if (c == '\n' || c == '\t' || c == '\r' || in_font(c)) continue;
        if (std::find(missing.begin(), missing.end(), c) == missing.end()) missing.push_back(c);
    }
    return missing;
}

std::string glyph_name(char32_t c) {
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X ", static_cast<unsigned>(c));
    std::string name = code;
    // the character itself, in UTF-8
    if (c < 0x80) name += char(c);
    else if (c < 0x800) name += {char(0xC0 | (c >> 6)), char(0x80 | (c & 0x3F))};
    else if (c < 0x10000) name += {char(0xE0 | (c >> 12)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
    else name += {char(0xF0 | (c >> 18)), char(0x80 | ((c >> 12) & 0x3F)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
    return name;
}

}  // namespace hsr::viz
