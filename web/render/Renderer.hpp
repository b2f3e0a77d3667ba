// Draws the grid, the flattened motion and the markers with the programs in shaders/ (OpenGL ES 3.0:
// WebGL2 in the browser, a GLES 3 context natively). The segments live in textures of kTexWidth segments a row,
// split into pages of at most kPageRows rows, filled a few rows at a time while the drawing is built (append):
// no frame uploads the whole stream, and the texture height never reaches the GPU's limit.
//
// The grid, the paths and the markers are drawn into an offscreen image (a framebuffer texture) that covers
// the drawing area and a margin around it. A frame whose zoom, layers, playback and geometry are those of the
// image only draws the image, moved by the pan since it was drawn, and the small overlays (selection, tool):
// panning costs one textured rectangle. The image is drawn again when one of those changes or when a pan
// leaves its margin (a CPU renderer such as SwiftShader needs seconds for a million segments).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "app/View.hpp"
#include "render/LodRaster.hpp"
#include "render/GlPrograms.hpp"
#include "render/PathBuffers.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

// Segments [first, first + count) of the drawn path.
struct SegmentRun {
    std::size_t first = 0, count = 0;
    bool operator==(const SegmentRun&) const = default;
};
// Segments drawn over the scene every frame in one colour, `extra_px` wider on each side (a diagnostic's contour
// and its related places, hovered or selected).
struct Highlight {
    SegmentRun run;
    Rgba color;
    float extra_px = 0;
    bool operator==(const Highlight&) const = default;
};

struct DrawOptions {
    int layer_mask = kAllPathMask;                      // a bit per MotionKind (kind_bit), kKerfPathBit, kKerfBandBit
    std::array<float, kKerfBandWidths> kerf_band_mm{};  // the kerf bands' widths (PathBuffers::kerf_widths)
    int marker_mask = kAllMarkersMask;                  // a bit per MarkerType (marker_bit)
    std::size_t segment_limit = ~std::size_t(0);        // playback: draw segments [0, limit)
    std::size_t selection_first = 0, selection_count = 0;  // segments drawn highlighted
    bool has_tool = false;                                 // playback: the tool marker
    Point tool;                                            // relative to the document origin
    float framebuffer_scale = 1;
    bool lod = false;                 // draw the level-of-detail raster instead of the segments (and pierces)
    Rgba panel_color = {0, 0, 0, 1};  // the window around the drawing area (the panels draw no background)
    // The problems-only view: every motion and marker drawn at kDimAlpha, then `bright` (what the diagnostics
    // concern) again in full, and the diagnostics' marks in full (not with the level of detail).
    bool dim = false;
    std::vector<SegmentRun> bright;
    std::vector<Highlight> highlights;  // over everything but the selection
    bool operator==(const DrawOptions&) const = default;
};

// What the last frames cost (the e2e tests check that a pan reuses the image and a zoom redraws it).
struct RenderStats {
    std::uint64_t frames = 0;
    std::uint64_t full_redraws = 0;     // the whole scene drawn (into the image or the window)
    std::uint64_t partial_redraws = 0;  // playback moved forward: only the new segments drawn into the image
    std::uint64_t cached_frames = 0;    // the image reused, moved by the pan
    std::uint64_t filling_frames = 0;   // frames that went on drawing an image too big for one frame
    std::size_t pending_segments = 0;   // segments of the current image still to draw (0: it is complete)
};

// One page of segments: RGBA32F x0 y0 x1 y1 and R8UI kind, kTexWidth segments a row.
struct GpuPage {
    unsigned seg_tex = 0, kind_tex = 0;
    std::size_t first = 0;  // its first segment
    std::size_t rows = 0;
};

// A segment set on the GPU: [0, count) uploaded.
struct GpuPath {
    static constexpr std::size_t kCullGroup = 256;  // segments a box
    std::vector<GpuPage> pages;
    // The box of every kCullGroup segments (min x, min y, max x, max y; mm relative to the document origin): a
    // zoomed-in view draws only the groups that meet it.
    std::vector<float> group_boxes;
    std::size_t count = 0;
    std::uint64_t version = 0;  // changes whenever its content does (the cached image depends on it)
    [[nodiscard]] std::size_t gpu_bytes() const;
};

class Renderer {
public:
    static constexpr int kTexWidth = 4096;          // segments a texture row (GLES 3 guarantees 2048; WebGL2 4096+)
    static constexpr std::size_t kPageRows = 256;   // rows a page at most: 1 M segments, 17 MB
    static constexpr std::size_t kRowQuantum = 16;  // page heights are multiples of this
    // Segments drawn into the image a frame at most: SwiftShader draws about a million segments a second, so a
    // zoomed-in view of a big tape fills its image over several frames instead of freezing the page (the
    // pan, the zoom and the panels go on meanwhile; what is drawn so far shows).
    static constexpr std::size_t kSegmentsPerFrame = 150000;
    static constexpr std::size_t kWholeImage = ~std::size_t(0);  // draw()'s fill budget: the whole image at once
    static constexpr float kCullMarginPx = 8;  // a group's box meets the view when it is this close (line widths)
    static constexpr float kDimAlpha = 0.18f;  // the problems-only view: what no diagnostic concerns
    static constexpr float kMarkRadiusPx = 8;  // a diagnostic's mark (window pixels, the same at every zoom)

    bool init();  // compiles the programs and finds their uniforms; false (program_error()) when the GPU refuses them
    // The theme's colours (background, grid, tool marker); the cached image is drawn again.
    void set_theme(const Theme& theme);
    [[nodiscard]] const Theme& theme() const { return theme_; }
    // Moves the whole rows staged in `b` to `path` (and the last, partial row once `b` is complete).
    void append(GpuPath& path, PathBuffers& b);
    void release(GpuPath& path);
    void upload_markers(const std::vector<MarkerInstance>& markers);
    void upload_lod(const LodRaster& lod);  // a finished raster, every level
    void clear_lod();
    [[nodiscard]] bool has_lod() const { return lod_levels_ > 0; }
    [[nodiscard]] double lod_cell_mm() const { return lod_cell_; }
    [[nodiscard]] std::size_t lod_gpu_bytes() const { return lod_bytes_; }
    // The finest LOD level whose cells are at least a pixel at `zoom_px_per_mm` (the raster is used when
    // even the finest cells are at most kLodMaxCellPx).
    [[nodiscard]] int lod_level(double zoom_px_per_mm) const;
    static constexpr double kLodMaxCellPx = 1.0;
    // `grid_origin`: the document origin in the shown coordinates (the grid lies along their axes, View::plate).
    // `fill_budget`: segments drawn into the image this frame at most (kWholeImage: all of them).
    void draw(const View& view, int fb_w, int fb_h, const DrawOptions& options, double grid_step_mm, Point grid_origin,
              const GpuPath* path, std::size_t fill_budget = kSegmentsPerFrame);

    // Draws `path` and the markers once, as a frame's scene draws them, into a small image of their own that is
    // then deleted (nothing on the screen changes, nothing counts in stats()): the GPU prepares what drawing them
    // takes (SwiftShader compiles a program's code on its first draw) before a tape is dropped (app/WarmUp.hpp).
    // `center` (mm relative to the document origin) and `zoom` (px/mm) place the drawing in the image.
    void warm_up(const GpuPath& path, Point center, double zoom);
    static constexpr int kWarmUpImagePx = 64;

    [[nodiscard]] const RenderStats& stats() const { return stats_; }
    // The image is still being filled: the next frames must be drawn even when nothing changed.
    [[nodiscard]] bool filling() const { return stats_.pending_segments > 0; }

private:
    // Where a pass draws: the view mapped into a target of w x h pixels, u_center drawn at (ox, oy).
    struct Target {
        float cx, cy, zoom, ox, oy;
        int w, h;
        float scale;
        Rotation rot;  // View::rotation()
    };
    // One draw() call: its arguments and what follows from them.
    struct Frame {
        const View& view;
        int fb_w, fb_h;
        const DrawOptions& o;
        double grid_step;
        Point world_origin;
        const GpuPath* path;
        float scale;        // framebuffer pixels a window pixel
        Target window;      // the view in the window's framebuffer
        std::size_t limit;  // segments [0, limit) are drawn (playback)
        int layer_mask;
        bool lod;                 // the raster instead of the segments
        float ax, ay, aw, ah;     // the drawing area in framebuffer pixels (top-left origin)
        int mx, my;               // the image's margin on each side
        std::size_t fill_budget;  // segments drawn into the image at most (kSegmentsPerFrame, kWholeImage)
    };
    // The state the cached image was drawn for (a pan is not part of it).
    struct SceneKey {
        double zoom = 0, grid_step = 0;
        Point world_origin;
        int layer_mask = 0, marker_mask = 0, fb_w = 0, fb_h = 0;
        float scale = 0;
        Rect area;
        const GpuPath* path = nullptr;
        std::uint64_t path_version = 0, markers_version = 0, lod_version = 0;
        bool lod = false;
        Rotation rot;
        bool dim = false;
        std::vector<SegmentRun> bright;
        bool operator==(const SceneKey&) const = default;
    };
    void add_page(GpuPath& path, std::size_t first, std::size_t rows);
    void add_group_boxes(GpuPath& path, const float* ends, std::size_t first, std::size_t n);
    void draw_run(const GpuPath& path, std::size_t first, std::size_t end);
    // Segments [first, last) of `path`, those of the groups whose box meets `cull` (all when null), until about
    // `budget` are drawn; returns where it stopped (`last` when it drew them all).
    std::size_t draw_segments(const GpuPath& path, std::size_t first, std::size_t last, const Target* cull = nullptr,
                              std::size_t budget = ~std::size_t(0));
    [[nodiscard]] static Target grid_target(const Target& t, const View& view);
    void draw_grid(const Target& t, double grid_step, Point world_origin);
    void begin_paths(const Target& t, int layer_mask, const DrawOptions& o, float alpha = 1);
    [[nodiscard]] Point pan_px(const View& view, float s) const;
    void draw_markers(const Target& t, int marker_mask, bool dim);
    void draw_bright(const Frame& f, const Target& t);  // the problems-only view's concerned segments
    void draw_highlights(const Target& t, const GpuPath& path, const DrawOptions& o);
    void draw_marks_on_top(const Target& t);  // the diagnostics' marks again, over the highlights
    void draw_selection(const Target& t, const GpuPath& path, const DrawOptions& o);
    void draw_tool(const Target& t, const DrawOptions& o);
    void draw_lod(const Target& t, int mask);
    void begin_scene_state() const;  // the GL state the scene's programs draw with
    void end_scene_state() const;    // textures, vertex array and program unbound
    bool ensure_cache(int w, int h);
    // The scene into target t: the grid (when `full`), the paths [from, f.limit) that show in t until `budget`
    // segments are drawn, then the markers once every path is in. Returns where the paths stopped.
    std::size_t draw_scene(const Frame& f, const Target& t, std::size_t from, bool full, std::size_t budget);
    void scissor_area(const Frame& f) const;
    void clear_window(const Frame& f) const;  // the panels' colour
    void draw_uncached(const Frame& f);       // everything into the window (no image: the GPU refused it)
    void update_image(const Frame& f);        // draws the image again, or adds to it, when needed
    void blit_image(const Frame& f);          // the image into the window, moved by the pan

    ScenePrograms programs_;
    Theme theme_ = kDarkTheme;
    unsigned lod_tex_ = 0;
    int lod_levels_ = 0;
    double lod_cell_ = 1;
    float lod_min_x_ = 0, lod_min_y_ = 0;
    std::size_t lod_bytes_ = 0;
    std::uint64_t lod_version_ = 0;
    unsigned cache_fbo_ = 0, cache_tex_ = 0;
    int cache_w_ = 0, cache_h_ = 0;
    bool cache_valid_ = false;
    SceneKey cache_key_;
    std::size_t cache_limit_ = 0;           // segments [0, limit) are in the image
    bool cache_markers_pending_ = false;    // the markers go on top once the image's segments are all in
    double cache_cx_ = 0, cache_cy_ = 0;    // the view centre (mm) the image was drawn at
    float cache_left_ = 0, cache_top_ = 0;  // the image's top-left corner in window pixels, then
    std::uint64_t version_counter_ = 0, markers_version_ = 0;
    RenderStats stats_;

    unsigned empty_vao_ = 0;   // the programs pull their data by gl_VertexID: no attributes
    unsigned marker_tex_ = 0;  // RGBA32F x y type, kTexWidth a row
    std::size_t marker_count_ = 0;
    std::size_t marks_first_ = 0;  // the diagnostics' marks are markers [marks_first_, marker_count_)
};

}  // namespace essi::viewer
