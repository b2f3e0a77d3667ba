#version 300 es
// Thick anti-aliased lines: every segment is one instance of a 4-vertex quad, expanded here in pixels.
precision highp float;
precision highp int;

layout(location = 0) in vec2 a_corner;  // x: 0 = segment start, 1 = segment end; y: -1 / +1 across
layout(location = 1) in vec4 a_seg;     // x0 y0 x1 y1, mm relative to the document origin
layout(location = 2) in float a_kind;   // 0 rapid, 1 travel, 2 cut, 3 mark

uniform vec2 u_center;        // view centre, mm relative to the document origin
uniform float u_zoom;         // pixels per mm
uniform vec2 u_origin_px;     // pixel (top-left origin) where u_center is drawn
uniform vec2 u_viewport;      // framebuffer size in pixels
uniform float u_half_width[4];
uniform vec4 u_colors[4];
uniform int u_layer_mask;     // bit k: kind k visible
uniform vec4 u_override;      // when alpha > 0: one colour for every kind (selection)
uniform float u_extra_width;  // added to the half width (selection)

out vec4 v_color;
out float v_across;
out float v_half;

vec2 to_px(vec2 p) {
    return u_origin_px + vec2(p.x - u_center.x, u_center.y - p.y) * u_zoom;
}

void main() {
    int kind = clamp(int(a_kind + 0.5), 0, 3);
    vec2 p0 = to_px(a_seg.xy);
    vec2 p1 = to_px(a_seg.zw);
    vec2 d = p1 - p0;
    float len = length(d);
    vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float hw = u_half_width[kind] + u_extra_width;
    float ext = hw + 1.0;  // one pixel of anti-aliasing ramp
    vec2 p = mix(p0, p1, a_corner.x) + dir * (a_corner.x * 2.0 - 1.0) * ext + nrm * a_corner.y * ext;
    bool visible = ((u_layer_mask >> kind) & 1) != 0;
    vec2 ndc = vec2(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0);
    gl_Position = visible ? vec4(ndc, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
    v_color = u_override.a > 0.0 ? u_override : u_colors[kind];
    v_across = a_corner.y * ext;
    v_half = hw;
}
