#version 300 es
precision mediump float;

uniform sampler2D u_texture;  // the font atlas: coverage in the red channel (UiRenderer::upload_fonts)
in vec2 v_uv;
in vec4 v_color;
out vec4 o_color;

void main() {
    o_color = vec4(v_color.rgb, v_color.a * texture(u_texture, v_uv).r);
}
