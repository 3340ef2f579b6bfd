// SPDX-License-Identifier: MIT
#include "state/window_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "scene/input_file.h"
#include "scene/toml_reader.h"
#include "state/settings_file.h"

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
constexpr std::string_view header = "# hsrviz remembers the window here between runs; delete the file to start afresh.\n";

// The first key a settings file does not have, if any: such a file is someone else's (a lesson, say) and is
// neither used nor overwritten.
std::optional<std::string> foreign_key(const toml::table& t) {
    for (const auto& [key, value] : t)
        if (std::find(settings_keys.begin(), settings_keys.end(), key.str()) == settings_keys.end()) return std::string(key.str());
    return std::nullopt;
}

// What is at the settings path. Only nothing, an empty file or a settings file may be replaced; a settings file
// hsrviz wrote (it starts with `header`) that no longer parses is kept aside; anything else is left alone.
struct SettingsFile {
    enum class Kind { absent, empty, settings, broken, foreign } kind = Kind::absent;
    toml::table table;  // settings
    std::string why;    // broken, foreign: "PATH: …" or "PATH:LINE: …"
};

SettingsFile inspect(const std::string& path) {
    using Kind = SettingsFile::Kind;
    std::error_code ec;
    const auto status = std::filesystem::symlink_status(path, ec);
    if (!std::filesystem::exists(status)) return {};
    if (std::filesystem::is_symlink(status))  // its target may be anyone's: never read through nor written over
        return {Kind::foreign, {}, algo::printable(path) + " is a symbolic link"};
    std::string text;
    try {
        if (std::filesystem::is_regular_file(status) && std::filesystem::file_size(path, ec) == 0 && !ec) return {Kind::empty, {}, ""};
        text = algo::read_input_file(path, settings_limit);
    } catch (const algo::LoadError& e) {  // not a regular file, too large: not ours to read or replace
        return {Kind::foreign, {}, algo::printable(path) + ": " + e.message};
    }
    try {
        toml::table t = toml::parse(text, path);
        if (const auto key = foreign_key(t))
            return {Kind::foreign, {}, algo::printable(path) + " is not an hsrviz settings file (it has '" + algo::printable(*key, 60) + "')"};
        return {Kind::settings, std::move(t), ""};
    } catch (const toml::parse_error& e) {
        const std::string where = algo::printable(path) + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description());
        if (text.rfind(header, 0) == 0) return {Kind::broken, {}, where};
        return {Kind::foreign, {}, where + " (it is not an hsrviz settings file)"};
    }
}

}  // namespace

WindowSettings read_window_settings(const std::string& path, std::string& warning) {
    using Kind = SettingsFile::Kind;
    warning.clear();
    WindowSettings s;
    SettingsFile file = inspect(path);
    if (file.kind == Kind::absent || file.kind == Kind::empty) return s;
    if (file.kind == Kind::foreign) {
        warning = file.why + "; it is left alone: the defaults are used and the settings are not saved there";
        return s;
    }
    if (file.kind == Kind::broken) {  // a settings file of ours, broken: kept beside, never silently replaced
        std::string why;
        const std::string kept = keep_aside(path, why);
        warning = file.why + (kept.empty() ? "; it is left as it is (it could not be kept aside: " + algo::printable(why) +
                                                 "): the defaults are used and the settings are not saved there"
                                           : "; kept as " + algo::printable(kept) + ", using the defaults");
        return s;
    }
    const toml::table& t = file.table;
    // Each field on its own: a bad one is skipped and named (every one of them), the rest still used.
    const auto add = [&](const std::string& w) { warning += (warning.empty() ? "" : "\n  ") + w; };
    const auto integer = [&](const char* key, int lo, int hi) -> std::optional<int> {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        // exact: toml++ converting a float such as 1.5e21 to an integer is undefined behaviour (found by fuzz_settings)
        const auto v = n->value_exact<std::int64_t>();
        if (v && *v >= lo && *v <= hi) return int(*v);
        add(algo::printable(path) + ":" + std::to_string(n->source().begin.line) + ": field '" + key + "': expected a whole number from " +
            std::to_string(lo) + " to " + std::to_string(hi) + "; ignored (and left out when the settings are saved again)");
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
    // [practice.TOPIC] answered, right, best_streak: a topic with a bad field is skipped and named, each of them, and
    // kept in the file as it is when the settings are saved (write_window_settings copies what it did not read)
    if (const toml::node* p = t.get("practice"); p && !p->is_table())
        add(algo::printable(path) + ":" + std::to_string(p->source().begin.line) +
            ": field 'practice': expected tables [practice.TOPIC]; ignored (and left out when the settings are saved again)");
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
                add(algo::printable(path) + ":" + std::to_string(node.source().begin.line) + ": field 'practice." + algo::printable(name, 40) +
                    "': expected answered ≥ right ≥ best_streak, whole numbers; ignored, and kept in the file as it is (practising " +
                    (named_well ? "this topic" : "anything") + " in this window " + (named_well ? "starts it afresh" : "leaves it there") + ")");
                continue;
            }
            s.practice[name] = {*answered, *right, *best};
        }
    return s;
}

std::string write_window_settings(const std::string& path, const WindowSettings& s) {
    using Kind = SettingsFile::Kind;
    std::error_code ec;
    const std::filesystem::path file(path);
    // only nothing, an empty file or a settings file is replaced: never a lesson, a link, a FIFO or a folder
    const SettingsFile there = inspect(path);
    if (there.kind == Kind::foreign || there.kind == Kind::broken) return there.why + "; left alone";
    if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path(), ec);
    toml::table t{{"width", s.width}, {"height", s.height}, {"maximized", s.maximized}, {"side", int(s.side)}, {"language", s.language}};
    if (s.x) t.insert("x", *s.x);
    if (s.y) t.insert("y", *s.y);
    if (s.scale) t.insert("type_size", int(std::lround(*s.scale * 100)));  // in percent: a number a person reads
    toml::table practice;
    for (const auto& [topic, r] : s.practice)
        practice.insert(topic, toml::table{{"answered", r.answered}, {"right", r.right}, {"best_streak", r.best_streak}});
    // the records this run did not hold (ones read as bad, and named then; or another window's) are kept as they were
    if (const toml::table* old = there.kind == Kind::settings ? there.table["practice"].as_table() : nullptr)
        for (const auto& [topic, node] : *old)
            if (!practice.contains(topic.str())) practice.insert(topic, node);
    if (!practice.empty()) t.insert("practice", std::move(practice));
    // A new file of its own, then renamed over the old one: a full disk or a crash mid-write leaves the old settings whole.
    std::ostringstream text;
    text << header << t << '\n';
    return replace_file(path, text.str());
}

float clamp_side(float side, float window_width) { return std::clamp(side, 320.0f, std::max(320.0f, window_width - 320.0f)); }

}  // namespace hsr::viz
