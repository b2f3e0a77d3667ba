#version 300 es
precision highp float;

in vec2 v_local;
flat in int v_type;
uniform float u_radius_px;
uniform vec4 u_colors[3];
out vec4 o_color;

void main() {
    float r = length(v_local);
    float outer = clamp(u_radius_px + 0.5 - r, 0.0, 1.0);
    float a;
    if (v_type == 1) {
        a = outer;                                                 // start: a filled disc
    } else {
        float inner = clamp(r - (u_radius_px - 2.0) + 0.5, 0.0, 1.0);
        a = outer * inner;                                         // pierce / tool: a ring
        if (v_type == 2) a = max(a, clamp(1.5 - min(abs(v_local.x), abs(v_local.y)), 0.0, 1.0) * outer);
    }
    if (a <= 0.0) discard;
    vec4 c = u_colors[clamp(v_type, 0, 2)];
    o_color = vec4(c.rgb, c.a * a);
}
