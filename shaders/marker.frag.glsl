#version 300 es
precision highp float;

in vec2 v_local;
flat in int v_type;
flat in float v_radius;
uniform vec4 u_colors[6];
uniform float u_plain_alpha;  // pierces, start and tool (types 0-2): 1, or faint in the problems-only view
out vec4 o_color;

const vec3 kMarkEdge = vec3(0.08, 0.08, 0.1);  // the dark rim that sets a diagnostic's mark off the paths
const vec3 kMarkCross = vec3(1.0);

void main() {
    float r = length(v_local);
    float outer = clamp(v_radius + 0.5 - r, 0.0, 1.0);
    vec4 c = u_colors[clamp(v_type, 0, 5)];
    float a;
    if (v_type >= 3) {
        // A diagnostic's mark: a disc (error crossed, warning plain) or a ring (note), with a dark rim.
        float rim = clamp(r - (v_radius - 1.0) + 0.5, 0.0, 1.0);
        vec3 rgb = mix(c.rgb, kMarkEdge, rim * 0.85);
        if (v_type == 5) {
            float inner = clamp(r - (v_radius - 3.5) + 0.5, 0.0, 1.0);
            outer *= inner;
        } else if (v_type == 3) {
            float cross = clamp(1.1 - abs(abs(v_local.x) - abs(v_local.y)) * 0.7071, 0.0, 1.0) *
                          clamp(v_radius - 3.5 - r + 0.5, 0.0, 1.0);
            rgb = mix(rgb, kMarkCross, cross);
        }
        if (outer <= 0.0) discard;
        o_color = vec4(rgb, c.a * outer);
        return;
    }
    if (v_type == 1) {
        a = outer;                                                 // start: a filled disc
    } else {
        float inner = clamp(r - (v_radius - 2.0) + 0.5, 0.0, 1.0);
        a = outer * inner;                                         // pierce / tool: a ring
        if (v_type == 2) a = max(a, clamp(1.5 - min(abs(v_local.x), abs(v_local.y)), 0.0, 1.0) * outer);
    }
    if (a <= 0.0) discard;
    o_color = vec4(c.rgb, c.a * a * u_plain_alpha);
}
