#version 300 es
// The grid under the drawing (render/GridLines.hpp): minor lines every u_step mm, major lines every tenth step, the
// axes through the origin. Every line is two triangles (6 vertices, no vertex attributes) expanded here in pixels,
// with a pixel of anti-aliasing: a CPU renderer such as SwiftShader shades the lines' pixels, not the whole image.
//   lines [0, u_count.x):              x = u_first.x + i u_step (offsets from the view centre, mm, shown axes)
//   the next u_count.y:                y = u_first.y + i u_step
//   the last two:                      the axes, x = u_axes_at.x and y = u_axes_at.y
precision highp float;
precision highp int;

uniform float u_zoom;         // pixels per mm
uniform vec2 u_origin_px;     // pixel (top-left origin) where the view centre is drawn
uniform vec2 u_viewport;      // framebuffer size
uniform vec2 u_turn;          // (cos, sin) of the view's quarter turns
uniform vec2 u_first;         // the first line along x and along y
uniform float u_step;         // minor step in mm
uniform ivec2 u_count;        // lines along x and along y (the axes not counted)
uniform int u_major_every;    // every this many lines a major one (GridLines::kMajorEvery)
uniform ivec2 u_major_phase;  // the first line's grid index, modulo u_major_every (a multiple of it is a major line)
uniform ivec2 u_zero;         // the line that lies on the axis (-1: none): the axis draws it
uniform vec2 u_axes_at;
uniform vec4 u_span;          // what a line spans: x from .x to .z, y from .y to .w
uniform vec4 u_minor;
uniform vec4 u_major;
uniform vec4 u_axis;

out vec4 v_color;
out float v_across;
out float v_half;

vec2 to_px(vec2 d) {
    d = vec2(u_turn.x * d.x - u_turn.y * d.y, u_turn.y * d.x + u_turn.x * d.y);
    return u_origin_px + vec2(d.x, -d.y) * u_zoom;
}

// (along, across) of the 6 corners: (0,-1) (1,-1) (0,1) / (0,1) (1,-1) (1,1)
const vec2 kCorners[6] = vec2[6](vec2(0.0, -1.0), vec2(1.0, -1.0), vec2(0.0, 1.0),
                                 vec2(0.0, 1.0), vec2(1.0, -1.0), vec2(1.0, 1.0));

vec4 line_color(int i, int phase, int zero) {
    if (i == zero) return vec4(0.0);
    return (phase + i) % u_major_every == 0 ? u_major : u_minor;
}

void main() {
    int line = gl_VertexID / 6;
    vec2 corner = kCorners[gl_VertexID % 6];
    bool x_line;  // x constant (a line along y)
    float at;
    vec4 color;
    float half_px = 0.5;  // coverage 1 - distance (px): the axes 1.5 - distance
    if (line < u_count.x) {
        x_line = true;
        at = u_first.x + float(line) * u_step;
        color = line_color(line, u_major_phase.x, u_zero.x);
    } else if (line < u_count.x + u_count.y) {
        int i = line - u_count.x;
        x_line = false;
        at = u_first.y + float(i) * u_step;
        color = line_color(i, u_major_phase.y, u_zero.y);
    } else {
        x_line = line == u_count.x + u_count.y;
        at = x_line ? u_axes_at.x : u_axes_at.y;
        color = u_axis;
        half_px = 1.0;
    }
    if (color.a <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
        v_color = vec4(0.0);
        v_across = 0.0;
        v_half = 0.0;
        return;
    }
    vec2 p0 = to_px(x_line ? vec2(at, u_span.y) : vec2(u_span.x, at));
    vec2 p1 = to_px(x_line ? vec2(at, u_span.w) : vec2(u_span.z, at));
    vec2 dir = normalize(p1 - p0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float ext = half_px + 0.5;
    vec2 p = mix(p0, p1, corner.x) + nrm * corner.y * ext;
    gl_Position = vec4(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0, 0.0, 1.0);
    v_color = color;
    v_across = corner.y * ext;
    v_half = half_px;
}
