#version 300 es
// The level-of-detail raster (web/render/LodRaster): for each pixel, the kinds of the cells under it (at most
// 2 x 2 at the level the renderer picks, where a cell is 1-2 pixels), drawn in the colour of the one on top:
// pierce, mark, cut, travel, rapid. Drawn on a rectangle over the whole target (blit.vert.glsl).
precision highp float;
precision highp int;
precision highp usampler2D;

uniform usampler2D u_lod;   // R8UI, a level per LOD level; bits 0-3 MotionKind, bit 4 pierce
uniform int u_level;
uniform float u_cell;       // mm a cell at u_level
uniform vec2 u_min;         // corner of cell (0, 0), mm relative to the document origin
uniform vec2 u_center;      // view centre, mm relative to the document origin
uniform float u_zoom;       // pixels per mm
uniform vec2 u_origin_px;   // pixel (top-left origin) where u_center is drawn
uniform vec2 u_viewport;    // target size in pixels
uniform vec2 u_turn;        // (cos, sin) of the view's rotation (View::rotation())
uniform int u_mask;         // bits 0-3: visible kinds; bit 4: pierces shown
uniform vec4 u_colors[4];
uniform vec4 u_pierce;
out vec4 o_color;

void main() {
    vec2 px = vec2(gl_FragCoord.x, u_viewport.y - gl_FragCoord.y);  // the pixel's centre, top-left origin
    // The pixel's footprint in cells: the box around the pixel turned back by the view's rotation (a pixel's
    // width along a cell's axes is |cos| + |sin| pixels; one pixel for quarter turns).
    vec2 r = vec2(px.x - u_origin_px.x, u_origin_px.y - px.y) / u_zoom;
    vec2 at = (u_center + vec2(u_turn.x * r.x + u_turn.y * r.y, -u_turn.y * r.x + u_turn.x * r.y) - u_min) / u_cell;
    vec2 half_px = vec2(0.5 * (abs(u_turn.x) + abs(u_turn.y)) / (u_zoom * u_cell));
    vec2 lo = at - half_px;
    vec2 hi = at + half_px;
    ivec2 size = textureSize(u_lod, u_level);
    if (hi.x <= 0.0 || hi.y <= 0.0 || lo.x >= float(size.x) || lo.y >= float(size.y)) discard;
    ivec2 c0 = clamp(ivec2(floor(lo)), ivec2(0), size - 1);
    ivec2 c1 = clamp(ivec2(ceil(hi)) - 1, c0, min(c0 + 1, size - 1));
    uint m = texelFetch(u_lod, c0, u_level).r;
    if (c1.x > c0.x) m |= texelFetch(u_lod, ivec2(c1.x, c0.y), u_level).r;
    if (c1.y > c0.y) m |= texelFetch(u_lod, ivec2(c0.x, c1.y), u_level).r;
    if (c1.x > c0.x && c1.y > c0.y) m |= texelFetch(u_lod, c1, u_level).r;
    m &= uint(u_mask);
    if (m == 0u) discard;
    if ((m & 16u) != 0u) o_color = u_pierce;
    else if ((m & 8u) != 0u) o_color = u_colors[3];
    else if ((m & 4u) != 0u) o_color = u_colors[2];
    else if ((m & 2u) != 0u) o_color = u_colors[1];
    else o_color = u_colors[0];
}
