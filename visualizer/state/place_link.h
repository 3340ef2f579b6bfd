// SPDX-License-Identifier: MIT
// A link to a moment of a lesson, as the page's address carries it: #lesson=05_bsp_traversal&step=12, and optionally
// &lang=de (the narration's language) and &projector (large type for a classroom). A teacher copies the address of
// the page where the class should look; opening it opens that lesson at that step.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace hsr::viz {

struct PlaceLink {
    std::string lesson;               // a shipped lesson's name, its file's stem ("05_bsp_traversal"); "" for the default
    std::optional<std::size_t> step;  // where to open it
    std::string language;             // "" for the one last chosen
    bool projector = false;
};

// Reads an address's fragment ("#lesson=…&step=…", with or without the '#'). Parts it cannot use are left out and
// named in `problems` ("step=abc: not a step number"), so that a mistyped link still opens the lesson it can.
PlaceLink read_place_link(std::string_view fragment, std::string& problems);

// The fragment for a lesson and a step: "#lesson=05_bsp_traversal&step=12".
std::string place_link(const std::string& lesson, std::size_t step);

// The name a link gives the lesson file `path`: its stem when it is one of the shipped lessons (data_dir()/lessons),
// else "" (a file of the person's own, a preset's scene: no link can name it).
std::string linked_lesson_name(const std::string& path);

// The shipped lesson a link names: data_dir()/lessons/NAME.toml.
std::string linked_lesson_path(const std::string& name);

}  // namespace hsr::viz
