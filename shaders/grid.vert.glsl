#version 300 es
// One triangle that covers the viewport; the fragment shader draws the grid.
precision highp float;
const vec2 kCorners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
void main() {
    gl_Position = vec4(kCorners[gl_VertexID], 0.0, 1.0);
}
