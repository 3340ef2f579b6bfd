// SPDX-License-Identifier: MIT
// Where commands and the window write their files, and writing them whole.
#pragma once

#include <string>

namespace hsr::viz {

// Makes a folder (and its parents); false, having said why on stderr, when it cannot be made.
bool make_folder(const std::string& dir);

// Writes `text` to `path` whole: "" when written, else "cannot write PATH: REASON", with no partial file left
// behind (a full disk that took half of it).
std::string write_whole_file(const std::string& path, const std::string& text);

// "" when a file could probably be written at `path` (a folder there, or a folder that does not let us in, says no),
// else why not: asked before minutes of work whose result would be written there.
std::string why_not_writable(const std::string& path);

// Where the window puts a folder of its files (`name`: hsrviz-export for E, S and random scenes, hsrviz-out for the
// no-display fallback): in the current directory, as someone who started it from a shell expects, unless that is
// the home folder (where a program started from the desktop menu starts: exports would litter it) or cannot be
// written; then under $XDG_DATA_HOME/hsrviz (~/.local/share/hsrviz). HSRVIZ_OUTPUT=DIR puts it in DIR instead.
std::string output_folder(const std::string& name);

}  // namespace hsr::viz
