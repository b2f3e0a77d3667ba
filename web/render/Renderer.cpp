#include "render/Renderer.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "essi_shaders.hpp"

namespace essi::viewer {

namespace {

std::string g_error;

GLuint compile(GLenum type, const char* src, const char* name) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        g_error = std::string("shader ") + name + ": " + log;
        std::fprintf(stderr, "essi_viewer: %s\n", g_error.c_str());
        glDeleteShader(s);
        return 0;
    }
    return s;
}

GLuint link(const char* vs_src, const char* fs_src, const char* name) {
    GLuint vs = compile(GL_VERTEX_SHADER, vs_src, name);
    GLuint fs = compile(GL_FRAGMENT_SHADER, fs_src, name);
    if (!vs || !fs) return 0;
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        g_error = std::string("program ") + name + ": " + log;
        std::fprintf(stderr, "essi_viewer: %s\n", g_error.c_str());
        return 0;
    }
    return p;
}

void set_view_uniforms(GLuint p, const View& v, int fb_w, int fb_h, float scale) {
    glUniform2f(glGetUniformLocation(p, "u_center"), static_cast<float>(v.cx), static_cast<float>(v.cy));
    glUniform1f(glGetUniformLocation(p, "u_zoom"), static_cast<float>(v.zoom * scale));
    glUniform2f(glGetUniformLocation(p, "u_origin_px"), static_cast<float>(v.ox() * scale), static_cast<float>(v.oy() * scale));
    glUniform2f(glGetUniformLocation(p, "u_viewport"), static_cast<float>(fb_w), static_cast<float>(fb_h));
}

}  // namespace

bool Renderer::init() {
    path_program_ = link(shaders::path_vert_glsl, shaders::path_frag_glsl, "path");
    grid_program_ = link(shaders::grid_vert_glsl, shaders::grid_frag_glsl, "grid");
    marker_program_ = link(shaders::marker_vert_glsl, shaders::marker_frag_glsl, "marker");
    if (!path_program_ || !grid_program_ || !marker_program_) {
        error_ = g_error.c_str();
        return false;
    }
    // Unit quad as a triangle strip: (along, across).
    const float quad[] = {0, -1, 1, -1, 0, 1, 1, 1};
    glGenBuffers(1, &quad_vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glGenBuffers(1, &seg_vbo_);
    glGenBuffers(1, &marker_vbo_);
    glGenBuffers(1, &tool_vbo_);
    glGenVertexArrays(1, &path_vao_);  // no attributes: the path program pulls its segments from textures
    for (GLuint* t : {&seg_tex_, &kind_tex_}) {
        glGenTextures(1, t);
        glBindTexture(GL_TEXTURE_2D, *t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenVertexArrays(1, &sel_vao_);
    glGenVertexArrays(1, &marker_vao_);
    glGenVertexArrays(1, &tool_vao_);
    glGenVertexArrays(1, &grid_vao_);
    for (GLuint vao : {marker_vao_, tool_vao_}) {
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);  // marker corners: remapped in the shader
        glBindBuffer(GL_ARRAY_BUFFER, vao == marker_vao_ ? marker_vbo_ : tool_vbo_);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(MarkerInstance), nullptr);
        glVertexAttribDivisor(1, 1);
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(MarkerInstance),
                              reinterpret_cast<void*>(offsetof(MarkerInstance, type)));
        glVertexAttribDivisor(2, 1);
    }
    glBindVertexArray(0);
    return true;
}

void Renderer::upload(const PathBuffers& b) {
    // Segments into two textures, a row of kTexWidth segments at a time (no second copy of the stream).
    GLint max_size = 4096;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    const std::size_t rows_max = static_cast<std::size_t>(max_size);
    std::size_t n = b.segments.size();
    std::size_t rows = (n + kTexWidth - 1) / kTexWidth;
    if (rows > rows_max) {
        std::fprintf(stderr, "essi_viewer: %zu segments, the GPU takes %zu; the rest is not drawn\n", n, rows_max * kTexWidth);
        rows = rows_max;
        n = rows * kTexWidth;
    }
    const GLsizei h = static_cast<GLsizei>(std::max<std::size_t>(rows, 1));
    glBindTexture(GL_TEXTURE_2D, seg_tex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTexWidth, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, kind_tex_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, kTexWidth, h, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    std::vector<float> row(static_cast<std::size_t>(kTexWidth) * 4);
    std::vector<std::uint8_t> kinds(static_cast<std::size_t>(kTexWidth));
    for (std::size_t r = 0; r < rows; ++r) {
        const std::size_t first = r * kTexWidth;
        const std::size_t count = std::min<std::size_t>(kTexWidth, n - first);
        for (std::size_t k = 0; k < count; ++k) {
            const SegmentInstance& sg = b.segments[first + k];
            row[4 * k] = sg.x0;
            row[4 * k + 1] = sg.y0;
            row[4 * k + 2] = sg.x1;
            row[4 * k + 3] = sg.y1;
            kinds[k] = static_cast<std::uint8_t>(sg.kind);
        }
        glBindTexture(GL_TEXTURE_2D, seg_tex_);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(r), static_cast<GLsizei>(count), 1, GL_RGBA, GL_FLOAT, row.data());
        glBindTexture(GL_TEXTURE_2D, kind_tex_);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(r), static_cast<GLsizei>(count), 1, GL_RED_INTEGER,
                        GL_UNSIGNED_BYTE, kinds.data());
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
    segment_count_ = n;
    glBindBuffer(GL_ARRAY_BUFFER, marker_vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(b.markers.size() * sizeof(MarkerInstance)),
                 b.markers.empty() ? nullptr : b.markers.data(), GL_STATIC_DRAW);
    marker_count_ = b.markers.size();
}

void Renderer::clear_geometry() {
    segment_count_ = 0;
    marker_count_ = 0;
}

void Renderer::draw(const View& view, int fb_w, int fb_h, const DrawOptions& o, double grid_step, Point world_origin) {
    glViewport(0, 0, fb_w, fb_h);
    glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    const float s = o.framebuffer_scale;

    // Grid
    glUseProgram(grid_program_);
    set_view_uniforms(grid_program_, view, fb_w, fb_h, s);
    glUniform2f(glGetUniformLocation(grid_program_, "u_world_origin"), static_cast<float>(world_origin.x),
                static_cast<float>(world_origin.y));
    glUniform1f(glGetUniformLocation(grid_program_, "u_step"), static_cast<float>(grid_step));
    glUniform4f(glGetUniformLocation(grid_program_, "u_minor"), 0.5f, 0.55f, 0.6f, 0.10f);
    glUniform4f(glGetUniformLocation(grid_program_, "u_major"), 0.5f, 0.55f, 0.6f, 0.25f);
    glUniform4f(glGetUniformLocation(grid_program_, "u_axis"), 0.6f, 0.8f, 0.6f, 0.45f);
    glBindVertexArray(grid_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // Paths
    if (segment_count_ > 0 && (o.layer_mask & 0xF) != 0) {  // every layer hidden: not one vertex to run
        glUseProgram(path_program_);
        set_view_uniforms(path_program_, view, fb_w, fb_h, s);
        float hw[4] = {0.6f * s, 0.6f * s, 1.1f * s, 1.0f * s};
        glUniform1fv(glGetUniformLocation(path_program_, "u_half_width"), 4, hw);
        glUniform4fv(glGetUniformLocation(path_program_, "u_colors"), 4, &kKindColors[0].r);
        glUniform1i(glGetUniformLocation(path_program_, "u_layer_mask"), o.layer_mask);
        glUniform4f(glGetUniformLocation(path_program_, "u_override"), 0, 0, 0, 0);
        glUniform1f(glGetUniformLocation(path_program_, "u_extra_width"), 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, seg_tex_);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, kind_tex_);
        glActiveTexture(GL_TEXTURE0);
        glUniform1i(glGetUniformLocation(path_program_, "u_segs"), 0);
        glUniform1i(glGetUniformLocation(path_program_, "u_kinds"), 1);
        glUniform1i(glGetUniformLocation(path_program_, "u_tex_width"), kTexWidth);
        glUniform1i(glGetUniformLocation(path_program_, "u_first"), 0);
        glBindVertexArray(path_vao_);
        const std::size_t n = std::min(segment_count_, o.segment_limit);
        if (n > 0) glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(n * 6));
        if (o.selection_count > 0 && o.selection_first < segment_count_) {
            glUniform4f(glGetUniformLocation(path_program_, "u_override"), kSelectionColor.r, kSelectionColor.g,
                        kSelectionColor.b, kSelectionColor.a);
            glUniform1f(glGetUniformLocation(path_program_, "u_extra_width"), 1.0f * s);
            glUniform1i(glGetUniformLocation(path_program_, "u_layer_mask"), 0xF);
            glUniform1i(glGetUniformLocation(path_program_, "u_first"), static_cast<GLint>(o.selection_first));
            const std::size_t count = std::min(o.selection_count, segment_count_ - o.selection_first);
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count * 6));
        }
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    // Markers
    glUseProgram(marker_program_);
    set_view_uniforms(marker_program_, view, fb_w, fb_h, s);
    glUniform1f(glGetUniformLocation(marker_program_, "u_radius_px"), 5.0f * s);
    const float mc[12] = {1.0f, 0.25f, 0.2f, 1.0f,   // pierce: red ring
                          0.3f, 0.95f, 0.4f, 1.0f,   // start: green disc
                          1.0f, 1.0f, 1.0f, 1.0f};   // tool: white ring + cross
    glUniform4fv(glGetUniformLocation(marker_program_, "u_colors"), 3, mc);
    glUniform1i(glGetUniformLocation(marker_program_, "u_type_mask"), o.marker_mask);
    if (marker_count_ > 0) {
        glBindVertexArray(marker_vao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(marker_count_));
    }
    if (o.has_tool) {
        const MarkerInstance tool{static_cast<float>(o.tool.x), static_cast<float>(o.tool.y), 2.f};
        glBindBuffer(GL_ARRAY_BUFFER, tool_vbo_);
        glBufferData(GL_ARRAY_BUFFER, sizeof tool, &tool, GL_DYNAMIC_DRAW);
        glUniform1i(glGetUniformLocation(marker_program_, "u_type_mask"), 0x7);
        glUniform1f(glGetUniformLocation(marker_program_, "u_radius_px"), 8.0f * s);
        glBindVertexArray(tool_vao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 1);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace essi::viewer
