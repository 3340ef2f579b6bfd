// SPDX-License-Identifier: MIT
#include "state/window_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "scene/input_file.h"
#include "scene/toml_reader.h"

namespace hsr::viz {

std::string window_settings_path() {
    if (const char* p = std::getenv("HSRVIZ_CONFIG"); p && *p) return p;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/hsrviz/window.toml";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/hsrviz/window.toml";
    return "hsrviz-window.toml";
}

namespace {

constexpr std::size_t settings_limit = 64 << 10;  // a settings file is a few lines
const std::vector<std::string_view> settings_keys{"width", "height", "x", "y", "side", "maximized", "language", "type_size", "practice"};

// The first key a settings file does not have, if any: such a file is someone else's (a lesson, say) and is
// neither used nor overwritten.
std::optional<std::string> foreign_key(const toml::table& t) {
    for (const auto& [key, value] : t)
        if (std::find(settings_keys.begin(), settings_keys.end(), key.str()) == settings_keys.end()) return std::string(key.str());
    return std::nullopt;
}

}  // namespace

WindowSettings read_window_settings(const std::string& path, std::string& warning) {
    warning.clear();
    WindowSettings s;
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)) && !std::filesystem::exists(path, ec)) return s;
    toml::table t;
    try {
        t = toml::parse(algo::read_input_file(path, settings_limit), path);
    } catch (const algo::LoadError& e) {  // not a regular file, too large, empty: not ours to read or replace
        warning = algo::printable(path) + ": " + e.message + "; using the defaults, and the settings are not saved there";
        return s;
    } catch (const toml::parse_error& e) {  // a broken settings file is kept beside, never silently replaced
        const std::string kept = path + ".bak";
        std::filesystem::rename(path, kept, ec);
        warning = algo::printable(path) + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()) +
                  (ec ? "; using the defaults (it could not be kept aside: " + ec.message() + ")"
                      : "; kept as " + algo::printable(kept) + ", using the defaults");
        return s;
    }
    if (const auto key = foreign_key(t)) {
        warning = algo::printable(path) + " is not an hsrviz settings file (it has '" + algo::printable(*key, 60) +
                  "'); it is left alone: the defaults are used and the settings are not saved there";
        return s;
    }
    // Each field on its own: a bad one is skipped and named, the rest still used.
    const auto integer = [&](const char* key, int lo, int hi) -> std::optional<int> {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        // exact: toml++ converting a float such as 1.5e21 to an integer is undefined behaviour (found by fuzz_settings)
        const auto v = n->value_exact<std::int64_t>();
        if (v && *v >= lo && *v <= hi) return int(*v);
        warning = path + ":" + std::to_string(n->source().begin.line) + ": field '" + key + "': expected a whole number from " +
                  std::to_string(lo) + " to " + std::to_string(hi) + "; ignored";
        return std::nullopt;
    };
    if (const auto w = integer("width", 320, 16384)) s.width = *w;
    if (const auto h = integer("height", 240, 16384)) s.height = *h;
    s.x = integer("x", -16384, 16384);
    s.y = integer("y", -16384, 16384);
    if (const auto side = integer("side", 200, 4000)) s.side = float(*side);
    if (const auto m = t["maximized"].value<bool>()) s.maximized = *m;
    if (const auto l = t["language"].value<std::string>(); l && l->size() <= 16) s.language = *l;
    if (const auto percent = integer("type_size", 50, 400)) s.scale = float(*percent) / 100;
    // [practice.TOPIC] answered, right, best_streak: a topic with a bad field is skipped and named
    if (const toml::table* practice = t["practice"].as_table())
        for (const auto& [topic, node] : *practice) {
            const toml::table* record = node.as_table();
            const std::string name(topic.str());
            const bool named_well = !name.empty() && name.size() <= 32 &&
                                    std::all_of(name.begin(), name.end(), [](char c) { return (c >= 'a' && c <= 'z') || c == '_'; });
            const auto count = [&](const char* key) -> std::optional<int> {
                const auto v = record ? (*record)[key].value_exact<std::int64_t>() : std::nullopt;
                return v && *v >= 0 && *v <= 1'000'000'000 ? std::optional<int>(int(*v)) : std::nullopt;
            };
            const auto answered = count("answered"), right = count("right"), best = count("best_streak");
            if (!named_well || !answered || !right || !best || *right > *answered || *best > *right) {
                warning = path + ":" + std::to_string(node.source().begin.line) + ": field 'practice." + algo::printable(name, 40) +
                          "': expected answered ≥ right ≥ best_streak, whole numbers; ignored";
                continue;
            }
            s.practice[name] = {*answered, *right, *best};
        }
    return s;
}

std::string write_window_settings(const std::string& path, const WindowSettings& s) {
    std::error_code ec;
    const std::filesystem::path file(path);
    if (std::filesystem::exists(file, ec)) {  // only a settings file is replaced: never a lesson, a FIFO or a folder
        try {
            if (const auto key = foreign_key(toml::parse(algo::read_input_file(path, settings_limit), path)))
                return path + " is not an hsrviz settings file (it has '" + algo::printable(*key, 60) + "'); left alone";
        } catch (const std::exception&) {
            return path + " is not an hsrviz settings file; left alone";
        }
    }
    if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path(), ec);
    toml::table t{{"width", s.width}, {"height", s.height}, {"maximized", s.maximized}, {"side", int(s.side)}, {"language", s.language}};
    if (s.x) t.insert("x", *s.x);
    if (s.y) t.insert("y", *s.y);
    if (s.scale) t.insert("type_size", int(std::lround(*s.scale * 100)));  // in percent: a number a person reads
    if (!s.practice.empty()) {
        toml::table practice;
        for (const auto& [topic, r] : s.practice)
            practice.insert(topic, toml::table{{"answered", r.answered}, {"right", r.right}, {"best_streak", r.best_streak}});
        t.insert("practice", std::move(practice));
    }
    // A new file, then renamed over the old one: a full disk or a crash mid-write leaves the old settings whole.
    const std::string temporary = path + ".new";
    {
        std::ofstream f(temporary, std::ios::trunc);
        f << "# hsrviz remembers the window here between runs; delete the file to start afresh.\n" << t << '\n';
        if (!f.flush()) {
            std::filesystem::remove(temporary, ec);
            return "cannot write " + temporary;
        }
    }
    std::filesystem::rename(temporary, file, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return "cannot replace " + path;
    }
    return "";
}

float clamp_side(float side, float window_width) { return std::clamp(side, 320.0f, std::max(320.0f, window_width - 320.0f)); }

}  // namespace hsr::viz
