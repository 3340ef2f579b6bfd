// SPDX-License-Identifier: MIT
// The browser build's <GL/glcorearb.h> (render/gl.h includes it): OpenGL ES 3.0, which WebGL 2 is. The window uses
// only what the two share (platform.h tells the code which one it runs on).
#pragma once
#include <GLES3/gl3.h>
#ifndef GL_PROGRAM_POINT_SIZE
#define GL_PROGRAM_POINT_SIZE 0x8642  // desktop-only; the window enables it only on the desktop (gl_profile().es)
#endif
