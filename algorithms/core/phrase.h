// SPDX-License-Identifier: MIT
// A sentence as a template with named values, so that another language can put the values where its grammar wants
// them: "Split #{polygon} by the plane of #{by}." A machine says what an event did as a Phrase; the command line
// and the traces print its English, the window looks its key up in the catalogue of the language the student chose
// (visualizer/state/strings.h) and falls back to the English.
//
// Templates: {name} is a value; {name?one|other} is the word for one or for any other count of `name`
// ("{n} {n?pair|pairs}"). Nothing here knows of a window.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hsr::algo {

using NamedValue = std::pair<std::string_view, std::string>;

// Fills a template's {names} from `values`; a name without a value stays as written.
std::string fill(std::string_view pattern, const NamedValue* first, const NamedValue* last);
inline std::string fill(std::string_view pattern, std::initializer_list<NamedValue> values) {
    return fill(pattern, values.begin(), values.end());
}
inline std::string fill(std::string_view pattern, const std::vector<NamedValue>& values) {
    return fill(pattern, values.data(), values.data() + values.size());
}
// The names a template uses (a plural's name once), sorted, without repeats.
std::vector<std::string> value_names(std::string_view pattern);

// One template of a machine: the key another language's catalogue gives it under [machine] ("depth_sort.moved"),
// and its English.
struct Saying {
    std::string_view key, english;
};

// Values that are themselves words to translate, such as a test's name: each names the saying that says it.
using Terms = std::vector<std::pair<std::string_view, const Saying*>>;

// What one event says: a template, its values, and its terms.
struct Phrase {
    const Saying* saying = nullptr;
    std::vector<NamedValue> values;
    Terms terms;

    Phrase() = default;
    Phrase(const Saying& s, std::vector<NamedValue> v = {}, Terms t = {})
        : saying(&s), values(std::move(v)), terms(std::move(t)) {}
    std::string english() const;
};

}  // namespace hsr::algo
