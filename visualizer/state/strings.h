// SPDX-License-Identifier: MIT
// The window's own words, one catalogue per language: data_dir()/assets/strings/LANG.toml, each a table of keys
// to whole sentences (templates) that name their values in braces, "step {step} of {steps}", so that a language
// puts the values where its grammar wants them. A teacher adds a language by adding one file with the same keys;
// `problems()` (and the test over the shipped files) names every key a language lacks or adds, and every template
// whose values differ from the English one's.
//
//   # assets/strings/de.toml
//   language = "Deutsch"
//   [timeline]
//   step = "Schritt {step} von {steps}"
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/phrase.h"

namespace hsr::viz {

using StringValues = std::initializer_list<algo::NamedValue>;

class Strings {
public:
    // Every LANG.toml in the folder. A file that cannot be read is left out and named in problems(); English
    // (en.toml) is what every other language is checked against and what a missing key falls back to.
    static Strings load(const std::string& folder);
    // From texts (for tests): language code → the file's text, as if it were `folder`/LANG.toml.
    static Strings from_texts(const std::map<std::string, std::string>& files);

    // The language the window speaks; one without a catalogue speaks English.
    void use(const std::string& language) { language_ = language; }
    const std::string& language() const { return language_; }
    std::vector<std::string> languages() const;  // those with a catalogue, English first

    // The template for `key` in the language used (else English, else the key itself, so that a gap shows rather
    // than crashes), its {names} filled from `values`; a name without a value stays as written.
    std::string text(std::string_view key, StringValues values = {}) const;
    std::string text_in(std::string_view language, std::string_view key, StringValues values = {}) const;  // in that one
    // What a machine's event says (algo::phrase(event)), in the language used: its template under [machine] in that
    // language's catalogue, else the machine's own English; its terms (a test's name) likewise.
    std::string say(const algo::Phrase& phrase) const;
    std::string say(const algo::Saying& term) const;  // a word or name the machine uses, without values
    // A template whose English is in the code (a machine's under [machine], a practice question's under [exercise]):
    // the catalogue's `section`.KEY in the language used, else the code's English.
    std::string_view pattern(std::string_view section, const algo::Saying& s) const;
    // A machine's word given in English, as a lesson's choice gives it ("entering"): in the language used when a
    // machine's term says it, else as given.
    std::string word(std::string_view english) const;
    // A name the code writes in English (a topic, a practice topic's title) in the student's language: the
    // catalogue's [names], else as written.
    std::string name(std::string_view english) const;
    std::string english(std::string_view key) const;            // the English template as written ("" if none)
    // A value as `language` writes it: a decimal number with the catalogue's `decimal_separator` ("11,1" in German),
    // anything else as given. text() and say() write every value so.
    std::string number(std::string_view language, std::string value) const;
    std::vector<std::string> keys(const std::string& language) const;  // a catalogue's keys, sorted
    // Does the catalogue hold the key in English?
    bool has(std::string_view key) const;

    // What is wrong with the catalogues, as "de.toml: key 'timeline.play' is missing (English: 'Play')".
    const std::vector<std::string>& problems() const { return problems_; }

private:
    std::map<std::string, std::map<std::string, std::string>, std::less<>> catalogues_;  // language → key → template
    std::string language_ = "en";
    std::vector<std::string> problems_;
    void add(const std::string& language, const std::string& path, std::string_view text);
    void check();
};

// Fills a template's {names} and {name?one|other} plurals (also for the lessons' own sentences).
using algo::fill;
// The {names} a template uses, sorted.
using algo::value_names;

// The window's catalogue, loaded once from data_dir()/assets/strings.
Strings& window_strings();
// Shorthand for window_strings().text(key, values).
inline std::string tr(std::string_view key, StringValues values = {}) { return window_strings().text(key, values); }
// A number as the window's language writes it ("0,211" in German), for the panels' tables.
inline std::string number_in_language(std::string number) {
    return window_strings().number(window_strings().language(), std::move(number));
}

}  // namespace hsr::viz
