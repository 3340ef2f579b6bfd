// SPDX-License-Identifier: MIT
// Where commands and the window write their files.
#pragma once

#include <string>

namespace hsr::viz {

// Makes a folder (and its parents); false, having said why on stderr, when it cannot be made.
bool make_folder(const std::string& dir);

}  // namespace hsr::viz
