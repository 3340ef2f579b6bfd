// SPDX-License-Identifier: MIT
#include "scene/obj_faces.h"

#include <algorithm>

namespace hsr::algo {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// The number of words in `line` separated by spaces and tabs.
std::size_t words(std::string_view line) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < line.size(); ++k)
        if (!is_blank(line[k]) && (k == 0 || is_blank(line[k - 1]))) ++count;
    return count;
}

}  // namespace

std::vector<ObjFace> obj_faces(std::string_view text) {
    std::vector<ObjFace> faces;
    int number = 0;
    for (std::size_t at = 0; at < text.size();) {
        // one line, ended as tinyobjloader's safeGetline ends it
        const std::size_t end = std::min(text.find_first_of("\r\n", at), text.size());
        std::string_view line = text.substr(at, end - at);
        at = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
        ++number;
        while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
        if (line.size() < 2 || line[0] != 'f' || !is_blank(line[1])) continue;
        if (const std::size_t n = words(line.substr(2)); n >= 3) faces.push_back({number, n});
    }
    return faces;
}

}  // namespace hsr::algo
