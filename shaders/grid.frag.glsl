#version 300 es
// A millimetre grid: minor lines every u_step mm, major lines every 10 steps, the axes through the origin.
precision highp float;

uniform vec2 u_center;     // view centre, mm in the shown coordinates (program or machine), relative to u_world_origin
uniform vec2 u_world_origin; // the document origin in the shown coordinates (grid lines sit on their multiples)
uniform float u_zoom;      // pixels per mm
uniform vec2 u_origin_px;  // pixel (top-left origin) where u_center is drawn
uniform vec2 u_viewport;   // framebuffer size
uniform vec2 u_turn;       // (cos, sin) of the view's quarter turns (the grid lies along the shown axes)
uniform float u_step;      // minor grid step in mm
uniform vec4 u_minor;
uniform vec4 u_major;
uniform vec4 u_axis;
out vec4 o_color;

float line_alpha(float coord_mm, float step) {
    // distance (pixels) to the nearest multiple of `step`
    float f = coord_mm / step;
    float d = abs(f - floor(f + 0.5)) * step * u_zoom;
    return clamp(1.0 - d, 0.0, 1.0);
}

void main() {
    vec2 px = vec2(gl_FragCoord.x, u_viewport.y - gl_FragCoord.y);
    vec2 r = vec2(px.x - u_origin_px.x, u_origin_px.y - px.y) / u_zoom;
    vec2 rel = u_center + vec2(u_turn.x * r.x + u_turn.y * r.y, -u_turn.y * r.x + u_turn.x * r.y);  // mm from the doc origin, shown axes
    vec2 w = rel + u_world_origin;
    float minor = max(line_alpha(w.x, u_step), line_alpha(w.y, u_step));
    float major = max(line_alpha(w.x, u_step * 10.0), line_alpha(w.y, u_step * 10.0));
    float axis = max(clamp(1.5 - abs(w.x) * u_zoom, 0.0, 1.0), clamp(1.5 - abs(w.y) * u_zoom, 0.0, 1.0));
    vec4 c = vec4(u_minor.rgb, minor * u_minor.a);
    if (major * u_major.a >= c.a) c = vec4(u_major.rgb, major * u_major.a);
    if (axis * u_axis.a >= c.a) c = vec4(u_axis.rgb, axis * u_axis.a);
    if (c.a <= 0.001) discard;
    o_color = c;
}
