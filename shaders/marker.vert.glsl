#version 300 es
// Point markers (pierces, the start point, the tool in playback): a screen-aligned quad per instance.
precision highp float;

layout(location = 0) in vec2 a_corner;  // the path quad: x 0..1, y -1..1
layout(location = 1) in vec2 a_pos;     // mm relative to the document origin
layout(location = 2) in float a_type;   // 0 pierce, 1 start, 2 tool

uniform vec2 u_center;
uniform float u_zoom;
uniform vec2 u_origin_px;
uniform vec2 u_viewport;
uniform float u_radius_px;
uniform int u_type_mask;

out vec2 v_local;
flat out int v_type;

void main() {
    int type = int(a_type + 0.5);
    vec2 corner = vec2(a_corner.x * 2.0 - 1.0, a_corner.y);
    vec2 c = u_origin_px + vec2(a_pos.x - u_center.x, u_center.y - a_pos.y) * u_zoom;
    vec2 p = c + corner * (u_radius_px + 1.0);
    vec2 ndc = vec2(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0);
    bool visible = ((u_type_mask >> type) & 1) != 0;
    gl_Position = visible ? vec4(ndc, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
    v_local = corner * (u_radius_px + 1.0);
    v_type = type;
}
