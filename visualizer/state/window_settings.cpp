#include "state/window_settings.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <toml++/toml.h>

namespace hsr::viz {

std::string window_settings_path() {
    if (const char* p = std::getenv("HSRVIZ_CONFIG"); p && *p) return p;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/hsrviz/window.toml";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/hsrviz/window.toml";
    return "hsrviz-window.toml";
}

WindowSettings read_window_settings(const std::string& path, std::string& warning) {
    warning.clear();
    WindowSettings s;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return s;
    toml::table t;
    try {
        t = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        warning = path + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()) + "; using the defaults";
        return s;
    }
    // Each field on its own: a bad one is skipped and named, the rest still used.
    const auto integer = [&](const char* key, int lo, int hi) -> std::optional<int> {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        const auto v = n->value<std::int64_t>();
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
    if (const auto l = t["language"].value<std::string>()) s.language = *l;
    return s;
}

bool write_window_settings(const std::string& path, const WindowSettings& s) {
    std::error_code ec;
    const auto dir = std::filesystem::path(path).parent_path();
    if (!dir.empty()) std::filesystem::create_directories(dir, ec);
    toml::table t{{"width", s.width}, {"height", s.height}, {"maximized", s.maximized}, {"side", int(s.side)}, {"language", s.language}};
    if (s.x) t.insert("x", *s.x);
    if (s.y) t.insert("y", *s.y);
    std::ofstream f(path);
    f << "# hsrviz remembers the window here between runs; delete the file to start afresh.\n" << t << '\n';
    return static_cast<bool>(f);
}

float clamp_side(float side, float window_width) { return std::clamp(side, 320.0f, std::max(320.0f, window_width - 320.0f)); }

}  // namespace hsr::viz
