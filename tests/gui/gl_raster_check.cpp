// Our z-buffer against OpenGL's rasteriser (Mesa llvmpipe here): the same triangles, the same viewport, each
// drawn in a colour that encodes its index, with GL_LESS on a 24-bit depth buffer. Prints how many pixels differ
// and fails if any does:
//   gl_raster_check mesh      a mesh of triangles with vertices on pixel centres, pixel corners and between
//                             them, covering the viewport: coverage and the fill rule on shared edges
//   gl_raster_check overlap   random overlapping, piercing triangles: coverage and the depth test
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#include <SDL.h>

#include "zbuffer/zbuffer_fill.h"

using namespace hsr::algo;

namespace {

constexpr int width = 64, height = 48;

struct Triangle {
    glm::dvec4 v[3];  // clip space
};

std::vector<Triangle> mesh(std::mt19937& rng) {
    // Grid points snapped to quarter pixels (some on centres, some on corners), in NDC, covering [-1, 1]²
    std::uniform_int_distribution<int> quarter(-2, 2);
    const int nx = 9, ny = 7;
    std::vector<glm::dvec2> p;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            double px = double(i) * width / nx, py = double(j) * height / ny;
            px = std::round(px * 4) / 4 + (i > 0 && i < nx ? quarter(rng) * 0.25 : 0);
            py = std::round(py * 4) / 4 + (j > 0 && j < ny ? quarter(rng) * 0.25 : 0);
            p.emplace_back(px / width * 2 - 1, 1 - py / height * 2);
        }
    const auto at = [&](int i, int j) { return glm::dvec4(p[std::size_t(j * (nx + 1) + i)], 0.0, 1.0); };
    std::vector<Triangle> t;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            t.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
            t.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
        }
    return t;
}

std::vector<Triangle> overlap(std::mt19937& rng) {
    std::uniform_real_distribution<double> xy(-1.3, 1.3), z(-0.9, 0.9), w(0.5, 2);
    std::vector<Triangle> t;
    for (int k = 0; k < 60; ++k) {
        Triangle tri;
        for (auto& v : tri.v) {
            const double ww = w(rng);
            v = {xy(rng) * ww, xy(rng) * ww, z(rng) * ww, ww};
        }
        t.push_back(tri);
    }
    return t;
}

GLuint shader(GLenum type, const char* source) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    return s;
}

// Index + 1 per pixel (0 for background), rows top first, from GL.
std::vector<int> gl_ids(const std::vector<Triangle>& tris) {
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
                                     float((id >> 8) & 255) / 255.f, 0});
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
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(program);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(tris.size() * 3));
    std::vector<unsigned char> rgba(std::size_t(width * height * 4));
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    std::vector<int> ids(std::size_t(width * height));
    for (int y = 0; y < height; ++y)  // GL's rows go up; ours go down
        for (int x = 0; x < width; ++x) {
            const unsigned char* c = &rgba[std::size_t(((height - 1 - y) * width + x) * 4)];
            ids[std::size_t(y * width + x)] = c[0] | (c[1] << 8);
        }
    return ids;
}

std::vector<int> our_ids(const std::vector<Triangle>& tris) {
    std::vector<ScreenPolygon> polys;
    for (std::size_t k = 0; k < tris.size(); ++k)
        polys.push_back(project_polygon(SceneId(k + 1), {}, {tris[k].v[0], tris[k].v[1], tris[k].v[2]}, {width, height}));
    const FrameDepth f = zbuffer_fill(polys, {.viewport = {width, height}, .format = DepthFormat::int24,
                                              .range = {1, 10}, .perspective = true, .detail = EventDetail::polygon})
                             .run_to_end();
    std::vector<int> ids;
    for (auto i : f.image.ids) ids.push_back(i);
    return ids;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string what = argc > 1 ? argv[1] : "mesh";
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return std::fprintf(stderr, "gl_raster_check: %s\n", SDL_GetError()), 1;
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_Window* window = SDL_CreateWindow("gl_raster_check", 0, 0, width, height, SDL_WINDOW_OPENGL | SDL_WINDOW_HIDDEN);
    SDL_GLContext context = window ? SDL_GL_CreateContext(window) : nullptr;
    if (!context) return std::fprintf(stderr, "gl_raster_check: %s\n", SDL_GetError()), 1;
    int differ = 0, covered = 0, runs = 0;
    for (std::uint32_t seed = 1; seed <= 20; ++seed, ++runs) {
        std::mt19937 rng(seed);
        const auto tris = what == "mesh" ? mesh(rng) : overlap(rng);
        const auto gl = gl_ids(tris), ours = our_ids(tris);
        for (std::size_t k = 0; k < gl.size(); ++k) {
            covered += ours[k] != 0;
            if (gl[k] != ours[k]) {
                if (differ < 10)
                    std::fprintf(stderr, "seed %u pixel (%zu, %zu): GL %d, ours %d\n", seed, k % width, k / width, gl[k], ours[k]);
                ++differ;
            }
        }
    }
    std::printf("gl_raster_check %s: %d of %d pixels differ from OpenGL (%s), %d covered\n", what.c_str(), differ,
                runs * width * height, reinterpret_cast<const char*>(glGetString(GL_RENDERER)), covered);
    SDL_GL_DeleteContext(context);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return differ == 0 ? 0 : 1;
}
