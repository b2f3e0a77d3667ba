#version 300 es
// Point markers (pierces, the start point, the tool in playback, the diagnostics' marks): a screen-aligned quad (6 vertices) per marker,
// pulled from a texture by gl_VertexID like the paths (instancing costs SwiftShader one internal draw per instance).
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D u_markers;  // RGBA32F: x, y (mm relative to the document origin), type (0 pierce, 1 start, 2 tool,
                              // 3-5 a diagnostic's mark: error, warning, note)
uniform int u_tex_width;
uniform int u_first;          // the first marker of this draw (the diagnostics' marks alone: they come last)
uniform int u_use_single;     // 1: draw u_single instead of the texture (the playback tool)
uniform vec3 u_single;        // x, y, type

uniform vec2 u_center;
uniform float u_zoom;
uniform vec2 u_origin_px;
uniform vec2 u_viewport;
uniform vec2 u_turn;         // (cos, sin) of the view's rotation (View::rotation())
uniform float u_radius_px;
uniform float u_mark_radius_px;  // the diagnostics' marks (types 3-5)
uniform int u_type_mask;

out vec2 v_local;
flat out int v_type;
flat out float v_radius;

const vec2 kCorners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0),
                                 vec2(-1.0, 1.0), vec2(1.0, -1.0), vec2(1.0, 1.0));

void main() {
    int index = u_first + gl_VertexID / 6;
    vec3 m = u_use_single != 0 ? u_single : texelFetch(u_markers, ivec2(index % u_tex_width, index / u_tex_width), 0).xyz;
    int type = int(m.z + 0.5);
    vec2 corner = kCorners[gl_VertexID % 6];
    vec2 d = m.xy - u_center;
    d = vec2(u_turn.x * d.x - u_turn.y * d.y, u_turn.y * d.x + u_turn.x * d.y);
    vec2 c = u_origin_px + vec2(d.x, -d.y) * u_zoom;
    float radius = type >= 3 ? u_mark_radius_px : u_radius_px;
    vec2 p = c + corner * (radius + 1.0);
    vec2 ndc = vec2(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0);
    bool visible = ((u_type_mask >> type) & 1) != 0;
    gl_Position = visible ? vec4(ndc, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
    v_local = corner * (radius + 1.0);
    v_type = type;
    v_radius = radius;
}
