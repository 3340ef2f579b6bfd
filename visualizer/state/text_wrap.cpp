// SPDX-License-Identifier: MIT
#include "state/text_wrap.h"

#include <algorithm>

namespace hsr::viz {
namespace {

// The longest prefix of `word` (whole UTF-8 characters) no wider than `width`, at least one character.
std::size_t fitting_prefix(std::string_view word, float width, const std::function<float(std::string_view)>& measure) {
    std::size_t best = 0;
    for (std::size_t i = 1; i <= word.size(); ++i) {
        if (i < word.size() && (static_cast<unsigned char>(word[i]) & 0xC0) == 0x80) continue;  // inside a character
        if (measure(word.substr(0, i)) > width && best > 0) break;
        best = i;
    }
    return std::max<std::size_t>(best, 1);
}

}  // namespace

std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const std::function<float(std::string_view)>& measure, int* forced) {
    std::vector<std::string> lines;
    while (true) {
        const std::size_t end = text.find('\n');
        std::string_view paragraph = text.substr(0, end);
        std::string line;
        while (!paragraph.empty() || line.empty()) {
            const std::size_t space = paragraph.find(' ');
            std::string_view word = paragraph.substr(0, space);
            const std::string candidate = line.empty() ? std::string(word) : line + " " + std::string(word);
            if (measure(candidate) <= width || line.empty()) {
                if (line.empty() && measure(word) > width && !word.empty()) {  // too wide even alone: cut it
                    const std::size_t cut = fitting_prefix(word, width, measure);
                    lines.emplace_back(word.substr(0, cut));
                    if (forced) ++*forced;
                    paragraph.remove_prefix(cut);
                    continue;
                }
                line = candidate;
                paragraph = space == std::string_view::npos ? std::string_view{} : paragraph.substr(space + 1);
                if (paragraph.empty()) break;
            } else {
                lines.push_back(std::move(line));
                line.clear();
            }
        }
        lines.push_back(std::move(line));
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return lines;
}

std::string reflow(std::string_view text) {
    while (!text.empty() && text.front() == '\n') text.remove_prefix(1);
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n') {
            out += text[i];
            continue;
        }
        std::size_t run = i;
        while (run < text.size() && text[run] == '\n') ++run;
        out += run - i > 1 ? "\n" : (out.empty() || out.back() == ' ' ? "" : " ");
        i = run - 1;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == '\n')) out.pop_back();
    return out;
}

}  // namespace hsr::viz
