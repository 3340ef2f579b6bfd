// SPDX-License-Identifier: MIT
// Reading hand-written TOML with errors a teacher can act on: every failure names the file, the line and column,
// the field (a dotted path such as "segments[2].a") and what was expected. Shared by scene and lesson loading.
#pragma once

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec4.hpp>
#include <toml++/toml.h>

namespace hsr::algo {

class LoadError : public std::runtime_error {
public:
    LoadError(std::string file, int line, int column, std::string field, std::string message);
    const std::string file, field, message;
    const int line, column;
};

// Far above any real lesson (its longest text is about 700 characters), far below what the window cannot draw.
inline constexpr std::size_t max_text_length = 4000, max_key_length = 100;

class TomlReader {
public:
    // Parses the file; a syntax error, a file that is not a regular file of text or a text beyond the bounds
    // above is a LoadError.
    explicit TomlReader(std::string path);
    // Parses text as if it came from `path` (for tests and editors).
    TomlReader(std::string path, std::string_view text);

    const toml::table& root() const { return root_; }
    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const toml::node* at, const std::string& field, const std::string& message) const;
    // Removes what a field path names ("camera.fov"; for "polygons[2].vertices[0]", the whole of polygons[2]), so
    // that reading again finds the problems after it: `check` reports every problem of a file, not only the first.
    // False when the path names nothing that can be removed.
    bool forget(const std::string& field);

    // Each rejects keys a table does not know ("did you mean …" is left to the list of known keys it prints).
    void only_keys(const toml::table& t, const std::string& field, std::initializer_list<std::string_view> keys) const;

    std::string text(const toml::table& t, std::string_view key, const std::string& field,
                     std::optional<std::string> fallback = std::nullopt) const;
    double number(const toml::table& t, std::string_view key, const std::string& field,
                  std::optional<double> fallback = std::nullopt) const;
    std::int64_t integer(const toml::table& t, std::string_view key, const std::string& field,
                         std::optional<std::int64_t> fallback = std::nullopt) const;
    bool boolean(const toml::table& t, std::string_view key, const std::string& field, std::optional<bool> fallback = std::nullopt) const;
    // A vector of `size` finite numbers (3 or 4); a 3-vector gets w = 1.
    glm::dvec4 vector(const toml::node& n, const std::string& field, std::size_t min_size, std::size_t max_size) const;
    const toml::array* array(const toml::table& t, std::string_view key, const std::string& field,
                             bool required) const;
    const toml::table* table(const toml::table& t, std::string_view key, const std::string& field,
                             bool required) const;
    std::vector<std::string> strings(const toml::table& t, std::string_view key, const std::string& field) const;

private:
    std::string path_;
    toml::table root_;
};

std::string join(const std::string& field, std::string_view key);  // "camera" + "eye" → "camera.eye"
std::string index(const std::string& field, std::size_t i);        // "segments" + 2 → "segments[2]"

}  // namespace hsr::algo
