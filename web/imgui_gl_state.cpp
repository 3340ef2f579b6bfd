// SPDX-License-Identifier: MIT
// The GL state the window leaves when Dear ImGui's backend draws the panels, answered without asking WebGL (see
// web/compat/imgui_gl_state.h). The frame (visualizer/app.cpp, render/line_batch.cpp) draws its view, then unbinds
// its program and vertex array, leaves blending on (alpha over) and the depth test off, and sets the viewport again
// at the start of the next frame; so what the backend restores afterwards is what is said here. Anything else is
// asked of GL as before (the backend's start-up queries: version, extensions).
#include <GLES3/gl3.h>

extern "C" void hsr_imgui_get_integerv(unsigned int pname, int* data) {
    switch (pname) {
        case GL_ACTIVE_TEXTURE: *data = GL_TEXTURE0; return;
        case GL_CURRENT_PROGRAM:
        case GL_TEXTURE_BINDING_2D:
        case GL_ARRAY_BUFFER_BINDING:
        case GL_VERTEX_ARRAY_BINDING: *data = 0; return;
        case GL_VIEWPORT:
        case GL_SCISSOR_BOX: data[0] = data[1] = data[2] = data[3] = 0; return;  // set again before they are used
        case GL_BLEND_SRC_RGB:
        case GL_BLEND_SRC_ALPHA: *data = GL_SRC_ALPHA; return;
        case GL_BLEND_DST_RGB:
        case GL_BLEND_DST_ALPHA: *data = GL_ONE_MINUS_SRC_ALPHA; return;
        case GL_BLEND_EQUATION_RGB:
        case GL_BLEND_EQUATION_ALPHA: *data = GL_FUNC_ADD; return;
        default: glGetIntegerv(pname, data);
    }
}

extern "C" unsigned char hsr_imgui_is_enabled(unsigned int capability) {
    switch (capability) {
        case GL_BLEND: return GL_TRUE;
        case GL_CULL_FACE:
        case GL_DEPTH_TEST:
        case GL_STENCIL_TEST:
        case GL_SCISSOR_TEST: return GL_FALSE;
        default: return glIsEnabled(capability);
    }
}
