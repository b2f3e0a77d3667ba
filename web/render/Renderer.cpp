#include "render/Renderer.hpp"

#include <GLES3/gl3.h>
#include <imgui.h>

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

// The image around the drawing area: this share of the area's width (height) on each side.
constexpr float kCacheMarginShare = 0.5f;

void set_target_uniforms(GLuint p, float cx, float cy, float zoom, float ox, float oy, int w, int h) {
    glUniform2f(glGetUniformLocation(p, "u_center"), cx, cy);
    glUniform1f(glGetUniformLocation(p, "u_zoom"), zoom);
    glUniform2f(glGetUniformLocation(p, "u_origin_px"), ox, oy);
    glUniform2f(glGetUniformLocation(p, "u_viewport"), static_cast<float>(w), static_cast<float>(h));
}

}  // namespace

namespace {

GLuint new_texture() {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

}  // namespace

std::size_t GpuPath::gpu_bytes() const {
    std::size_t n = 0;
    for (const GpuPage& p : pages) n += p.rows * Renderer::kTexWidth * 17;
    return n;
}

bool Renderer::init() {
    path_program_ = link(shaders::path_vert_glsl, shaders::path_frag_glsl, "path");
    grid_program_ = link(shaders::grid_vert_glsl, shaders::grid_frag_glsl, "grid");
    marker_program_ = link(shaders::marker_vert_glsl, shaders::marker_frag_glsl, "marker");
    if (!path_program_ || !grid_program_ || !marker_program_) {
        error_ = g_error.c_str();
        return false;
    }
    blit_program_ = link(shaders::blit_vert_glsl, shaders::blit_frag_glsl, "blit");
    lod_program_ = link(shaders::blit_vert_glsl, shaders::lod_frag_glsl, "lod");
    if (!blit_program_ || !lod_program_) {
        error_ = g_error.c_str();
        return false;
    }
    glGenVertexArrays(1, &empty_vao_);
    marker_tex_ = new_texture();
    glBindTexture(GL_TEXTURE_2D, 0);
    return init_ui();
}

bool Renderer::init_ui() {
    ui_program_ = link(shaders::ui_vert_glsl, shaders::ui_frag_glsl, "ui");
    if (!ui_program_) {
        error_ = g_error.c_str();
        return false;
    }
    glGenVertexArrays(1, &ui_vao_);
    glGenBuffers(1, &ui_vertices_);
    glGenBuffers(1, &ui_indices_);
    glBindVertexArray(ui_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, ui_vertices_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ui_indices_);
    const auto stride = static_cast<GLsizei>(sizeof(ImDrawVert));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(IM_OFFSETOF(ImDrawVert, pos)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(IM_OFFSETOF(ImDrawVert, uv)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, reinterpret_cast<void*>(IM_OFFSETOF(ImDrawVert, col)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    // The font atlas (ImGui's default font), linear filtering as ImGui draws it.
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    font_tex_ = new_texture();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glBindTexture(GL_TEXTURE_2D, 0);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(font_tex_)));
    io.BackendRendererName = "essikit";
    return true;
}

void Renderer::draw_ui(const ImDrawData& data, int fb_w, int fb_h) {
    if (fb_w <= 0 || fb_h <= 0 || data.CmdListsCount == 0) return;
    const ImVec2 scale = data.FramebufferScale;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb_w, fb_h);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glUseProgram(ui_program_);
    glUniform2f(glGetUniformLocation(ui_program_, "u_viewport"), data.DisplaySize.x, data.DisplaySize.y);
    glUniform1i(glGetUniformLocation(ui_program_, "u_texture"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(ui_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, ui_vertices_);
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.VtxBuffer.Size) * static_cast<GLsizeiptr>(sizeof(ImDrawVert)),
                     list.VtxBuffer.Data, GL_STREAM_DRAW);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.IdxBuffer.Size) * static_cast<GLsizeiptr>(sizeof(ImDrawIdx)),
                     list.IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback != nullptr) {  // (the viewer adds none)
                cmd.UserCallback(&list, &cmd);
                continue;
            }
            // The clip rectangle in framebuffer pixels (GL's y runs upwards).
            const float x0 = (cmd.ClipRect.x - data.DisplayPos.x) * scale.x, y0 = (cmd.ClipRect.y - data.DisplayPos.y) * scale.y;
            const float x1 = (cmd.ClipRect.z - data.DisplayPos.x) * scale.x, y1 = (cmd.ClipRect.w - data.DisplayPos.y) * scale.y;
            if (x1 <= x0 || y1 <= y0) continue;
            glScissor(static_cast<GLint>(x0), static_cast<GLint>(static_cast<float>(fb_h) - y1), static_cast<GLsizei>(x1 - x0),
                      static_cast<GLsizei>(y1 - y0));
            glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(reinterpret_cast<std::intptr_t>(cmd.GetTexID())));
            // (no vertex offsets: the viewer does not set ImGuiBackendFlags_RendererHasVtxOffset)
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount),
                           sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                           reinterpret_cast<void*>(static_cast<std::intptr_t>(cmd.IdxOffset * sizeof(ImDrawIdx))));
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
}

void Renderer::add_page(GpuPath& path, std::size_t first, std::size_t rows) {
    GpuPage pg;
    pg.first = first;
    pg.rows = rows;
    const auto h = static_cast<GLsizei>(rows);
    pg.seg_tex = new_texture();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTexWidth, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    pg.kind_tex = new_texture();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, kTexWidth, h, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    path.pages.push_back(pg);
}

void Renderer::append(GpuPath& path, PathBuffers& b) {
    const bool final = b.complete();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    while (b.staged_count() > 0) {
        const std::size_t first = b.staged_first;  // == path.count
        if (path.pages.empty() || first >= path.pages.back().first + path.pages.back().rows * kTexWidth) {
            // A new page sized for the segments still to come (projected), in whole quanta of rows.
            const std::size_t expected = std::max(b.estimated_segments(), first + b.staged_count()) - first;
            std::size_t rows = (expected + kTexWidth - 1) / kTexWidth;
            rows = std::clamp((rows + kRowQuantum - 1) / kRowQuantum * kRowQuantum, kRowQuantum, kPageRows);
            add_page(path, first, rows);
        }
        const GpuPage& pg = path.pages.back();
        const std::size_t row0 = (first - pg.first) / kTexWidth;  // uploads start on whole rows
        std::size_t rows = std::min(b.staged_count() / kTexWidth, pg.rows - row0);
        std::size_t width = kTexWidth;
        if (rows == 0) {
            if (!final) break;  // wait for a whole row
            rows = 1;           // the last, partial row
            width = b.staged_count();
        }
        glBindTexture(GL_TEXTURE_2D, pg.seg_tex);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(row0), static_cast<GLsizei>(width),
                        static_cast<GLsizei>(rows), GL_RGBA, GL_FLOAT, b.staged_ends.data());
        glBindTexture(GL_TEXTURE_2D, pg.kind_tex);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(row0), static_cast<GLsizei>(width),
                        static_cast<GLsizei>(rows), GL_RED_INTEGER, GL_UNSIGNED_BYTE, b.staged_kinds.data());
        const std::size_t n = rows == 1 && width < kTexWidth ? width : rows * kTexWidth;
        for (std::size_t k = 0; k < n; ++k) {  // the boxes of the groups these segments are in
            const float* e = b.staged_ends.data() + 4 * k;
            const std::size_t g = (first + k) / GpuPath::kCullGroup;
            if (4 * g == path.group_boxes.size()) path.group_boxes.insert(path.group_boxes.end(), {e[0], e[1], e[0], e[1]});
            float* box = path.group_boxes.data() + 4 * g;
            box[0] = std::min({box[0], e[0], e[2]});
            box[1] = std::min({box[1], e[1], e[3]});
            box[2] = std::max({box[2], e[0], e[2]});
            box[3] = std::max({box[3], e[1], e[3]});
        }
        b.drop_staged(n);
        path.count += n;
        path.version = ++version_counter_;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void Renderer::release(GpuPath& path) {
    for (GpuPage& p : path.pages) {
        glDeleteTextures(1, &p.seg_tex);
        glDeleteTextures(1, &p.kind_tex);
    }
    path.pages.clear();
    path.group_boxes.clear();
    path.count = 0;
    path.version = ++version_counter_;
}

void Renderer::upload_markers(const std::vector<MarkerInstance>& markers) {
    GLint max_size = 4096;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    const std::size_t n = std::min(markers.size(), static_cast<std::size_t>(max_size) * kTexWidth);
    const std::size_t rows = std::max<std::size_t>((n + kTexWidth - 1) / kTexWidth, 1);
    std::vector<float> data(rows * kTexWidth * 4, 0.f);
    for (std::size_t i = 0; i < n; ++i) {
        data[4 * i] = markers[i].x;
        data[4 * i + 1] = markers[i].y;
        data[4 * i + 2] = markers[i].type;
    }
    glBindTexture(GL_TEXTURE_2D, marker_tex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTexWidth, static_cast<GLsizei>(rows), 0, GL_RGBA, GL_FLOAT, data.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    marker_count_ = n;
    markers_version_ = ++version_counter_;
}

void Renderer::upload_lod(const LodRaster& lod) {
    clear_lod();
    if (!lod.active() || !lod.finished()) return;
    if (lod_tex_ == 0) lod_tex_ = new_texture();
    glBindTexture(GL_TEXTURE_2D, lod_tex_);
    // Integer textures are read with texelFetch at an explicit level: no filtering.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, lod.levels() - 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    lod_bytes_ = 0;
    for (int k = 0; k < lod.levels(); ++k) {
        const int w = lod.width(k), rows = lod.strip_rows(k);
        glTexImage2D(GL_TEXTURE_2D, k, GL_R8UI, w, lod.height(k), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
        int y = 0;
        for (const std::vector<std::uint8_t>& strip : lod.strips(k)) {
            const int h = static_cast<int>(strip.size() / static_cast<std::size_t>(w));
            glTexSubImage2D(GL_TEXTURE_2D, k, 0, y, w, h, GL_RED_INTEGER, GL_UNSIGNED_BYTE, strip.data());
            y += rows;
            lod_bytes_ += strip.size();
        }
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
    lod_levels_ = lod.levels();
    lod_cell_ = lod.cell_mm();
    lod_min_x_ = lod.min_x();
    lod_min_y_ = lod.min_y();
    lod_version_ = ++version_counter_;
}

void Renderer::clear_lod() {
    lod_levels_ = 0;
    lod_bytes_ = 0;
    lod_version_ = ++version_counter_;
}

int Renderer::lod_level(double zoom) const {
    int level = 0;
    double cell_px = lod_cell_ * zoom;
    while (cell_px < 1.0 && level + 1 < lod_levels_) {
        cell_px *= 2;
        ++level;
    }
    return level;
}

void Renderer::draw_lod(const Target& t, int mask) {
    if (lod_levels_ == 0 || mask == 0) return;
    const int level = lod_level(t.zoom);
    glUseProgram(lod_program_);
    set_target_uniforms(lod_program_, t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h);
    glUniform4f(glGetUniformLocation(lod_program_, "u_rect"), 0.f, 0.f, static_cast<float>(t.w), static_cast<float>(t.h));
    glUniform1i(glGetUniformLocation(lod_program_, "u_lod"), 0);
    glUniform1i(glGetUniformLocation(lod_program_, "u_level"), level);
    glUniform1f(glGetUniformLocation(lod_program_, "u_cell"), static_cast<float>(lod_cell_ * std::ldexp(1.0, level)));
    glUniform2f(glGetUniformLocation(lod_program_, "u_min"), lod_min_x_, lod_min_y_);
    glUniform1i(glGetUniformLocation(lod_program_, "u_mask"), mask);
    glUniform4fv(glGetUniformLocation(lod_program_, "u_colors"), 4, &kKindColors[0].r);
    glUniform4f(glGetUniformLocation(lod_program_, "u_pierce"), 1.0f, 0.25f, 0.2f, 1.0f);
    glBindTexture(GL_TEXTURE_2D, lod_tex_);
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

// A draw per page the run touches (the path program is in use).
void Renderer::draw_run(const GpuPath& path, std::size_t first, std::size_t end) {
    for (const GpuPage& pg : path.pages) {
        const std::size_t a = std::max(first, pg.first);
        const std::size_t b = std::min(end, pg.first + pg.rows * kTexWidth);
        if (a >= b) continue;
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, pg.kind_tex);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, pg.seg_tex);
        glUniform1i(glGetUniformLocation(path_program_, "u_first"), static_cast<GLint>(a - pg.first));
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>((b - a) * 6));
    }
}

std::size_t Renderer::draw_segments(const GpuPath& path, std::size_t first, std::size_t last, const Target* cull,
                                    std::size_t budget) {
    last = std::min(last, path.count);
    if (first >= last) return last;
    if (cull == nullptr && budget >= last - first) {
        draw_run(path, first, last);
        return last;
    }
    // What the target shows, in mm relative to the origin (px = origin_px + (x - cx, cy - y) x zoom), widened by
    // the thickest line.
    float x0 = -1e30f, y0 = -1e30f, x1 = 1e30f, y1 = 1e30f;
    if (cull != nullptr && cull->zoom > 0) {
        const float margin = kCullMarginPx * cull->scale / cull->zoom;
        x0 = cull->cx - cull->ox / cull->zoom - margin;
        x1 = cull->cx + (static_cast<float>(cull->w) - cull->ox) / cull->zoom + margin;
        y0 = cull->cy - (static_cast<float>(cull->h) - cull->oy) / cull->zoom - margin;
        y1 = cull->cy + cull->oy / cull->zoom + margin;
    }
    const auto meets = [&](std::size_t g) {
        if (4 * g + 3 >= path.group_boxes.size()) return true;
        const float* b = path.group_boxes.data() + 4 * g;
        return b[0] <= x1 && b[2] >= x0 && b[1] <= y1 && b[3] >= y0;
    };
    // Runs of groups that meet the view, one draw (per page) each, until the budget is spent.
    constexpr std::size_t G = GpuPath::kCullGroup;
    std::size_t drawn = 0, i = first;
    while (i < last && drawn < budget) {
        const std::size_t group_end = std::min(last, (i / G + 1) * G);
        if (!meets(i / G)) {
            i = group_end;
            continue;
        }
        std::size_t end = group_end;
        while (end < last && drawn + (end - i) < budget && meets(end / G)) end = std::min(last, end + G);
        draw_run(path, i, end);
        drawn += end - i;
        i = end;
    }
    return i;
}

void Renderer::draw_grid(const Target& t, double grid_step, Point world_origin) {
    glUseProgram(grid_program_);
    set_target_uniforms(grid_program_, t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h);
    glUniform2f(glGetUniformLocation(grid_program_, "u_world_origin"), static_cast<float>(world_origin.x),
                static_cast<float>(world_origin.y));
    glUniform1f(glGetUniformLocation(grid_program_, "u_step"), static_cast<float>(grid_step));
    glUniform4f(glGetUniformLocation(grid_program_, "u_minor"), 0.5f, 0.55f, 0.6f, 0.10f);
    glUniform4f(glGetUniformLocation(grid_program_, "u_major"), 0.5f, 0.55f, 0.6f, 0.25f);
    glUniform4f(glGetUniformLocation(grid_program_, "u_axis"), 0.6f, 0.8f, 0.6f, 0.45f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Renderer::begin_paths(const Target& t, int layer_mask) {
    const float s = t.scale;
    glUseProgram(path_program_);
    set_target_uniforms(path_program_, t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h);
    float hw[4] = {0.6f * s, 0.6f * s, 1.1f * s, 1.0f * s};
    glUniform1fv(glGetUniformLocation(path_program_, "u_half_width"), 4, hw);
    glUniform4fv(glGetUniformLocation(path_program_, "u_colors"), 4, &kKindColors[0].r);
    glUniform1i(glGetUniformLocation(path_program_, "u_layer_mask"), layer_mask);
    glUniform4f(glGetUniformLocation(path_program_, "u_override"), 0, 0, 0, 0);
    glUniform1f(glGetUniformLocation(path_program_, "u_extra_width"), 0);
    glUniform1i(glGetUniformLocation(path_program_, "u_segs"), 0);
    glUniform1i(glGetUniformLocation(path_program_, "u_kinds"), 1);
    glUniform1i(glGetUniformLocation(path_program_, "u_tex_width"), kTexWidth);
}

void Renderer::draw_selection(const Target& t, const GpuPath& path, const DrawOptions& o) {
    if (o.selection_count == 0 || o.selection_first >= path.count) return;
    begin_paths(t, 0xF);
    glUniform4f(glGetUniformLocation(path_program_, "u_override"), kSelectionColor.r, kSelectionColor.g,
                kSelectionColor.b, kSelectionColor.a);
    glUniform1f(glGetUniformLocation(path_program_, "u_extra_width"), 1.0f * t.scale);
    draw_segments(path, o.selection_first, o.selection_first + o.selection_count);
}

void Renderer::draw_markers(const Target& t, int marker_mask) {
    if (marker_count_ == 0 || (marker_mask & 3) == 0) return;
    glUseProgram(marker_program_);
    set_target_uniforms(marker_program_, t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h);
    glUniform1f(glGetUniformLocation(marker_program_, "u_radius_px"), 5.0f * t.scale);
    const float mc[12] = {1.0f, 0.25f, 0.2f, 1.0f,   // pierce: red ring
                          0.3f, 0.95f, 0.4f, 1.0f,   // start: green disc
                          1.0f, 1.0f, 1.0f, 1.0f};   // tool: white ring + cross
    glUniform4fv(glGetUniformLocation(marker_program_, "u_colors"), 3, mc);
    glUniform1i(glGetUniformLocation(marker_program_, "u_type_mask"), marker_mask);
    glUniform1i(glGetUniformLocation(marker_program_, "u_markers"), 0);
    glUniform1i(glGetUniformLocation(marker_program_, "u_tex_width"), kTexWidth);
    glUniform1i(glGetUniformLocation(marker_program_, "u_use_single"), 0);
    glBindTexture(GL_TEXTURE_2D, marker_tex_);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(marker_count_ * 6));
}

void Renderer::draw_tool(const Target& t, const DrawOptions& o) {
    if (!o.has_tool) return;
    glUseProgram(marker_program_);
    set_target_uniforms(marker_program_, t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h);
    const float mc[12] = {1.0f, 0.25f, 0.2f, 1.0f, 0.3f, 0.95f, 0.4f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f};
    glUniform4fv(glGetUniformLocation(marker_program_, "u_colors"), 3, mc);
    glUniform1i(glGetUniformLocation(marker_program_, "u_markers"), 0);
    glUniform1i(glGetUniformLocation(marker_program_, "u_tex_width"), kTexWidth);
    glUniform1i(glGetUniformLocation(marker_program_, "u_use_single"), 1);
    glUniform3f(glGetUniformLocation(marker_program_, "u_single"), static_cast<float>(o.tool.x),
                static_cast<float>(o.tool.y), 2.f);
    glUniform1i(glGetUniformLocation(marker_program_, "u_type_mask"), 0x7);
    glUniform1f(glGetUniformLocation(marker_program_, "u_radius_px"), 8.0f * t.scale);
    glBindTexture(GL_TEXTURE_2D, marker_tex_);  // (a sampler must still be bound)
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

bool Renderer::ensure_cache(int w, int h) {
    if (cache_fbo_ != 0 && cache_w_ == w && cache_h_ == h) return true;
    if (cache_fbo_ == 0) {
        glGenFramebuffers(1, &cache_fbo_);
        cache_tex_ = new_texture();
    }
    glBindTexture(GL_TEXTURE_2D, cache_tex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, cache_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, cache_tex_, 0);
    const bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    cache_w_ = ok ? w : 0;
    cache_h_ = ok ? h : 0;
    return ok;
}

void Renderer::draw(const View& view, int fb_w, int fb_h, const DrawOptions& o, double grid_step, Point world_origin,
                    const GpuPath* path) {
    ++stats_.frames;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(empty_vao_);
    glActiveTexture(GL_TEXTURE0);
    const float s = o.framebuffer_scale;
    const float zoom = static_cast<float>(view.zoom * s);
    const Target window{static_cast<float>(view.cx), static_cast<float>(view.cy), zoom, static_cast<float>(view.ox() * s),
                        static_cast<float>(view.oy() * s), fb_w, fb_h, s};
    const std::size_t count = path ? path->count : 0;
    const std::size_t limit = std::min(count, o.segment_limit);
    const int layer_mask = o.layer_mask & 0xF;

    // The scene into target t: the grid (when `full`), the paths [from, limit) that show in t until `budget`
    // segments are drawn, then the markers once every path is in. Returns where the paths stopped.
    const bool lod = o.lod && lod_levels_ > 0;
    auto draw_scene = [&](const Target& t, std::size_t from, bool full, std::size_t budget) -> std::size_t {
        if (full) draw_grid(t, grid_step, world_origin);
        if (lod) {  // the raster has the paths and the pierces; the start marker is drawn as usual
            draw_lod(t, layer_mask | ((o.marker_mask & 1) ? LodRaster::kPierceBit : 0));
            draw_markers(t, o.marker_mask & 2);
            return limit;
        }
        std::size_t reached = limit;
        if (limit > from && layer_mask != 0) {  // every layer hidden: not one vertex to run
            begin_paths(t, layer_mask);
            reached = draw_segments(*path, from, limit, &t, budget);
        }
        const bool markers_due = full || cache_markers_pending_;  // (a fill of the image ends with them)
        if (markers_due && reached == limit) draw_markers(t, o.marker_mask);
        cache_markers_pending_ = markers_due && reached < limit;
        return reached;
    };

    // The drawing area and its margin, in framebuffer pixels (top-left origin).
    const float ax = view.area.x * s, ay = view.area.y * s, aw = view.area.w * s, ah = view.area.h * s;
    const int mx = static_cast<int>(std::ceil(aw * kCacheMarginShare)), my = static_cast<int>(std::ceil(ah * kCacheMarginShare));
    const int cw = static_cast<int>(std::ceil(aw)) + 2 * mx, ch = static_cast<int>(std::ceil(ah)) + 2 * my;
    const bool cache = o.use_cache && cw > 0 && ch > 0 && ensure_cache(cw, ch);
    // The drawing area in GL's scissor terms (bottom-left origin).
    const auto scissor_area = [&] {
        glScissor(static_cast<GLint>(ax), static_cast<GLint>(static_cast<float>(fb_h) - (ay + ah)),
                  static_cast<GLsizei>(std::ceil(aw)), static_cast<GLsizei>(std::ceil(ah)));
    };
    if (!cache) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fb_w, fb_h);
        glClearColor(o.panel_color.r, o.panel_color.g, o.panel_color.b, o.panel_color.a);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        scissor_area();
        glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        draw_scene(window, 0, true, ~std::size_t(0));  // (no image to fill over frames: all at once)
        ++stats_.full_redraws;
        stats_.pending_segments = 0;
        cache_valid_ = false;
    } else {
        const SceneKey key{view.zoom, grid_step, world_origin, layer_mask, o.marker_mask, fb_w, fb_h, s, view.area, path,
                           path ? path->version : 0, markers_version_, lod_version_, lod};
        // Where the image's top-left corner is now: where it was, moved by the pan since (whole pixels).
        const float left = cache_left_ + std::round(static_cast<float>((cache_cx_ - view.cx) * view.zoom * s));
        const float top = cache_top_ + std::round(static_cast<float>((view.cy - cache_cy_) * view.zoom * s));
        const bool covers = left <= ax && top <= ay && left + static_cast<float>(cache_w_) >= ax + aw &&
                            top + static_cast<float>(cache_h_) >= ay + ah;
        const bool same = cache_valid_ && key == cache_key_;
        if (!same || !covers || limit < cache_limit_) {
            // Draw the image for the current view, the area in its middle.
            cache_key_ = key;
            cache_cx_ = view.cx;
            cache_cy_ = view.cy;
            cache_left_ = ax - static_cast<float>(mx);
            cache_top_ = ay - static_cast<float>(my);
            glBindFramebuffer(GL_FRAMEBUFFER, cache_fbo_);
            glViewport(0, 0, cache_w_, cache_h_);
            glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
            glClear(GL_COLOR_BUFFER_BIT);
            const Target t{window.cx, window.cy, zoom, window.ox - cache_left_, window.oy - cache_top_, cache_w_, cache_h_, s};
            cache_limit_ = draw_scene(t, 0, true, kSegmentsPerFrame);
            cache_valid_ = true;
            ++stats_.full_redraws;
        } else if (limit > cache_limit_ && !lod) {
            // The image is still being filled, or playback moved forward: add the next segments to the image
            // (drawn at the image's own view).
            glBindFramebuffer(GL_FRAMEBUFFER, cache_fbo_);
            glViewport(0, 0, cache_w_, cache_h_);
            // The image's own mapping: its centre view (cache_cx_, cache_cy_) at the area's centre.
            const Target own{static_cast<float>(cache_cx_), static_cast<float>(cache_cy_), zoom,
                             static_cast<float>(view.ox() * s) - cache_left_, static_cast<float>(view.oy() * s) - cache_top_,
                             cache_w_, cache_h_, s};
            const bool filling = cache_markers_pending_;
            cache_limit_ = draw_scene(own, cache_limit_, false, kSegmentsPerFrame);
            ++(filling ? stats_.filling_frames : stats_.partial_redraws);
        } else {
            ++stats_.cached_frames;
        }
        stats_.pending_segments = lod || limit <= cache_limit_ ? 0 : limit - cache_limit_;
        // The window: the panels' colour, the image where it is now (it covers the drawing area), then the overlays.
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fb_w, fb_h);
        glClearColor(o.panel_color.r, o.panel_color.g, o.panel_color.b, o.panel_color.a);
        glClear(GL_COLOR_BUFFER_BIT);
        const float now_left = cache_left_ + std::round(static_cast<float>((cache_cx_ - view.cx) * view.zoom * s));
        const float now_top = cache_top_ + std::round(static_cast<float>((view.cy - cache_cy_) * view.zoom * s));
        glEnable(GL_SCISSOR_TEST);
        scissor_area();
        glDisable(GL_BLEND);
        glUseProgram(blit_program_);
        glUniform4f(glGetUniformLocation(blit_program_, "u_rect"), now_left, now_top, static_cast<float>(cache_w_),
                    static_cast<float>(cache_h_));
        glUniform2f(glGetUniformLocation(blit_program_, "u_viewport"), static_cast<float>(fb_w), static_cast<float>(fb_h));
        glUniform1i(glGetUniformLocation(blit_program_, "u_image"), 0);
        glBindTexture(GL_TEXTURE_2D, cache_tex_);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        glEnable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
    }
    // Overlays drawn every frame at the current view: the selection and the playback tool.
    if (path != nullptr && layer_mask != 0) draw_selection(window, *path, o);
    draw_tool(window, o);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace essi::viewer
