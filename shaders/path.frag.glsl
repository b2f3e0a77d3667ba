#version 300 es
precision highp float;

in vec4 v_color;
in float v_across;
in float v_half;
uniform float u_alpha;  // 1, or faint: the problems-only view's motions that no diagnostic concerns
out vec4 o_color;

void main() {
    float coverage = clamp(v_half + 0.5 - abs(v_across), 0.0, 1.0);
    if (coverage <= 0.0) discard;
    o_color = vec4(v_color.rgb, v_color.a * coverage * u_alpha);
}
