#version 300 es
// Thick anti-aliased lines: every segment is two triangles (6 vertices, no vertex attributes), expanded here in
// pixels. The segments are pulled from textures by gl_VertexID: a draw call of 6*N vertices is one batch for
// any GPU (instanced quads cost SwiftShader one internal draw per instance: seconds a frame at 1 M segments).
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp usampler2D;

uniform sampler2D u_segs;     // RGBA32F: x0 y0 x1 y1, mm relative to the document origin; u_tex_width a row
uniform usampler2D u_kinds;   // R8UI: 0 rapid, 1 travel, 2 cut, 3 mark, 4 kerf path, 5 + k kerf band k (same layout),
                              // 13 + b a cut and 29 + b a mark in colour bin b (colour by: render/Palette.hpp)
uniform int u_tex_width;
uniform int u_first;          // first segment of this draw

uniform vec2 u_center;        // view centre, mm relative to the document origin
uniform float u_zoom;         // pixels per mm
uniform vec2 u_origin_px;     // pixel (top-left origin) where u_center is drawn
uniform vec2 u_viewport;      // framebuffer size in pixels
uniform vec2 u_turn;          // (cos, sin) of the view's rotation (View::rotation())
uniform float u_half_width[6];
uniform vec4 u_colors[6];
uniform vec4 u_ramp[16];      // colour by: the bins' colours
uniform float u_band_half_mm[8];  // kerf band k: half its width in mm (the cut's real width on screen)
uniform int u_layer_mask;     // bit k: colour k visible (the bands: bit 5)
uniform vec4 u_override;      // when alpha > 0: one colour for every kind (selection)
uniform float u_extra_width;  // added to the half width (selection)

out vec4 v_color;
out float v_across;
out float v_half;

vec2 to_px(vec2 p) {
    vec2 d = p - u_center;
    d = vec2(u_turn.x * d.x - u_turn.y * d.y, u_turn.y * d.x + u_turn.x * d.y);
    return u_origin_px + vec2(d.x, -d.y) * u_zoom;
}

// (along, across) of the 6 corners: (0,-1) (1,-1) (0,1) / (0,1) (1,-1) (1,1)
const vec2 kCorners[6] = vec2[6](vec2(0.0, -1.0), vec2(1.0, -1.0), vec2(0.0, 1.0),
                                 vec2(0.0, 1.0), vec2(1.0, -1.0), vec2(1.0, 1.0));

void main() {
    int seg = u_first + gl_VertexID / 6;
    vec2 corner = kCorners[gl_VertexID % 6];
    ivec2 texel = ivec2(seg % u_tex_width, seg / u_tex_width);
    vec4 s = texelFetch(u_segs, texel, 0);
    int kind = clamp(int(texelFetch(u_kinds, texel, 0).r), 0, 44);
    int colour = kind < 13 ? min(kind, 5) : (kind < 29 ? 2 : 3);  // (a bin's segment: a cut's or a mark's layer)
    bool visible = ((u_layer_mask >> colour) & 1) != 0;
    if (!visible) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
        v_color = vec4(0.0);
        v_across = 0.0;
        v_half = 0.0;
        return;
    }
    vec2 p0 = to_px(s.xy);
    vec2 p1 = to_px(s.zw);
    vec2 d = p1 - p0;
    float len = length(d);
    vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float hw = u_half_width[colour] + u_extra_width;
    if (kind >= 5 && kind < 13) hw = max(hw, u_band_half_mm[kind - 5] * u_zoom);
    float ext = hw + 1.0;  // one pixel of anti-aliasing ramp
    vec2 p = mix(p0, p1, corner.x) + dir * (corner.x * 2.0 - 1.0) * ext + nrm * corner.y * ext;
    vec2 ndc = vec2(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
    v_color = u_override.a > 0.0 ? u_override : kind >= 13 ? u_ramp[(kind - 13) % 16] : u_colors[colour];
    v_across = corner.y * ext;
    v_half = hw;
}
