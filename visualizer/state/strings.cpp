// SPDX-License-Identifier: MIT
#include "state/strings.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "sayings.h"
#include "state/lesson.h"

namespace hsr::viz {
namespace {

// Nested tables become dotted keys: [timeline] play = "Play" is "timeline.play".
void flatten(const toml::table& t, const std::string& prefix, std::map<std::string, std::string>& out,
             std::vector<std::string>& problems, const std::string& file) {
    for (const auto& [k, v] : t) {
        const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
        if (const auto* sub = v.as_table()) flatten(*sub, key, out, problems, file);
        else if (const auto* s = v.as_string()) out[key] = s->get();
        else if (key != "language")
            problems.push_back(file + ":" + std::to_string(v.source().begin.line) + ": key '" + key + "' is not text");
    }
}

// The template a language's catalogue has for `key`, if it has one.
const std::string* entry(const std::map<std::string, std::map<std::string, std::string>, std::less<>>& catalogues,
                         std::string_view language, const std::string& key) {
    const auto catalogue = catalogues.find(language);
    if (catalogue == catalogues.end()) return nullptr;
    const auto it = catalogue->second.find(key);
    return it == catalogue->second.end() ? nullptr : &it->second;
}

// Is `value` one number written with a decimal point ("11.1", "-0.25", "1.5e-3"), and nothing else? Such a value is
// written with the language's decimal separator; a tuple, a name or a version ("0.9.1") is left as it is.
bool is_number(std::string_view value, bool decimal_point) {
    std::size_t i = value.starts_with('-') ? 1 : 0;
    const auto digits = [&] {
        const std::size_t from = i;
        while (i < value.size() && value[i] >= '0' && value[i] <= '9') ++i;
        return i > from;
    };
    if (!digits()) return false;
    if (i < value.size() && value[i] == '.') {
        ++i;
        if (!digits()) return false;
    } else if (decimal_point) {
        return false;
    }
    if (i < value.size() && (value[i] == 'e' || value[i] == 'E')) {
        ++i;
        if (i < value.size() && (value[i] == '-' || value[i] == '+')) ++i;
        if (!digits()) return false;
    }
    return i == value.size();
}
bool is_decimal_number(std::string_view value) { return is_number(value, true); }

// The numbers of a tuple or an interval of numbers, "(1.5, -2, 0)" or "[-0.87, 0)", without its brackets; none
// when `value` is not one.
std::optional<std::vector<std::string_view>> tuple_items(std::string_view value) {
    if (value.size() < 3 || (value.front() != '(' && value.front() != '[') || (value.back() != ')' && value.back() != ']'))
        return std::nullopt;
    std::vector<std::string_view> items;
    std::string_view inside = value.substr(1, value.size() - 2);
    for (std::size_t comma; (comma = inside.find(", ")) != std::string_view::npos; inside.remove_prefix(comma + 2))
        items.push_back(inside.substr(0, comma));
    items.push_back(inside);
    if (items.size() < 2 || !std::all_of(items.begin(), items.end(), [](std::string_view v) { return is_number(v, false); }))
        return std::nullopt;
    return items;
}

}  // namespace

std::string Strings::number(std::string_view language, std::string value) const {
    const std::string* separator = entry(catalogues_, language, "decimal_separator");
    if (!separator || *separator == ".") return value;
    if (is_decimal_number(value)) return value.replace(value.find('.'), 1, *separator);
    // a tuple's numbers each so, and parted by semicolons: "(1,5; −2; 0)", not "(1,5, −2, 0)"
    if (const auto items = tuple_items(value)) {
        std::string out(1, value.front());
        for (std::size_t k = 0; k < items->size(); ++k) out += (k ? "; " : "") + number(language, std::string((*items)[k]));
        return out + value.back();
    }
    return value;
}

void Strings::add(const std::string& language, const std::string& path, std::string_view text) {
    try {
        const toml::table root = toml::parse(text, path);
        std::map<std::string, std::string> keys;
        flatten(root, "", keys, problems_, path);
        catalogues_[language] = std::move(keys);
    } catch (const toml::parse_error& e) {
        problems_.push_back(path + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()) +
                            " (the file is left out: its language falls back to English)");
    }
}

void Strings::check() {
    const auto english = catalogues_.find("en");
    if (english == catalogues_.end()) {
        problems_.push_back("en.toml: no English catalogue (every other language is checked against it)");
        return;
    }
    for (const auto& [language, keys] : catalogues_) {
        if (language == "en") continue;
        const std::string file = language + ".toml";
        for (const auto& [key, pattern] : english->second) {
            const auto it = keys.find(key);
            if (it == keys.end()) problems_.push_back(file + ": key '" + key + "' is missing (English: '" + pattern + "')");
            else if (value_names(it->second) != value_names(pattern))
                problems_.push_back(file + ": key '" + key + "' names other values than English's '" + pattern + "'");
        }
        for (const auto& [key, pattern] : keys)
            if (!english->second.contains(key)) problems_.push_back(file + ": key '" + key + "' is not in English's catalogue");
    }
}

Strings Strings::load(const std::string& folder) {
    Strings s;
    std::error_code error;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        std::ifstream in(path);
        std::ostringstream text;
        text << in.rdbuf();
        s.add(path.stem().string(), path.string(), text.str());
    }
    s.check();
    return s;
}

Strings Strings::from_texts(const std::map<std::string, std::string>& files) {
    Strings s;
    for (const auto& [language, text] : files) s.add(language, language + ".toml", text);
    s.check();
    return s;
}

std::vector<std::string> Strings::languages() const {
    std::vector<std::string> out;
    if (catalogues_.contains("en")) out.push_back("en");
    for (const auto& [language, keys] : catalogues_)
        if (language != "en") out.push_back(language);
    return out;
}

std::string Strings::english(std::string_view key) const {
    const std::string* t = entry(catalogues_, "en", std::string(key));
    return t ? *t : std::string();
}

std::vector<std::string> Strings::keys(const std::string& language) const {
    std::vector<std::string> out;
    if (const auto c = catalogues_.find(language); c != catalogues_.end())
        for (const auto& [key, pattern] : c->second) out.push_back(key);
    return out;
}

bool Strings::has(std::string_view key) const {
    return entry(catalogues_, "en", std::string(key)) != nullptr;
}

std::string Strings::text(std::string_view key, StringValues values) const { return text_in(language_, key, values); }

std::string Strings::text_in(std::string_view wanted, std::string_view key, StringValues values) const {
    // that language, else English, else the key itself (a missing key shows, it does not crash)
    for (const std::string_view language : {wanted, std::string_view("en")})
        if (const std::string* t = entry(catalogues_, language, std::string(key))) {
            std::vector<algo::NamedValue> written(values);
            for (auto& [name, value] : written) value = number(wanted, std::move(value));
            return fill(*t, written);
        }
    return std::string(key);
}

std::string_view Strings::pattern(std::string_view section, const algo::Saying& s) const {
    if (language_ != "en")
        if (const std::string* t = entry(catalogues_, language_, std::string(section) + "." + std::string(s.key))) return *t;
    return s.english;  // English is the code's own (the catalogue's English copy is checked equal to it by a test)
}

std::string Strings::say(const algo::Saying& term) const { return std::string(pattern("machine", term)); }

std::string Strings::word(std::string_view english) const {
    if (language_ == "en") return std::string(english);
    if (is_decimal_number(english)) return number(language_, std::string(english));  // "0,5" in German
    // the catalogue's own [words] first (true, false), then the machines' terms
    if (const std::string* t = entry(catalogues_, language_, "words." + std::string(english))) return *t;
    for (const auto family : algo::machine_sayings())
        for (const algo::Saying& saying : family)
            if (saying.english == english && saying.english.find('{') == std::string_view::npos) return say(saying);
    return std::string(english);
}

std::string Strings::name(std::string_view english) const {
    const std::string* t = entry(catalogues_, language_, "names." + std::string(english));
    return t ? *t : std::string(english);
}

std::string Strings::say(const algo::Phrase& phrase) const {
    if (!phrase.saying) return {};
    std::vector<algo::NamedValue> values = phrase.values;
    for (auto& [name, value] : values) value = number(language_, std::move(value));
    for (const auto& [name, term] : phrase.terms) values.emplace_back(name, say(*term));
    return fill(pattern("machine", *phrase.saying), values);
}

Strings& window_strings() {
    static Strings strings = Strings::load(data_dir() + "/assets/strings");
    return strings;
}

}  // namespace hsr::viz
