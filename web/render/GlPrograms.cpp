#include "render/GlPrograms.hpp"

#include <GLES3/gl3.h>

#include <cstdio>
#include <string>

#include "essi_shaders.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

namespace {

std::string g_error;

// Logs a compile or link error and keeps it for program_error().
void fail(const char* what, const char* name, const char* log) {
    g_error = std::string(what) + " " + name + ": " + log;
    std::fprintf(stderr, "essi_viewer: %s\n", g_error.c_str());
}

GLuint compile(GLenum type, const char* src, const char* name) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        fail("shader", name, log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

void set_color(int location, const Rgba& c) { glUniform4f(location, c.r, c.g, c.b, c.a); }

}  // namespace

unsigned link_program(const char* vs_src, const char* fs_src, const char* name) {
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
        fail("program", name, log);
        return 0;
    }
    return p;
}

const char* program_error() { return g_error.c_str(); }

unsigned new_texture() {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void TargetUniforms::find(unsigned p) {
    center = glGetUniformLocation(p, "u_center");
    zoom = glGetUniformLocation(p, "u_zoom");
    origin_px = glGetUniformLocation(p, "u_origin_px");
    viewport = glGetUniformLocation(p, "u_viewport");
}

void TargetUniforms::set(float cx, float cy, float zoom_px, float ox, float oy, int w, int h) const {
    glUniform2f(center, cx, cy);
    glUniform1f(zoom, zoom_px);
    glUniform2f(origin_px, ox, oy);
    glUniform2f(viewport, static_cast<float>(w), static_cast<float>(h));
}

bool ScenePrograms::init(int tex_width) {
    path.id = link_program(shaders::path_vert_glsl, shaders::path_frag_glsl, "path");
    grid.id = link_program(shaders::grid_vert_glsl, shaders::grid_frag_glsl, "grid");
    marker.id = link_program(shaders::marker_vert_glsl, shaders::marker_frag_glsl, "marker");
    if (!path.id || !grid.id || !marker.id) return false;
    blit.id = link_program(shaders::blit_vert_glsl, shaders::blit_frag_glsl, "blit");
    lod.id = link_program(shaders::blit_vert_glsl, shaders::lod_frag_glsl, "lod");
    if (!blit.id || !lod.id) return false;

    glUseProgram(path.id);
    path.target.find(path.id);
    path.half_width = glGetUniformLocation(path.id, "u_half_width");
    path.layer_mask = glGetUniformLocation(path.id, "u_layer_mask");
    path.override_color = glGetUniformLocation(path.id, "u_override");
    path.extra_width = glGetUniformLocation(path.id, "u_extra_width");
    path.first = glGetUniformLocation(path.id, "u_first");
    glUniform4fv(glGetUniformLocation(path.id, "u_colors"), kMotionKinds, &kKindColors[0].r);
    glUniform1i(glGetUniformLocation(path.id, "u_segs"), 0);   // texture unit 0: the end points
    glUniform1i(glGetUniformLocation(path.id, "u_kinds"), 1);  // unit 1: the kinds
    glUniform1i(glGetUniformLocation(path.id, "u_tex_width"), tex_width);

    glUseProgram(grid.id);
    grid.target.find(grid.id);
    grid.world_origin = glGetUniformLocation(grid.id, "u_world_origin");
    grid.step = glGetUniformLocation(grid.id, "u_step");
    set_color(glGetUniformLocation(grid.id, "u_minor"), kGridMinor);
    set_color(glGetUniformLocation(grid.id, "u_major"), kGridMajor);
    set_color(glGetUniformLocation(grid.id, "u_axis"), kGridAxis);

    glUseProgram(marker.id);
    marker.target.find(marker.id);
    marker.radius_px = glGetUniformLocation(marker.id, "u_radius_px");
    marker.type_mask = glGetUniformLocation(marker.id, "u_type_mask");
    marker.use_single = glGetUniformLocation(marker.id, "u_use_single");
    marker.single = glGetUniformLocation(marker.id, "u_single");
    glUniform4fv(glGetUniformLocation(marker.id, "u_colors"), kMarkerTypes, &kMarkerColors[0].r);
    glUniform1i(glGetUniformLocation(marker.id, "u_markers"), 0);
    glUniform1i(glGetUniformLocation(marker.id, "u_tex_width"), tex_width);

    glUseProgram(lod.id);
    lod.target.find(lod.id);
    lod.rect = glGetUniformLocation(lod.id, "u_rect");
    lod.level = glGetUniformLocation(lod.id, "u_level");
    lod.cell = glGetUniformLocation(lod.id, "u_cell");
    lod.min = glGetUniformLocation(lod.id, "u_min");
    lod.mask = glGetUniformLocation(lod.id, "u_mask");
    glUniform1i(glGetUniformLocation(lod.id, "u_lod"), 0);
    glUniform4fv(glGetUniformLocation(lod.id, "u_colors"), kMotionKinds, &kKindColors[0].r);
    set_color(glGetUniformLocation(lod.id, "u_pierce"), marker_color(MarkerType::Pierce));

    glUseProgram(blit.id);
    blit.rect = glGetUniformLocation(blit.id, "u_rect");
    blit.viewport = glGetUniformLocation(blit.id, "u_viewport");
    glUniform1i(glGetUniformLocation(blit.id, "u_image"), 0);
    glUseProgram(0);
    return true;
}

}  // namespace essi::viewer
