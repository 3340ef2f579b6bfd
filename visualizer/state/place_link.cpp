// SPDX-License-Identifier: MIT
#include "state/place_link.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>

#include "state/lesson.h"

namespace hsr::viz {

namespace {

// A lesson's name is a file's stem: letters, digits, '_' and '-' only (never a path: "../" cannot reach other files)
bool lesson_name(std::string_view s) {
    return !s.empty() && s.size() <= 100 &&
           std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; });
}

void add(std::string& problems, const std::string& problem) { problems += (problems.empty() ? "" : "; ") + problem; }

}  // namespace

PlaceLink read_place_link(std::string_view fragment, std::string& problems) {
    PlaceLink link;
    if (!fragment.empty() && fragment.front() == '#') fragment.remove_prefix(1);
    while (!fragment.empty()) {
        const std::size_t amp = fragment.find('&');
        const std::string_view part = fragment.substr(0, amp);
        fragment = amp == std::string_view::npos ? std::string_view() : fragment.substr(amp + 1);
        if (part.empty()) continue;
        const std::size_t eq = part.find('=');
        const std::string_view key = part.substr(0, eq), value = eq == std::string_view::npos ? std::string_view() : part.substr(eq + 1);
        const std::string shown(part.substr(0, 60));
        if (key == "lesson") {
            if (lesson_name(value)) link.lesson = value;
            else add(problems, shown + ": not a lesson's name (its file's name without .toml, as 05_bsp_traversal)");
        } else if (key == "step") {
            std::size_t step = 0;
            const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), step);
            if (error == std::errc() && end == value.data() + value.size() && !value.empty()) link.step = step;
            else add(problems, shown + ": not a step number");
        } else if (key == "lang") {
            if (value.size() >= 2 && value.size() <= 8 && std::all_of(value.begin(), value.end(), [](char c) { return std::islower(static_cast<unsigned char>(c)); }))
                link.language = value;
            else add(problems, shown + ": not a language code (as de)");
        } else if (key == "projector" && value.empty()) {
            link.projector = true;
        } else {
            add(problems, shown + ": unknown (a link knows lesson, step, lang and projector)");
        }
    }
    return link;
}

std::string place_link(const std::string& lesson, std::size_t step) { return "#lesson=" + lesson + "&step=" + std::to_string(step); }

std::string linked_lesson_name(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path file(path), lessons = fs::path(data_dir()) / "lessons";
    if (file.extension() != ".toml" || !lesson_name(file.stem().string())) return {};
    return fs::equivalent(file.parent_path(), lessons, ec) && !ec ? file.stem().string() : std::string();
}

std::string linked_lesson_path(const std::string& name) { return data_dir() + "/lessons/" + name + ".toml"; }

}  // namespace hsr::viz
