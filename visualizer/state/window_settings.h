// SPDX-License-Identifier: MIT
// What the window remembers between runs: its size and place, whether it was maximised, the width of the panel
// column, the narration language, the type's size and the practice scores. One small TOML file in the user's configuration folder; a missing or broken
// file gives the defaults (and a warning naming the file, line and field), never an error.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace hsr::viz {

// A practice topic's score, kept between runs (the streak starts again each run; its best is kept).
struct PracticeRecord {
    int answered = 0, right = 0, best_streak = 0;
    bool operator==(const PracticeRecord&) const = default;
};

struct WindowSettings {
    int width = 1280, height = 800;
    std::optional<int> x, y;  // the window's place on the desktop; centred when absent
    bool maximized = false;
    float side = 500;         // the panel column's width, in points
    std::string language;     // the narration language last chosen ("" for the lesson's first)
    std::optional<float> scale;  // the type's size last chosen with Ctrl+± (absent: the screen's), 0.5 … 4; kept in
                                 // whole percent (type_size = 110)
    std::map<std::string, PracticeRecord> practice;  // by topic id ([practice.TOPIC] tables)
    bool operator==(const WindowSettings&) const = default;
};

// $HSRVIZ_CONFIG if set, else $XDG_CONFIG_HOME/hsrviz/window.toml, else ~/.config/hsrviz/window.toml.
std::string window_settings_path();
// The settings in `path`; `warning` gets why a file there was not used, or each field that was not (empty when all
// were, or when there is no file). Only a file hsrviz wrote is ever moved or replaced: one that no longer parses is
// kept as PATH.bak (never over a PATH.bak that exists) and said in the warning; anything else (a lesson, a file that
// is not TOML, a symbolic link, a FIFO, a folder) is read as nothing and left alone.
WindowSettings read_window_settings(const std::string& path, std::string& warning);
// Writes them (making the folder) through a new file of its own (O_EXCL, beside it) renamed over the old one, and
// only over nothing, an empty file or a settings file: "" when written, else why not.
std::string write_window_settings(const std::string& path, const WindowSettings& s);
// The column width kept within a window: at least 320 points, and at least 320 left for the view.
float clamp_side(float side, float window_width);

}  // namespace hsr::viz
