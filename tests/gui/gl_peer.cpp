// SPDX-License-Identifier: MIT
#include "gl_peer.h"

#include <algorithm>
#include <chrono>
#include <functional>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include "analysis/measurement.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::test {

using namespace hsr::algo;

namespace {

using analysis::median_ms;

GLuint shader(GLenum type, const char* source) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    return s;
}

}  // namespace

GlContext::GlContext(int width, int height) {
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return;
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    window = SDL_CreateWindow("gl_peer", 0, 0, width, height, SDL_WINDOW_OPENGL | SDL_WINDOW_HIDDEN);
    context = window ? SDL_GL_CreateContext(window) : nullptr;
}

GlContext::~GlContext() {
    if (context) SDL_GL_DeleteContext(context);
    if (window) SDL_DestroyWindow(window);
    SDL_Quit();
}

const char* GlContext::renderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }

// Index + 1 per pixel (0 for background), rows top first, from GL.
std::vector<int> gl_ids(const std::vector<Triangle>& tris, int width, int height, double* draw_ms, int repeats) {
    GLuint fbo, colour, depth;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    const GLuint program = glCreateProgram();
    glAttachShader(program, shader(GL_VERTEX_SHADER, "#version 330 core\nlayout(location = 0) in vec4 p; layout(location = 1) in vec3 c;\n"
                                                      "flat out vec3 colour; void main() { gl_Position = p; colour = c; }\n"));
    glAttachShader(program, shader(GL_FRAGMENT_SHADER, "#version 330 core\nflat in vec3 colour; out vec4 o;\n"
                                                        "void main() { o = vec4(colour, 1); }\n"));
    glLinkProgram(program);
    std::vector<float> data;
    for (std::size_t k = 0; k < tris.size(); ++k)
        for (const auto& v : tris[k].v) {
            const int id = int(k) + 1;
            data.insert(data.end(), {float(v.x), float(v.y), float(v.z), float(v.w), float(id & 255) / 255.f,
                                     float((id >> 8) & 255) / 255.f, float((id >> 16) & 255) / 255.f});
        }
    GLuint vao, vbo;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), reinterpret_cast<void*>(4 * sizeof(float)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glViewport(0, 0, width, height);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(program);
    const auto draw = [&] {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(tris.size() * 3));
        glFinish();
    };
    draw();  // the first draw compiles the shaders into llvmpipe's code: not timed
    const double ms = median_ms(repeats, draw);
    if (draw_ms) *draw_ms = ms;
    std::vector<unsigned char> rgba(std::size_t(width * height * 4));
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    std::vector<int> ids(std::size_t(width * height));
    for (int y = 0; y < height; ++y)  // GL's rows go up; ours go down
        for (int x = 0; x < width; ++x) {
            const unsigned char* c = &rgba[std::size_t(((height - 1 - y) * width + x) * 4)];
            ids[std::size_t(y * width + x)] = c[0] | (c[1] << 8) | (c[2] << 16);
        }
    return ids;
}

std::vector<int> our_ids(const std::vector<Triangle>& tris, int width, int height, double* fill_ms, int repeats) {
    FrameDepth f{Image(0, 0), {}, {}};
    // given in clip space, as OpenGL's buffer is (uploaded before its timing)
    std::vector<ClipSpacePolygon> clip;
    for (std::size_t k = 0; k < tris.size(); ++k) clip.push_back({SceneId(k + 1), {}, {tris[k].v[0], tris[k].v[1], tris[k].v[2]}});
    const double ms = median_ms(repeats, [&] {
        f = zbuffer_fill(project_polygons(clip, {width, height}), {.viewport = {width, height}, .format = DepthFormat::int24, .range = {1, 10},
                                            .perspective = true, .detail = EventDetail::polygon})
                .run_to_end();
    });
    if (fill_ms) *fill_ms = ms;
    std::vector<int> ids;
    for (auto i : f.image.ids) ids.push_back(i);
    return ids;
}


}  // namespace hsr::test
