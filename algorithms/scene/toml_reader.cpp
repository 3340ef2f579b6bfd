// SPDX-License-Identifier: MIT
#include "scene/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "scene/input_file.h"

namespace hsr::algo {
namespace {

std::string where(const std::string& file, int line, int column, const std::string& field, const std::string& msg) {
    std::string out = printable_name(file) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
    if (!field.empty()) out += "field '" + printable(field) + "': ";
    return out + msg;
}

toml::table parse(const std::string& path, std::string_view text) {
    try {
        return toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw LoadError(path, int(e.source().begin.line), int(e.source().begin.column), "",
                        std::string(e.description()));
    }
}

// The characters of UTF-8 text, not its bytes: 4,000 CJK characters are 12,000 bytes (toml++ has checked the UTF-8).
std::size_t characters(std::string_view text) {
    std::size_t count = 0;
    for (const char c : text) count += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return count;
}

// Keys and texts far longer than any lesson's are refused before anything quotes or draws them: a 17,000-character
// name or a 1 MB key would otherwise reach the window's text drawing (16-bit vertex indices) or an error message.
void bound_texts(const std::string& path, const toml::node& n) {
    const auto refuse = [&](const toml::node& at, const std::string& what) {
        throw LoadError(path, int(at.source().begin.line), int(at.source().begin.column), "", what);
    };
    if (const toml::table* t = n.as_table()) {
        for (const auto& [key, value] : *t) {
            if (const std::size_t length = characters(key.str()); length > max_key_length)
                refuse(value, "a key of " + std::to_string(length) + " characters; keys are at most " +
                                  std::to_string(max_key_length));
            bound_texts(path, value);
        }
    } else if (const toml::array* a = n.as_array()) {
        for (const toml::node& value : *a) bound_texts(path, value);
    } else if (const auto* s = n.as_string()) {
        if (const std::size_t length = characters(s->get()); length > max_text_length)
            refuse(n, "a text of " + std::to_string(length) + " characters; texts are at most " +
                          std::to_string(max_text_length) + " (a lesson's longest summary is about 700)");
    }
}

toml::table parse_bounded(const std::string& path, std::string_view text) {
    toml::table t = parse(path, text);
    bound_texts(path, t);
    return t;
}

}  // namespace

LoadError::LoadError(std::string file_, int line_, int column_, std::string field_, std::string message_)
    : std::runtime_error(where(file_, line_, column_, field_, message_)),
      file(std::move(file_)), field(std::move(field_)), message(std::move(message_)), line(line_), column(column_) {}

std::string join(const std::string& field, std::string_view key) {
    return field.empty() ? std::string(key) : field + "." + std::string(key);
}
std::string index(const std::string& field, std::size_t i) { return field + "[" + std::to_string(i) + "]"; }

TomlReader::TomlReader(std::string path) : path_(std::move(path)), root_(parse_bounded(path_, read_input_file(path_))) {}
TomlReader::TomlReader(std::string path, std::string_view text) : path_(std::move(path)), root_(parse_bounded(path_, text)) {}

void TomlReader::fail(const toml::node* at, const std::string& field, const std::string& message) const {
    const auto& src = at ? at->source() : root_.source();
    throw LoadError(path_, int(src.begin.line), int(src.begin.column), field, message);
}

bool TomlReader::forget(const std::string& field) {
    toml::table* table = &root_;
    std::size_t at = 0;
    while (at < field.size()) {
        const std::size_t end = std::min(field.find('.', at), field.size()), bracket = field.find('[', at);
        if (bracket < end) {  // key[i]: the element goes, with everything under it
            toml::array* a = table->get_as<toml::array>(field.substr(at, bracket - at));
            const std::size_t i = std::strtoul(field.c_str() + bracket + 1, nullptr, 10);
            if (!a || i >= a->size()) return false;
            a->erase(a->begin() + std::ptrdiff_t(i));
            return true;
        }
        const std::string key = field.substr(at, end - at);
        if (end == field.size()) return table->erase(key) > 0;
        table = table->get_as<toml::table>(key);
        if (!table) return false;
        at = end + 1;
    }
    return false;
}

void TomlReader::only_keys(const toml::table& t, const std::string& field,
                           std::initializer_list<std::string_view> keys) const {
    for (const auto& [key, node] : t) {
        if (std::find(keys.begin(), keys.end(), key.str()) != keys.end()) continue;
        std::string known;
        for (auto k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
        fail(&node, join(field, key.str()), "unknown field; expected one of: " + known);
    }
}

std::string TomlReader::text(const toml::table& t, std::string_view key, const std::string& field,
                             std::optional<std::string> fallback) const {
    const toml::node* n = t.get(key);
    if (!n) {
        if (fallback) return *fallback;
        fail(&t, join(field, key), "missing; expected a string");
    }
    if (auto s = n->value<std::string>()) return *s;
    fail(n, join(field, key), "expected a string");
}

double TomlReader::number(const toml::table& t, std::string_view key, const std::string& field,
                          std::optional<double> fallback) const {
    const toml::node* n = t.get(key);
    if (!n) {
        if (fallback) return *fallback;
        fail(&t, join(field, key), "missing; expected a number");
    }
    if (!n->is_number()) fail(n, join(field, key), "expected a number");
    const double v = n->value<double>().value_or(0.0);
    if (!std::isfinite(v)) fail(n, join(field, key), "expected a finite number, got " + std::to_string(v));
    return v;
}

std::int64_t TomlReader::integer(const toml::table& t, std::string_view key, const std::string& field,
                                 std::optional<std::int64_t> fallback) const {
    const toml::node* n = t.get(key);
    if (!n) {
        if (fallback) return *fallback;
        fail(&t, join(field, key), "missing; expected an integer");
    }
    if (auto v = n->value_exact<std::int64_t>()) return *v;
    fail(n, join(field, key), "expected an integer");
}

bool TomlReader::boolean(const toml::table& t, std::string_view key, const std::string& field, std::optional<bool> fallback) const {
    const toml::node* n = t.get(key);
    if (!n) {
        if (fallback) return *fallback;
        fail(&t, join(field, key), "missing; expected true or false");
    }
    if (auto v = n->value_exact<bool>()) return *v;
    fail(n, join(field, key), "expected true or false");
}

glm::dvec4 TomlReader::vector(const toml::node& n, const std::string& field, std::size_t min_size,
                              std::size_t max_size) const {
    const auto expected = "expected an array of " +
                          (min_size == max_size ? std::to_string(min_size)
                                                : std::to_string(min_size) + " or " + std::to_string(max_size)) +
                          " numbers";
    const toml::array* a = n.as_array();
    if (!a || a->size() < min_size || a->size() > max_size) fail(&n, field, expected);
    glm::dvec4 v{0, 0, 0, 1};
    for (std::size_t i = 0; i < a->size(); ++i) {
        const toml::node& c = *a->get(i);
        if (!c.is_number()) fail(&c, index(field, i), "expected a number");
        v[int(i)] = c.value<double>().value_or(0.0);
        if (!std::isfinite(v[int(i)])) fail(&c, index(field, i), "expected a finite number (NaN and inf are refused)");
    }
    return v;
}

const toml::array* TomlReader::array(const toml::table& t, std::string_view key, const std::string& field,
                                     bool required) const {
    const toml::node* n = t.get(key);
    if (!n) {
        if (required) fail(&t, join(field, key), "missing; expected an array");
        return nullptr;
    }
    if (!n->is_array()) fail(n, join(field, key), "expected an array");
    return n->as_array();
}

const toml::table* TomlReader::table(const toml::table& t, std::string_view key, const std::string& field,
                                     bool required) const {
    const toml::node* n = t.get(key);
    if (!n) {
        if (required) fail(&t, join(field, key), "missing; expected a table");
        return nullptr;
    }
    if (!n->is_table()) fail(n, join(field, key), "expected a table");
    return n->as_table();
}

std::vector<std::string> TomlReader::strings(const toml::table& t, std::string_view key,
                                             const std::string& field) const {
    std::vector<std::string> out;
    const toml::array* a = array(t, key, field, false);
    if (!a) return out;
    for (std::size_t i = 0; i < a->size(); ++i) {
        auto s = a->get(i)->value<std::string>();
        if (!s) fail(a->get(i), index(join(field, key), i), "expected a string");
        out.push_back(*s);
    }
    return out;
}

}  // namespace hsr::algo
