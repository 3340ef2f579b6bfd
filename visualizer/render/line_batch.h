// SPDX-License-Identifier: MIT
// Coloured lines, triangles and points in one vertex buffer, drawn with one tiny shader. Filled every frame from
// a view (update, then draw): nothing here knows an algorithm.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/gl.h"

namespace hsr::viz {

struct ColoredVertex {
    glm::vec3 position;  // world space
    glm::vec4 color;     // straight (not premultiplied) alpha
};

class LineBatch {
public:
    LineBatch();
    ~LineBatch();
    LineBatch(const LineBatch&) = delete;
    LineBatch& operator=(const LineBatch&) = delete;

    void clear();
    void line(glm::vec3 a, glm::vec3 b, glm::vec4 color);
    void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec4 color);
    void point(glm::vec3 p, glm::vec4 color);

    // Draws triangles (translucent, no depth write), then lines of the given width, then points of the given size.
    void draw(const glm::mat4& view_projection, float line_width, float point_size);

private:
    void make_gl_objects();
    void upload_and_draw(const std::vector<ColoredVertex>& v, GLenum mode);
    std::vector<ColoredVertex> lines_, triangles_, points_;
    GLuint program_ = 0, vao_ = 0, vbo_ = 0;
    GLint mvp_location_ = -1, point_size_location_ = -1;
};

// Two batches drawn with different widths: thin context lines and thick lines for what the step is about.
struct LineBatches {
    LineBatch faint;
    LineBatch bold;
};

}  // namespace hsr::viz
