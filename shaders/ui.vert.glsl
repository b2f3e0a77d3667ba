#version 300 es
// The panels (Dear ImGui's draw lists): vertices in window pixels (top-left origin), a texture coordinate in
// the font atlas and a colour.
precision highp float;

uniform vec2 u_viewport;  // window size in pixels (ImGui's display size)

layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_color;  // 0..1 (normalized bytes)

out vec2 v_uv;
out vec4 v_color;

void main() {
    v_uv = a_uv;
    v_color = a_color;
    gl_Position = vec4(a_position.x / u_viewport.x * 2.0 - 1.0, 1.0 - a_position.y / u_viewport.y * 2.0, 0.0, 1.0);
}
