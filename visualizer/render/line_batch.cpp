// SPDX-License-Identifier: MIT
#include "render/line_batch.h"

#include <cstddef>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "platform.h"
#include "render/wide_lines.h"

namespace hsr::viz {
namespace {

// The shaders' bodies: the same GLSL in OpenGL 3.3 core and in OpenGL ES 3.0 (WebGL 2); their first line is the
// platform's (platform.h).
constexpr const char* vertex_shader = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
uniform mat4 mvp;
uniform float point_size;
out vec4 v_color;
void main() {
    gl_Position = mvp * vec4(position, 1.0);
    gl_PointSize = point_size;
    v_color = color;
})";

constexpr const char* fragment_shader = R"(
in vec4 v_color;
out vec4 frag;
void main() { frag = v_color; })";

GLuint compile(GLenum type, const char* body) {
    const GlProfile& gl = gl_profile();
    const std::string source = std::string(gl.glsl_version) + "\n" + (type == GL_FRAGMENT_SHADER ? gl.fragment_preamble : "") + body;
    const char* text = source.c_str();
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader compile failed: ") + log);
    }
    return s;
}

}  // namespace

LineBatch::LineBatch() = default;

// The GL objects are made at the first draw, not with the batch: a batch can then be filled with no GL context (the
// panel fuzzer fills a frame's batches headless) and a batch never drawn costs nothing.
void LineBatch::make_gl_objects() {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex_shader), fs = compile(GL_FRAGMENT_SHADER, fragment_shader);
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    mvp_location_ = glGetUniformLocation(program_, "mvp");
    point_size_location_ = glGetUniformLocation(program_, "point_size");

    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ColoredVertex),
                          reinterpret_cast<void*>(offsetof(ColoredVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ColoredVertex),
                          reinterpret_cast<void*>(offsetof(ColoredVertex, color)));
    glBindVertexArray(0);
}

LineBatch::~LineBatch() {
    if (program_ == 0) return;  // never drawn
    glDeleteBuffers(1, &vbo_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteProgram(program_);
}

void LineBatch::clear() {
    lines_.clear();
    triangles_.clear();
    solid_.clear();
    points_.clear();
}

void LineBatch::line(glm::vec3 a, glm::vec3 b, glm::vec4 color) {
    lines_.push_back({a, color});
    lines_.push_back({b, color});
}

void LineBatch::triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec4 color) {
    triangles_.push_back({a, color});
    triangles_.push_back({b, color});
    triangles_.push_back({c, color});
}

void LineBatch::solid_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec4 color) {
    solid_.push_back({a, color});
    solid_.push_back({b, color});
    solid_.push_back({c, color});
}

void LineBatch::point(glm::vec3 p, glm::vec4 color) { points_.push_back({p, color}); }

void LineBatch::upload_and_draw(const std::vector<ColoredVertex>& v, GLenum mode) {
    if (v.empty()) return;
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(ColoredVertex)), v.data(), GL_STREAM_DRAW);
    glDrawArrays(mode, 0, GLsizei(v.size()));
}

void LineBatch::draw(const glm::mat4& view_projection, glm::vec2 viewport, float line_width, float point_size) {
    if (program_ == 0) make_gl_objects();
    glUseProgram(program_);
    glUniformMatrix4fv(mvp_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    glUniform1f(point_size_location_, point_size);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    if (!gl_profile().es) glEnable(GL_PROGRAM_POINT_SIZE);  // ES always takes gl_PointSize from the shader
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    glDepthMask(GL_TRUE);
    if (!solid_.empty()) upload_and_draw(solid_, GL_TRIANGLES);  // opaque faces hide what lies behind them
    glDepthMask(GL_FALSE);  // translucent faces never hide what is behind them
    upload_and_draw(triangles_, GL_TRIANGLES);
    glDepthMask(GL_TRUE);
    // the lines as screen-space rectangles (wide_lines.h: GL_LINES are one pixel wide in WebGL), in normalised
    // device coordinates, so drawn with no transform
    wide_.clear();
    wide_line_triangles(lines_, view_projection, line_width, viewport, wide_);
    const glm::mat4 identity(1.0f);
    glUniformMatrix4fv(mvp_location_, 1, GL_FALSE, glm::value_ptr(identity));
    upload_and_draw(wide_, GL_TRIANGLES);
    glUniformMatrix4fv(mvp_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    glDisable(GL_DEPTH_TEST);  // points (intersections, endpoints) always show
    upload_and_draw(points_, GL_POINTS);

    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace hsr::viz
