// SPDX-License-Identifier: MIT
// Chapters of a lesson: narration that appears when an event first happens (or at a step), may pause playback, and
// may ask a question the machine itself answers.
//
//   languages = ["en", "de"]                 # the first is the default
//   [[chapters]]
//   title = { en = "The outcodes", de = "Die Outcodes" }   # or one text, in the first language
//   when = "OutcodeComputed"                 # an event kind; or step = 12
//   match = { endpoint = "p2" }              # optional: fields the event must have (as its trace writes them)
//   pause = true
//   opens = true                             # optional: the lesson opens where this chapter starts (Home and
//                                            # PgUp still go back to the steps before it)
//   narration = { en = "…", de = "…" }
//   [chapters.question]
//   ask = { en = "Predict the outcode of p2.", de = "…" }
//   event = "OutcodeComputed"                # the next event of this kind (after the chapter's) answers it …
//   match = { endpoint = "p2" }
//   field = "code"                           # … with this field
//   choices = ["000000", "000010", "010010"] # optional: offered as buttons (keys 1 … 9)
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/toml_reader.h"

namespace hsr::viz {

using Texts = std::map<std::string, std::string>;  // language → text

struct EventPattern {
    std::string kind;
    std::vector<std::pair<std::string, std::string>> match;  // field → value, as text
    bool operator==(const EventPattern&) const = default;
};

struct Question {
    Texts ask;
    EventPattern answer_event;
    std::string field;
    std::vector<std::string> choices;
    int line = 0;
};

struct Chapter {
    std::string title;  // in the lesson's first language (the checks, the course list)
    Texts titles;       // by language
    Texts narration;
    std::optional<EventPattern> when;     // the first event like this starts the chapter …
    std::optional<std::size_t> step;      // … or this step
    bool pause = false;
    bool opens = false;                   // the lesson opens here
    std::optional<Question> question;
    int line = 0;                         // in the lesson file
};

// `field`'s texts: one text (the first language's) or a table of texts by language, each of `languages`.
Texts read_texts(const algo::TomlReader& r, const toml::node* n, const std::string& field, const std::vector<std::string>& languages);
std::vector<Chapter> read_chapters(const algo::TomlReader& r, const toml::table& root, std::vector<std::string>& languages);

// Does an event (its trace line, parsed) fit the pattern? Values compare as text (strings without quotes).
bool fits(const nlohmann::json& event, const EventPattern& pattern);
std::string value_text(const nlohmann::json& value);
// The text in a language, else in the first language given, else "".
std::string in_language(const Texts& t, const std::string& language, const std::vector<std::string>& languages);

}  // namespace hsr::viz
