// SPDX-License-Identifier: MIT
// The `f` lines of an OBJ file, counted as tinyobjloader splits them. tinyobjloader keeps every index of a face but
// stores its size as an unsigned char (a face of 400 vertices says 144), so the mesh loader takes the sizes from here
// and tinyobjloader's indices, after checking that the two agree face by face.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace hsr::algo {

struct ObjFace {
    int line = 0;               // the file's line, from 1 ('\n', '\r\n' and a lone '\r' each end one)
    std::size_t vertices = 0;   // the words after 'f', each a vertex (v, v/vt, v//vn or v/vt/vn)
};

// Every face line with 3 or more vertices, in the file's order (tinyobjloader drops the shorter ones).
std::vector<ObjFace> obj_faces(std::string_view text);

}  // namespace hsr::algo
