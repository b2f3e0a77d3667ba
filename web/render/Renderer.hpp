// Draws the grid, the flattened motion and the markers with the programs in shaders/ (OpenGL ES 3.0:
// WebGL2 in the browser, a GLES 3 context natively).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "app/View.hpp"
#include "render/PathBuffers.hpp"

namespace essi::viewer {

struct Rgba {
    float r, g, b, a;
};

struct DrawOptions {
    int layer_mask = 0xF;          // bit per MotionKind
    int marker_mask = 0x7;         // bit per MarkerType
    std::size_t segment_limit = ~std::size_t(0);  // playback: draw segments [0, limit)
    std::size_t selection_first = 0, selection_count = 0;  // segments drawn highlighted
    bool has_tool = false;         // playback: the tool marker
    Point tool;                    // relative to the document origin
    float framebuffer_scale = 1;
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

class Renderer {
public:
    bool init();  // compiles the programs; false (and a message) when the GPU refuses them
    [[nodiscard]] const char* error() const { return error_; }
    void upload(const PathBuffers& buffers);
    void clear_geometry();
    void draw(const View& view, int fb_w, int fb_h, const DrawOptions& options, double grid_step_mm, Point world_origin);

private:
    unsigned path_program_ = 0, grid_program_ = 0, marker_program_ = 0;
    unsigned quad_vbo_ = 0, seg_vbo_ = 0, marker_vbo_ = 0, tool_vbo_ = 0;
    unsigned path_vao_ = 0, marker_vao_ = 0, grid_vao_ = 0, sel_vao_ = 0, tool_vao_ = 0;
    unsigned seg_tex_ = 0, kind_tex_ = 0;  // the segments (RGBA32F x0 y0 x1 y1, R8UI kind), kTexWidth a row
    static constexpr int kTexWidth = 4096;
    std::size_t segment_count_ = 0, marker_count_ = 0;
    const char* error_ = "";
};

}  // namespace essi::viewer
