// SPDX-License-Identifier: MIT
// A practice question in words any language can say. Its sentence is a template of the catalogue's [exercise]
// section, with named values, as the machines' sentences are templates of [machine]: the English lives here in the
// code (what `hsrviz practice` prints and the tests read), another language's in its catalogue file. A value that
// is words itself (the setting, a wall, the triangles drawn) is a wording too, and a list of them is joined by "; ".
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/phrase.h"

namespace hsr::viz::practice {

struct Wording {
    const algo::Saying* saying = nullptr;  // none: the wording is its one value as it stands (an outcode, a room's letter)
    std::vector<algo::NamedValue> values;
    std::vector<std::pair<std::string_view, std::vector<Wording>>> parts;  // values said in words

    Wording() = default;
    Wording(const algo::Saying& s, std::vector<algo::NamedValue> v = {},
            std::vector<std::pair<std::string_view, std::vector<Wording>>> p = {})
        : saying(&s), values(std::move(v)), parts(std::move(p)) {}
    // Words that are the same in every language: numbers, an outcode's bits, a room's letter.
    static Wording as_is(std::string text);
};

// A template's pattern in the language wanted (the catalogue's [exercise] entry, or the English).
using Patterns = std::function<std::string_view(const algo::Saying&)>;

std::string english(const Wording& w);
std::string said(const Wording& w, const Patterns& pattern);

}  // namespace hsr::viz::practice
