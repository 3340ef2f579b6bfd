// SPDX-License-Identifier: MIT
// The implementations the desktop build links from Debian's libraries and the browser build compiles here from the
// same headers: stb's PNG writer (libstb on the desktop) and tinyobjloader with doubles (libtinyobjloader).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
