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
#include "render/PathBuffers.hpp"

struct ImDrawData;

namespace essi::viewer {

struct Rgba {
    float r, g, b, a;
    bool operator==(const Rgba&) const = default;
};

struct DrawOptions {
    int layer_mask = 0xF;          // bit per MotionKind
    int marker_mask = 0x7;         // bit per MarkerType
    std::size_t segment_limit = ~std::size_t(0);  // playback: draw segments [0, limit)
    std::size_t selection_first = 0, selection_count = 0;  // segments drawn highlighted
    bool has_tool = false;         // playback: the tool marker
    Point tool;                    // relative to the document origin
    float framebuffer_scale = 1;
    bool use_cache = true;         // false: draw everything into the window every frame
    bool lod = false;              // draw the level-of-detail raster instead of the segments (and pierces)
    Rgba panel_color = {0, 0, 0, 1};  // the window around the drawing area (the panels draw no background)
    bool operator==(const DrawOptions&) const = default;
};

// What the last frames cost (the e2e tests check that a pan reuses the image and a zoom redraws it).
struct RenderStats {
    std::uint64_t frames = 0;
    std::uint64_t full_redraws = 0;    // the whole scene drawn (into the image or the window)
    std::uint64_t partial_redraws = 0; // playback moved forward: only the new segments drawn into the image
    std::uint64_t cached_frames = 0;   // the image reused, moved by the pan
    std::uint64_t filling_frames = 0;  // frames that went on drawing an image too big for one frame
    std::size_t pending_segments = 0;  // segments of the current image still to draw (0: it is complete)
};

// Colours by MotionKind: rapid, travel, cut, mark (also used by the UI legend and the e2e test).
inline constexpr std::array<Rgba, 4> kKindColors = {{
    {0.42f, 0.55f, 0.75f, 0.75f},  // rapid: blue-grey
    {0.55f, 0.62f, 0.70f, 0.75f},  // travel: grey
    {1.00f, 0.55f, 0.10f, 1.00f},  // cut: orange #ff8c1a
    {0.85f, 0.35f, 0.95f, 1.00f},  // mark: violet
}};
inline constexpr Rgba kBackground = {0.11f, 0.12f, 0.14f, 1.f};
inline constexpr Rgba kSelectionColor = {0.25f, 0.95f, 1.0f, 1.f};

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
    static constexpr int kTexWidth = 4096;        // segments a texture row (GLES 3 guarantees 2048; WebGL2 4096+)
    static constexpr std::size_t kPageRows = 256;  // rows a page at most: 1 M segments, 17 MB
    static constexpr std::size_t kRowQuantum = 16; // page heights are multiples of this
    // Segments drawn into the image a frame at most: SwiftShader draws about a million segments a second, so a
    // zoomed-in view of a big tape fills its image over several frames instead of freezing the page (the
    // pan, the zoom and the panels go on meanwhile; what is drawn so far shows).
    static constexpr std::size_t kSegmentsPerFrame = 150000;
    static constexpr float kCullMarginPx = 8;  // a group's box meets the view when it is this close (line widths)

    bool init();  // compiles the programs; false (and a message) when the GPU refuses them
    [[nodiscard]] const char* error() const { return error_; }
    // Moves the whole rows staged in `b` to `path` (and the last, partial row once `b` is complete).
    void append(GpuPath& path, PathBuffers& b);
    void release(GpuPath& path);
    void upload_markers(const std::vector<MarkerInstance>& markers);
    void clear_markers() { marker_count_ = 0; }
    void upload_lod(const LodRaster& lod);  // a finished raster, every level
    void clear_lod();
    [[nodiscard]] bool has_lod() const { return lod_levels_ > 0; }
    [[nodiscard]] double lod_cell_mm() const { return lod_cell_; }
    [[nodiscard]] std::size_t lod_gpu_bytes() const { return lod_bytes_; }
    // The finest LOD level whose cells are at least a pixel at `zoom_px_per_mm` (the raster is used when
    // even the finest cells are at most kLodMaxCellPx).
    [[nodiscard]] int lod_level(double zoom_px_per_mm) const;
    static constexpr double kLodMaxCellPx = 1.0;
    void draw(const View& view, int fb_w, int fb_h, const DrawOptions& options, double grid_step_mm, Point world_origin,
              const GpuPath* path);

    // The panels: Dear ImGui's draw data over the scene, with the font atlas made in init(). Sets the GL state it
    // needs and reads none back: every glGet of a WebGL context waits for the GPU process to finish the frame's
    // drawing (ImGui's own backend saves and restores the state that way: 30-70 ms a frame on SwiftShader).
    void draw_ui(const ImDrawData& data, int fb_w, int fb_h);

    [[nodiscard]] const RenderStats& stats() const { return stats_; }
    // The image is still being filled: the next frames must be drawn even when nothing changed.
    [[nodiscard]] bool filling() const { return stats_.pending_segments > 0; }
    void invalidate_cache() { cache_valid_ = false; }

private:
    // Where a pass draws: the view mapped into a target of w x h pixels, u_center drawn at (ox, oy).
    struct Target {
        float cx, cy, zoom, ox, oy;
        int w, h;
        float scale;
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
        bool operator==(const SceneKey&) const = default;
    };
    bool init_ui();
    void add_page(GpuPath& path, std::size_t first, std::size_t rows);
    void draw_run(const GpuPath& path, std::size_t first, std::size_t end);
    // Segments [first, last) of `path`, those of the groups whose box meets `cull` (all when null), until about
    // `budget` are drawn; returns where it stopped (`last` when it drew them all).
    std::size_t draw_segments(const GpuPath& path, std::size_t first, std::size_t last, const Target* cull = nullptr,
                              std::size_t budget = ~std::size_t(0));
    void draw_grid(const Target& t, double grid_step, Point world_origin);
    void begin_paths(const Target& t, int layer_mask);
    void draw_markers(const Target& t, int marker_mask);
    void draw_selection(const Target& t, const GpuPath& path, const DrawOptions& o);
    void draw_tool(const Target& t, const DrawOptions& o);
    void draw_lod(const Target& t, int mask);
    bool ensure_cache(int w, int h);

    unsigned blit_program_ = 0, lod_program_ = 0;
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
    std::size_t cache_limit_ = 0;        // segments [0, limit) are in the image
    bool cache_markers_pending_ = false; // the markers go on top once the image's segments are all in
    double cache_cx_ = 0, cache_cy_ = 0; // the view centre (mm) the image was drawn at
    float cache_left_ = 0, cache_top_ = 0;  // the image's top-left corner in window pixels, then
    std::uint64_t version_counter_ = 0, markers_version_ = 0;
    RenderStats stats_;

    unsigned path_program_ = 0, grid_program_ = 0, marker_program_ = 0;
    unsigned empty_vao_ = 0;     // the programs pull their data by gl_VertexID: no attributes
    unsigned ui_program_ = 0, ui_vao_ = 0, ui_vertices_ = 0, ui_indices_ = 0, font_tex_ = 0;
    unsigned marker_tex_ = 0;    // RGBA32F x y type, kTexWidth a row
    std::size_t marker_count_ = 0;
    const char* error_ = "";
};

}  // namespace essi::viewer
