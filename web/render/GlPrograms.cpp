#include "render/GlPrograms.hpp"

#include <GLES3/gl3.h>

#include <array>
#include <cstdio>
#include <string>

#include "essi_shaders.hpp"
#include "render/GridLines.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

namespace {

std::string g_error;

// Whether `object` (a shader or a program) compiled or linked: `status` through `get`; otherwise its info log
// (through `get_log`) is logged and kept for program_error().
bool succeeded(GLuint object, GLenum status, void (*get)(GLuint, GLenum, GLint*),
               void (*get_log)(GLuint, GLsizei, GLsizei*, GLchar*), const char* what, const char* name) {
    GLint ok = 0;
    get(object, status, &ok);
    if (ok) return true;
    char log[2048];
    get_log(object, sizeof log, nullptr, log);
    g_error = std::string(what) + " " + name + ": " + log;
    std::fprintf(stderr, "essi_viewer: %s\n", g_error.c_str());
    return false;
}

GLuint compile(GLenum type, const char* src, const char* name) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    if (succeeded(s, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, "shader", name)) return s;
    glDeleteShader(s);
    return 0;
}

// Start-up only: the uniforms of one program (in use from here on), found by name, and those whose value never
// changes set.
class Setup {
public:
    explicit Setup(unsigned program) : program_(program) { glUseProgram(program); }
    int operator()(const char* name) const { return glGetUniformLocation(program_, name); }
    [[nodiscard]] SceneProgram scene() const { return {program_, TargetUniforms::of(program_)}; }
    void set(const char* name, int v) const { glUniform1i((*this)(name), v); }
    void set(const char* name, float v) const { glUniform1f((*this)(name), v); }
    void set(const char* name, const Rgba& c) const { glUniform4f((*this)(name), c.r, c.g, c.b, c.a); }
    void set(const char* name, const Rgba* colors, std::size_t n) const {
        glUniform4fv((*this)(name), static_cast<GLsizei>(n), &colors->r);
    }

private:
    unsigned program_;
};

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
    return succeeded(p, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, "program", name) ? p : 0;
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

TargetUniforms TargetUniforms::of(unsigned p) {
    return {glGetUniformLocation(p, "u_center"), glGetUniformLocation(p, "u_zoom"),
            glGetUniformLocation(p, "u_origin_px"), glGetUniformLocation(p, "u_viewport"),
            glGetUniformLocation(p, "u_turn")};
}

void TargetUniforms::set(float cx, float cy, float zoom_px, float ox, float oy, int w, int h, Rotation r) const {
    glUniform2f(turn, static_cast<float>(r.c), static_cast<float>(r.s));
    glUniform2f(center, cx, cy);
    glUniform1f(zoom, zoom_px);
    glUniform2f(origin_px, ox, oy);
    glUniform2f(viewport, static_cast<float>(w), static_cast<float>(h));
}

void ScenePrograms::set_theme(const Theme& theme) const {
    const Setup g(grid.id);
    g.set("u_minor", theme.grid_minor);
    g.set("u_major", theme.grid_major);
    g.set("u_axis", theme.grid_axis);
    std::array<Rgba, kMarkerTypes> markers = kMarkerColors;
    markers[static_cast<std::size_t>(MarkerType::Tool)] = theme.tool;
    const Setup m(marker.id);
    m.set("u_colors", markers.data(), kMarkerTypes);
    glUseProgram(0);
}

bool ScenePrograms::init(int tex_width) {
    const unsigned path_id = link_program(shaders::path_vert_glsl, shaders::path_frag_glsl, "path");
    const unsigned grid_id = link_program(shaders::grid_vert_glsl, shaders::grid_frag_glsl, "grid");
    const unsigned marker_id = link_program(shaders::marker_vert_glsl, shaders::marker_frag_glsl, "marker");
    if (!path_id || !grid_id || !marker_id) return false;
    const unsigned blit_id = link_program(shaders::blit_vert_glsl, shaders::blit_frag_glsl, "blit");
    const unsigned lod_id = link_program(shaders::blit_vert_glsl, shaders::lod_frag_glsl, "lod");
    if (!blit_id || !lod_id) return false;

    const Setup p(path_id);
    path = {p.scene(),          p("u_half_width"), p("u_layer_mask"),   p("u_override"),
            p("u_extra_width"), p("u_first"),      p("u_band_half_mm"), p("u_alpha")};
    p.set("u_alpha", 1.f);
    p.set("u_colors", kPathColorTable.data(), kPathColors);
    p.set("u_ramp", kColourRamp.data(), kColourBins);
    p.set("u_segs", 0);   // texture unit 0: the end points
    p.set("u_kinds", 1);  // unit 1: the kinds
    p.set("u_tex_width", tex_width);

    const Setup g(grid_id);
    grid = {g.scene(),          g("u_first"), g("u_step"),    g("u_count"),
            g("u_major_phase"), g("u_zero"),  g("u_axes_at"), g("u_span")};
    g.set("u_major_every", GridLines::kMajorEvery);

    const Setup m(marker_id);
    marker = {m.scene(),     m("u_radius_px"),      m("u_type_mask"),   m("u_use_single"),
              m("u_single"), m("u_mark_radius_px"), m("u_plain_alpha"), m("u_first")};
    m.set("u_plain_alpha", 1.f);
    m.set("u_first", 0);
    m.set("u_markers", 0);
    m.set("u_tex_width", tex_width);

    const Setup l(lod_id);
    lod = {l.scene(), l("u_rect"), l("u_level"), l("u_cell"), l("u_min"), l("u_mask")};
    l.set("u_lod", 0);
    l.set("u_colors", kKindColors.data(), kMotionKinds);
    l.set("u_pierce", marker_color(MarkerType::Pierce));

    const Setup b(blit_id);
    blit = {blit_id, b("u_rect"), b("u_viewport")};
    b.set("u_image", 0);
    glUseProgram(0);
    set_theme(kDarkTheme);
    return true;
}

}  // namespace essi::viewer
