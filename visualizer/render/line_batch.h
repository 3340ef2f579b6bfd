// SPDX-License-Identifier: MIT
// Coloured lines, triangles and points in one vertex buffer, drawn with one tiny shader. Filled every frame from
// a view (update, then draw): nothing here knows an algorithm.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/colored_vertex.h"
#include "render/gl.h"

namespace hsr::viz {

class LineBatch {
public:
    LineBatch();
    ~LineBatch();
    LineBatch(const LineBatch&) = delete;
    LineBatch& operator=(const LineBatch&) = delete;

    void clear();
    void line(glm::vec3 a, glm::vec3 b, glm::vec4 color);
    void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec4 color);
    // Opaque: drawn before the translucent triangles, writing depth, so it hides what lies behind it (a walk's
    // frame; the translucent ones are drawn in any order and never hide anything).
    void solid_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec4 color);
    void point(glm::vec3 p, glm::vec4 color);

    // Draws the opaque triangles (depth written), the translucent ones (no depth write), then lines of the given width in pixels (as triangles: see
    // wide_lines.h) of the viewport's size in pixels (given, not asked of GL: in a browser glGet waits for the
    // GPU's queued work, 80 % of a frame), then points of the given size.
    void draw(const glm::mat4& view_projection, glm::vec2 viewport, float line_width, float point_size);

private:
    void make_gl_objects();
    void upload_and_draw(const std::vector<ColoredVertex>& v, GLenum mode);
    std::vector<ColoredVertex> lines_, triangles_, solid_, points_;
    std::vector<ColoredVertex> wide_;  // the lines as triangles, made at each draw (kept: no allocation per frame)
    GLuint program_ = 0, vao_ = 0, vbo_ = 0;
    GLint mvp_location_ = -1, point_size_location_ = -1;
};

// Two batches drawn with different widths: thin context lines and thick lines for what the step is about.
struct LineBatches {
    LineBatch faint;
    LineBatch bold;
};

}  // namespace hsr::viz
