#version 300 es
// A textured rectangle in target pixels (top-left origin): the cached drawing, moved while panning.
precision highp float;

uniform vec4 u_rect;      // x, y, width, height in target pixels
uniform vec2 u_viewport;  // target size in pixels

out vec2 v_uv;

const vec2 kCorners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(0.0, 1.0),
                                 vec2(0.0, 1.0), vec2(1.0, 0.0), vec2(1.0, 1.0));

void main() {
    vec2 c = kCorners[gl_VertexID];
    vec2 p = u_rect.xy + c * u_rect.zw;
    gl_Position = vec4(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0, 0.0, 1.0);
    v_uv = vec2(c.x, 1.0 - c.y);  // the texture's rows run bottom-up, as the framebuffer it was drawn into
}
