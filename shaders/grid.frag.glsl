#version 300 es
// The grid's lines (grid.vert.glsl): full within half a pixel of a minor or major line's centre (a pixel of an
// axis'), fading out over the next pixel.
precision highp float;

in vec4 v_color;
in float v_across;
in float v_half;
out vec4 o_color;

void main() {
    float coverage = clamp(v_half + 0.5 - abs(v_across), 0.0, 1.0);
    if (coverage * v_color.a <= 0.001) discard;
    o_color = vec4(v_color.rgb, v_color.a * coverage);
}
