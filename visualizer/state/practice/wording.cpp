// SPDX-License-Identifier: MIT
#include "state/practice/wording.h"

namespace hsr::viz::practice {

Wording Wording::as_is(std::string text) {
    Wording w;
    w.values.emplace_back("text", std::move(text));
    return w;
}

std::string said(const Wording& w, const Patterns& pattern) {
    if (!w.saying) return w.values.empty() ? std::string() : w.values.front().second;
    std::vector<algo::NamedValue> values = w.values;
    for (const auto& [name, list] : w.parts) {
        std::string joined;
        for (const Wording& item : list) joined += (joined.empty() ? "" : "; ") + said(item, pattern);
        values.emplace_back(name, std::move(joined));
    }
    return algo::fill(pattern(*w.saying), values);
}

std::string english(const Wording& w) {
    return said(w, [](const algo::Saying& s) { return s.english; });
}

}  // namespace hsr::viz::practice
