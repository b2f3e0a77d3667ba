// The GL programs of the scene (shaders/*.glsl) with their uniform locations, found once at start-up: the
// drawing path sets uniforms by location and never looks one up by name. The uniforms whose values never change
// (samplers' texture units, colours, the texture width) are set here too, once.
#pragma once

#include <string>

#include "app/View.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

// Compiles and links a program; 0 when the GPU refuses it (program_error() says why, also on stderr).
[[nodiscard]] unsigned link_program(const char* vertex_src, const char* fragment_src, const char* name);
// The last compile or link error ("" when none).
[[nodiscard]] const char* program_error();
// A 2D texture, bound, with nearest filtering and clamped edges.
[[nodiscard]] unsigned new_texture();

// The uniforms that map the view into a target (the scene programs have them): u_center is drawn at pixel
// u_origin_px of a u_viewport target, u_zoom pixels a mm.
struct TargetUniforms {
    int center = -1, zoom = -1, origin_px = -1, viewport = -1, turn = -1;
    [[nodiscard]] static TargetUniforms of(unsigned program);
    // `r`: the view's rotation (View::rotation(): the plate's and the quarter turns), as u_turn = (cos, sin).
    void set(float cx, float cy, float zoom_px, float ox, float oy, int w, int h, Rotation r) const;
};

// A program that draws into a view's target; the programs below add their own uniforms' locations.
struct SceneProgram {
    unsigned id = 0;
    TargetUniforms target;
};
// shaders/path.*: the segments as thick lines.
struct PathProgram : SceneProgram {
    int half_width = -1, layer_mask = -1, override_color = -1, extra_width = -1, first = -1, band_half_mm = -1;
    int alpha = -1;  // the problems-only view's faint motions
};
// shaders/grid.*: the grid under the drawing.
struct GridProgram : SceneProgram {
    int first = -1, step = -1, count = -1, major_phase = -1, zero = -1, axes_at = -1, span = -1;
};
// shaders/marker.*: pierces, the start point, the playback tool and the diagnostics' marks.
struct MarkerProgram : SceneProgram {
    int radius_px = -1, type_mask = -1, use_single = -1, single = -1, mark_radius_px = -1, plain_alpha = -1, first = -1;
};
// shaders/blit.vert + lod.frag: the level-of-detail raster as one rectangle.
struct LodProgram : SceneProgram {
    int rect = -1, level = -1, cell = -1, min = -1, mask = -1;
};
// shaders/blit.*: the cached image drawn into the window.
struct BlitProgram {
    unsigned id = 0;
    int rect = -1, viewport = -1;
};

struct ScenePrograms {
    PathProgram path;
    GridProgram grid;
    MarkerProgram marker;
    LodProgram lod;
    BlitProgram blit;
    // Links every program and finds its uniforms; `tex_width`: segments (markers) a texture row.
    bool init(int tex_width);
    // The theme's colours into the grid and marker programs.
    void set_theme(const Theme& theme) const;
};

}  // namespace essi::viewer
