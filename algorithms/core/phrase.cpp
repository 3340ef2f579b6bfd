// SPDX-License-Identifier: MIT
#include "core/phrase.h"

#include <algorithm>

namespace hsr::algo {

std::string fill(std::string_view pattern, const NamedValue* first, const NamedValue* last) {
    std::string out;
    for (std::size_t i = 0; i < pattern.size();) {
        const std::size_t open = pattern.find('{', i);
        if (open == std::string_view::npos) {
            out += pattern.substr(i);
            break;
        }
        out += pattern.substr(i, open - i);
        const std::size_t close = pattern.find('}', open);
        if (close == std::string_view::npos) {
            out += pattern.substr(open);
            break;
        }
        const std::string_view inside = pattern.substr(open + 1, close - open - 1);
        const std::size_t ask = inside.find('?');
        const std::string_view name = inside.substr(0, ask);
        const NamedValue* value = std::find_if(first, last, [&](const NamedValue& v) { return v.first == name; });
        if (value == last) out += pattern.substr(open, close - open + 1);
        else if (ask == std::string_view::npos) out += value->second;
        else {  // {name?one|other}: the form for a count of one, else the other (the one form when no | is given)
            const std::string_view forms = inside.substr(ask + 1);
            const std::size_t bar = forms.find('|');
            out += value->second == "1" || bar == std::string_view::npos ? forms.substr(0, bar) : forms.substr(bar + 1);
        }
        i = close + 1;
    }
    return out;
}

std::vector<std::string> value_names(std::string_view pattern) {
    std::vector<std::string> names;
    for (std::size_t open = pattern.find('{'); open != std::string_view::npos; open = pattern.find('{', open + 1))
        if (const std::size_t close = pattern.find('}', open); close != std::string_view::npos) {
            const std::string_view inside = pattern.substr(open + 1, close - open - 1);
            names.emplace_back(inside.substr(0, inside.find('?')));
        }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::string Phrase::english() const {
    if (!saying) return {};
    std::vector<NamedValue> all = values;
    for (const auto& [name, term] : terms) all.emplace_back(name, std::string(term->english));
    return fill(saying->english, all);
}

}  // namespace hsr::algo
