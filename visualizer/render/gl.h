// SPDX-License-Identifier: MIT
// OpenGL 3.3 core without a loader library: the prototypes come from glcorearb.h, the symbols from libOpenGL.
#pragma once
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
