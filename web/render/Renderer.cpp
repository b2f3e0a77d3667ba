#include "render/Renderer.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/GridLines.hpp"

namespace essi::viewer {

namespace {

// The image around the drawing area: this share of the area's width (height) on each side.
constexpr float kCacheMarginShare = 0.5f;
// Line half widths by MotionKind, in window pixels: rapid, travel, cut, mark.
constexpr float kHalfWidthPx[kPathColors] = {0.6f, 0.6f, 1.1f,
                                             1.0f, 0.6f, 1.1f};  // (a band: at least as wide as a cut)
constexpr float kSelectionExtraPx = 1.0f;                        // the selection is drawn this much wider on each side
constexpr float kMarkerRadiusPx = 5.0f;
constexpr float kToolRadiusPx = 8.0f;
// "Everything" for the culling box (mm): wider than any tape.
constexpr float kUnbounded = 1e30f;

}  // namespace

std::size_t GpuPath::gpu_bytes() const {
    std::size_t n = 0;
    for (const GpuPage& p : pages) n += p.rows * Renderer::kTexWidth * 17;
    return n;
}

bool Renderer::init() {
    if (!programs_.init(kTexWidth)) return false;
    glGenVertexArrays(1, &empty_vao_);
    marker_tex_ = new_texture();
    glBindTexture(GL_TEXTURE_2D, 0);
    return true;
}

void Renderer::set_theme(const Theme& theme) {
    theme_ = theme;
    programs_.set_theme(theme);
    cache_valid_ = false;
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
        add_group_boxes(path, b.staged_ends.data(), first, n);
        b.drop_staged(n);
        path.count += n;
        path.version = ++version_counter_;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

// The boxes of the groups that segments [first, first + n) are in (`ends`: 4 floats a segment).
void Renderer::add_group_boxes(GpuPath& path, const float* ends, std::size_t first, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        const float* e = ends + 4 * k;
        const std::size_t g = (first + k) / GpuPath::kCullGroup;
        if (4 * g == path.group_boxes.size()) path.group_boxes.insert(path.group_boxes.end(), {e[0], e[1], e[0], e[1]});
        float* box = path.group_boxes.data() + 4 * g;
        box[0] = std::min({box[0], e[0], e[2]});
        box[1] = std::min({box[1], e[1], e[3]});
        box[2] = std::max({box[2], e[0], e[2]});
        box[3] = std::max({box[3], e[1], e[3]});
    }
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
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTexWidth, static_cast<GLsizei>(rows), 0, GL_RGBA, GL_FLOAT,
                 data.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    marker_count_ = n;
    marks_first_ = n;
    while (marks_first_ > 0 && markers[marks_first_ - 1].type >= static_cast<float>(MarkerType::Error)) --marks_first_;
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
    const LodProgram& p = programs_.lod;
    glUseProgram(p.id);
    p.target.set(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot);
    glUniform4f(p.rect, 0.f, 0.f, static_cast<float>(t.w), static_cast<float>(t.h));
    glUniform1i(p.level, level);
    glUniform1f(p.cell, static_cast<float>(lod_cell_ * std::ldexp(1.0, level)));
    glUniform2f(p.min, lod_min_x_, lod_min_y_);
    glUniform1i(p.mask, mask);
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
        glUniform1i(programs_.path.first, static_cast<GLint>(a - pg.first));
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
    float x0 = -kUnbounded, y0 = -kUnbounded, x1 = kUnbounded, y1 = kUnbounded;
    if (cull != nullptr && cull->zoom > 0) {
        // The target's corners in mm (turned back by the view's rotation), their box widened.
        const float margin = kCullMarginPx * cull->scale / cull->zoom;
        x0 = y0 = kUnbounded;
        x1 = y1 = -kUnbounded;
        for (const float sx : {0.f, static_cast<float>(cull->w)})
            for (const float sy : {0.f, static_cast<float>(cull->h)}) {
                const Point d = cull->rot.undo({(sx - cull->ox) / cull->zoom, (cull->oy - sy) / cull->zoom});
                x0 = std::min(x0, cull->cx + static_cast<float>(d.x));
                x1 = std::max(x1, cull->cx + static_cast<float>(d.x));
                y0 = std::min(y0, cull->cy + static_cast<float>(d.y));
                y1 = std::max(y1, cull->cy + static_cast<float>(d.y));
            }
        x0 -= margin;
        y0 -= margin;
        x1 += margin;
        y1 += margin;
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

// The grid lies along the shown coordinates' axes (View::plate): its target is t with the centre in those
// coordinates and the orientation's quarter turns only.
Renderer::Target Renderer::grid_target(const Target& t, const View& view) {
    Target g = t;
    const Point c = view.plate.apply({t.cx, t.cy});
    g.cx = static_cast<float>(c.x);
    g.cy = static_cast<float>(c.y);
    g.rot = Rotation::quarter(view.turns);
    return g;
}

void Renderer::draw_grid(const Target& t, double grid_step, Point world_origin) {
    const GridLines g = grid_lines(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot, grid_step, world_origin);
    const GridProgram& p = programs_.grid;
    glUseProgram(p.id);
    p.target.set(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot);
    auto f = [](double v) { return static_cast<float>(v); };
    glUniform2f(p.first, f(g.first_x), f(g.first_y));
    glUniform1f(p.step, f(g.step));
    glUniform2i(p.count, g.count_x, g.count_y);
    glUniform2i(p.major_phase, major_phase(g.first_index_x), major_phase(g.first_index_y));
    glUniform2i(p.zero, line_on_axis(g.first_index_x, g.count_x), line_on_axis(g.first_index_y, g.count_y));
    glUniform2f(p.axes_at, f(g.axis_x), f(g.axis_y));
    glUniform4f(p.span, f(g.lo_x), f(g.lo_y), f(g.hi_x), f(g.hi_y));
    glDrawArrays(GL_TRIANGLES, 0, 6 * (g.count_x + g.count_y + 2));
}

void Renderer::begin_paths(const Target& t, int layer_mask, const DrawOptions& o, float alpha) {
    const PathProgram& p = programs_.path;
    glUseProgram(p.id);
    p.target.set(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot);
    float hw[kPathColors];
    for (std::size_t k = 0; k < kPathColors; ++k) hw[k] = kHalfWidthPx[k] * t.scale;
    glUniform1fv(p.half_width, kPathColors, hw);
    float band[kKerfBandWidths];
    for (std::size_t k = 0; k < kKerfBandWidths; ++k) band[k] = o.kerf_band_mm[k] / 2;
    glUniform1fv(p.band_half_mm, kKerfBandWidths, band);
    glUniform1i(p.layer_mask, layer_mask);
    glUniform4f(p.override_color, 0, 0, 0, 0);
    glUniform1f(p.extra_width, 0);
    glUniform1f(p.alpha, alpha);
}

void Renderer::draw_selection(const Target& t, const GpuPath& path, const DrawOptions& o) {
    if (o.selection_count == 0 || o.selection_first >= path.count) return;
    begin_paths(t, kAllKindsMask, o);  // (the motions only: the kerf layers are not selected)
    const Rgba& c = kSelectionColor;
    glUniform4f(programs_.path.override_color, c.r, c.g, c.b, c.a);
    glUniform1f(programs_.path.extra_width, kSelectionExtraPx * t.scale);
    draw_segments(path, o.selection_first, o.selection_first + o.selection_count);
}

// The markers of the texture: pierces, the start point and the diagnostics' marks (uploaded last: on top). `dim`:
// the pierces and the start faint (the problems-only view).
void Renderer::draw_markers(const Target& t, int marker_mask, bool dim) {
    constexpr int kTextureMarkers =
        marker_bit(MarkerType::Pierce) | marker_bit(MarkerType::Start) | kDiagnosticMarkersMask;
    if (marker_count_ == 0 || (marker_mask & kTextureMarkers) == 0) return;
    const MarkerProgram& p = programs_.marker;
    glUseProgram(p.id);
    p.target.set(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot);
    glUniform1f(p.radius_px, kMarkerRadiusPx * t.scale);
    glUniform1f(p.mark_radius_px, kMarkRadiusPx * t.scale);
    glUniform1f(p.plain_alpha, dim ? kDimAlpha : 1.f);
    glUniform1i(p.type_mask, marker_mask);
    glUniform1i(p.use_single, 0);
    glBindTexture(GL_TEXTURE_2D, marker_tex_);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(marker_count_ * 6));
}

void Renderer::draw_bright(const Frame& f, const Target& t) {
    if (f.path == nullptr || f.layer_mask == 0 || f.o.bright.empty()) return;
    begin_paths(t, f.layer_mask, f.o);
    for (const SegmentRun& r : f.o.bright) draw_segments(*f.path, r.first, std::min(r.first + r.count, f.limit), &t);
}

void Renderer::draw_highlights(const Target& t, const GpuPath& path, const DrawOptions& o) {
    if (o.highlights.empty()) return;
    begin_paths(t, kAllKindsMask, o);  // (the motions only)
    for (const Highlight& h : o.highlights) {
        glUniform4f(programs_.path.override_color, h.color.r, h.color.g, h.color.b, h.color.a);
        glUniform1f(programs_.path.extra_width, h.extra_px * t.scale);
        draw_segments(path, h.run.first, h.run.first + h.run.count, &t);
    }
}

void Renderer::draw_marks_on_top(const Target& t) {
    if (marks_first_ >= marker_count_) return;
    const MarkerProgram& p = programs_.marker;
    glUseProgram(p.id);
    p.target.set(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot);
    glUniform1f(p.mark_radius_px, kMarkRadiusPx * t.scale);
    glUniform1i(p.type_mask, kDiagnosticMarkersMask);
    glUniform1i(p.use_single, 0);
    glUniform1i(p.first, static_cast<GLint>(marks_first_));
    glBindTexture(GL_TEXTURE_2D, marker_tex_);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>((marker_count_ - marks_first_) * 6));
    glUniform1i(p.first, 0);
}

void Renderer::draw_tool(const Target& t, const DrawOptions& o) {
    if (!o.has_tool) return;
    const MarkerProgram& p = programs_.marker;
    glUseProgram(p.id);
    p.target.set(t.cx, t.cy, t.zoom, t.ox, t.oy, t.w, t.h, t.rot);
    glUniform1i(p.use_single, 1);
    glUniform3f(p.single, static_cast<float>(o.tool.x), static_cast<float>(o.tool.y),
                static_cast<float>(MarkerType::Tool));
    glUniform1i(p.type_mask, kAllMarkersMask);
    glUniform1f(p.radius_px, kToolRadiusPx * t.scale);
    glUniform1f(p.plain_alpha, 1.f);
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

// What every program of the scene draws with: blending, no depth, no culling, the attribute-less vertex array.
void Renderer::begin_scene_state() const {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(empty_vao_);
    glActiveTexture(GL_TEXTURE0);
}

void Renderer::end_scene_state() const {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
    glUseProgram(0);
}

void Renderer::warm_up(const GpuPath& path, Point center, double zoom) {
    constexpr int kPx = kWarmUpImagePx;
    const unsigned tex = new_texture();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kPx, kPx, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // (as the image's)
    glBindTexture(GL_TEXTURE_2D, 0);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
        glViewport(0, 0, kPx, kPx);
        begin_scene_state();
        const float half = static_cast<float>(kPx) / 2;
        const Target t{static_cast<float>(center.x),
                       static_cast<float>(center.y),
                       static_cast<float>(zoom),
                       half,
                       half,
                       kPx,
                       kPx,
                       1.f,
                       Rotation{}};
        begin_paths(t, kAllPathMask, DrawOptions{});
        draw_run(path, 0, path.count);
        draw_markers(t, kAllMarkersMask, false);
        end_scene_state();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
}

// How far the cached image has moved on the screen since it was drawn (framebuffer pixels): the pan since, turned
// as the view is.
Point Renderer::pan_px(const View& view, float s) const {
    const Point r = view.rotation().apply({cache_cx_ - view.cx, cache_cy_ - view.cy});
    return {r.x * view.zoom * s, -r.y * view.zoom * s};
}

std::size_t Renderer::draw_scene(const Frame& f, const Target& t, std::size_t from, bool full, std::size_t budget) {
    constexpr int kStart = marker_bit(MarkerType::Start);
    if (full) draw_grid(grid_target(t, f.view), f.grid_step, f.world_origin);
    if (f.lod) {  // the raster has the paths and the pierces; the start marker is drawn as usual
        const bool pierces = (f.o.marker_mask & marker_bit(MarkerType::Pierce)) != 0;
        draw_lod(t, (f.layer_mask & kAllKindsMask) | (pierces ? LodRaster::kPierceBit : 0));
        draw_markers(t, f.o.marker_mask & (kStart | kDiagnosticMarkersMask), false);
        return f.limit;
    }
    std::size_t reached = f.limit;
    if (f.limit > from && f.layer_mask != 0) {  // every layer hidden: not one vertex to run
        begin_paths(t, f.layer_mask, f.o, f.o.dim ? kDimAlpha : 1.f);
        reached = draw_segments(*f.path, from, f.limit, &t, budget);
    }
    const bool markers_due = full || cache_markers_pending_;  // (a fill of the image ends with them)
    if (markers_due && reached == f.limit) {
        if (f.o.dim) draw_bright(f, t);
        draw_markers(t, f.o.marker_mask, f.o.dim);
    }
    cache_markers_pending_ = markers_due && reached < f.limit;
    return reached;
}

// The drawing area in GL's scissor terms (bottom-left origin).
void Renderer::scissor_area(const Frame& f) const {
    glScissor(static_cast<GLint>(f.ax), static_cast<GLint>(static_cast<float>(f.fb_h) - (f.ay + f.ah)),
              static_cast<GLsizei>(std::ceil(f.aw)), static_cast<GLsizei>(std::ceil(f.ah)));
}

void Renderer::clear_window(const Frame& f) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, f.fb_w, f.fb_h);
    glClearColor(f.o.panel_color.r, f.o.panel_color.g, f.o.panel_color.b, f.o.panel_color.a);
    glClear(GL_COLOR_BUFFER_BIT);
}

void Renderer::draw_uncached(const Frame& f) {
    clear_window(f);
    glEnable(GL_SCISSOR_TEST);
    scissor_area(f);
    glClearColor(theme_.background.r, theme_.background.g, theme_.background.b, theme_.background.a);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    draw_scene(f, f.window, 0, true, ~std::size_t(0));  // (no image to fill over frames: all at once)
    ++stats_.full_redraws;
    stats_.pending_segments = 0;
    cache_valid_ = false;
}

void Renderer::update_image(const Frame& f) {
    const View& view = f.view;
    const float s = f.scale;
    const SceneKey key{view.zoom,
                       f.grid_step,
                       f.world_origin,
                       f.layer_mask,
                       f.o.marker_mask,
                       f.fb_w,
                       f.fb_h,
                       s,
                       view.area,
                       f.path,
                       f.path ? f.path->version : 0,
                       markers_version_,
                       lod_version_,
                       f.lod,
                       view.rotation(),
                       f.o.dim && !f.lod,
                       f.o.dim && !f.lod ? f.o.bright : std::vector<SegmentRun>{}};
    // Where the image's top-left corner is now: where it was, moved by the pan since (whole pixels).
    const Point moved = pan_px(view, s);
    const float left = cache_left_ + std::round(static_cast<float>(moved.x));
    const float top = cache_top_ + std::round(static_cast<float>(moved.y));
    const bool covers = left <= f.ax && top <= f.ay && left + static_cast<float>(cache_w_) >= f.ax + f.aw &&
                        top + static_cast<float>(cache_h_) >= f.ay + f.ah;
    const bool same = cache_valid_ && key == cache_key_;
    if (!same || !covers || f.limit < cache_limit_) {
        // Draw the image for the current view, the area in its middle.
        cache_key_ = key;
        cache_cx_ = view.cx;
        cache_cy_ = view.cy;
        cache_left_ = f.ax - static_cast<float>(f.mx);
        cache_top_ = f.ay - static_cast<float>(f.my);
        glBindFramebuffer(GL_FRAMEBUFFER, cache_fbo_);
        glViewport(0, 0, cache_w_, cache_h_);
        glClearColor(theme_.background.r, theme_.background.g, theme_.background.b, theme_.background.a);
        glClear(GL_COLOR_BUFFER_BIT);
        const Target& w = f.window;
        const Target t{w.cx, w.cy, w.zoom, w.ox - cache_left_, w.oy - cache_top_, cache_w_, cache_h_, s, w.rot};
        cache_limit_ = draw_scene(f, t, 0, true, f.fill_budget);
        cache_valid_ = true;
        ++stats_.full_redraws;
    } else if (f.limit > cache_limit_ && !f.lod) {
        // The image is still being filled, or playback moved forward: add the next segments to the image
        // (drawn at the image's own view).
        glBindFramebuffer(GL_FRAMEBUFFER, cache_fbo_);
        glViewport(0, 0, cache_w_, cache_h_);
        // The image's own mapping: its centre view (cache_cx_, cache_cy_) at the area's centre.
        const Target own{static_cast<float>(cache_cx_),
                         static_cast<float>(cache_cy_),
                         f.window.zoom,
                         static_cast<float>(view.ox() * s) - cache_left_,
                         static_cast<float>(view.oy() * s) - cache_top_,
                         cache_w_,
                         cache_h_,
                         s,
                         f.window.rot};
        const bool filling = cache_markers_pending_;
        cache_limit_ = draw_scene(f, own, cache_limit_, false, f.fill_budget);
        ++(filling ? stats_.filling_frames : stats_.partial_redraws);
    } else {
        ++stats_.cached_frames;
    }
    stats_.pending_segments = f.lod || f.limit <= cache_limit_ ? 0 : f.limit - cache_limit_;
}

// The window: the panels' colour, the image where it is now (it covers the drawing area).
void Renderer::blit_image(const Frame& f) {
    const View& view = f.view;
    const float s = f.scale;
    clear_window(f);
    const Point moved = pan_px(view, s);
    const float now_left = cache_left_ + std::round(static_cast<float>(moved.x));
    const float now_top = cache_top_ + std::round(static_cast<float>(moved.y));
    glEnable(GL_SCISSOR_TEST);
    scissor_area(f);
    glDisable(GL_BLEND);
    const BlitProgram& p = programs_.blit;
    glUseProgram(p.id);
    glUniform4f(p.rect, now_left, now_top, static_cast<float>(cache_w_), static_cast<float>(cache_h_));
    glUniform2f(p.viewport, static_cast<float>(f.fb_w), static_cast<float>(f.fb_h));
    glBindTexture(GL_TEXTURE_2D, cache_tex_);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glEnable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::draw(const View& view, int fb_w, int fb_h, const DrawOptions& o, double grid_step, Point world_origin,
                    const GpuPath* path, std::size_t fill_budget) {
    ++stats_.frames;
    begin_scene_state();
    const float s = o.framebuffer_scale;
    const Target window{static_cast<float>(view.cx),
                        static_cast<float>(view.cy),
                        static_cast<float>(view.zoom * s),
                        static_cast<float>(view.ox() * s),
                        static_cast<float>(view.oy() * s),
                        fb_w,
                        fb_h,
                        s,
                        view.rotation()};
    const std::size_t count = path ? path->count : 0;
    const float aw = view.area.w * s, ah = view.area.h * s;
    const Frame f{view,
                  fb_w,
                  fb_h,
                  o,
                  grid_step,
                  world_origin,
                  path,
                  s,
                  window,
                  std::min(count, o.segment_limit),
                  o.layer_mask & kAllPathMask,
                  o.lod && lod_levels_ > 0,
                  view.area.x * s,
                  view.area.y * s,
                  aw,
                  ah,
                  static_cast<int>(std::ceil(aw * kCacheMarginShare)),
                  static_cast<int>(std::ceil(ah * kCacheMarginShare)),
                  fill_budget};
    const int cw = static_cast<int>(std::ceil(aw)) + 2 * f.mx, ch = static_cast<int>(std::ceil(ah)) + 2 * f.my;
    if (cw > 0 && ch > 0 && ensure_cache(cw, ch)) {
        update_image(f);
        blit_image(f);
    } else {
        draw_uncached(f);
    }
    // Overlays drawn every frame at the current view: the selection and the playback tool.
    if (path != nullptr) draw_highlights(window, *path, o);
    if (path != nullptr && f.layer_mask != 0) draw_selection(window, *path, o);
    // (what the highlights and the selection cover of the marks: a hovered or selected diagnostic's mark)
    if (!o.highlights.empty() || o.selection_count > 0) draw_marks_on_top(window);
    draw_tool(window, o);
    end_scene_state();
}

}  // namespace essi::viewer
