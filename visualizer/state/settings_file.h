// SPDX-License-Identifier: MIT
// Replacing a small file in place without ever writing through something that is not ours: the new text goes to a
// temporary file made with O_EXCL in the same folder (never a name a FIFO, a link or another program's file holds),
// then is renamed over the old one, so a full disk or a crash leaves the old file whole.
#pragma once

#include <string>

namespace hsr::viz {

// Writes `text` to `path` through a fresh temporary file: "" when written, else why not (nothing left behind).
std::string replace_file(const std::string& path, const std::string& text);

// Moves `path` aside to PATH.bak, never over a file there: the name it now has, or "" when it could not be moved
// (`why` then says why).
std::string keep_aside(const std::string& path, std::string& why);

}  // namespace hsr::viz
