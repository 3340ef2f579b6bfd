// SPDX-License-Identifier: MIT
// The one door every file a user names comes in by (scenes, lessons, meshes). Only a regular file is read, and
// never more than a limit far above any real lesson: a FIFO, a device, a folder or an endless file is an error
// that says what it is, not a hang, an empty scene or the whole memory. A file that cannot be opened says why
// (the operating system's reason: missing, permission, a symbolic-link loop).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace hsr::algo {

// 64 MiB: the largest shipped scene is a few hundred kB; a mesh of a million triangles as OBJ is about 60 MB.
inline constexpr std::size_t input_file_limit = std::size_t(64) << 20;

// The file's bytes; a LoadError (file, line 0) naming the reason otherwise. An empty file is an error too: no
// scene, lesson or mesh is empty, and an empty file is what an editor leaves when a save went wrong.
std::string read_input_file(const std::string& path, std::size_t limit = input_file_limit);

// Text a terminal or the window can show safely: control characters (escape sequences, carriage returns; not line
// feeds and tabs) as \xNN, and at most `max` characters (… in the middle), so a hostile name cannot rewrite the
// terminal or bury the message.
std::string printable(std::string_view text, std::size_t max = 300);
// A file's name as printable shows it, with its line feeds and tabs as \xNN too: a name is one line.
std::string printable_name(std::string_view name, std::size_t max = 300);

}  // namespace hsr::algo
