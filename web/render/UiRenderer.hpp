// The panels: Dear ImGui's draw data drawn with the ui program (shaders/ui.*) and the font atlas made in init().
// ImGui's own OpenGL backend is not used: it reads GL state back every frame, and every glGet of a WebGL context
// waits for the GPU process to finish the frame's drawing (30-70 ms a frame on SwiftShader). This one sets the
// state it needs and reads none back.
#pragma once

struct ImDrawData;

namespace essi::viewer {

class UiRenderer {
public:
    // Compiles the program and uploads ImGui's font atlas (after the GL context and ImGui exist and the atlas is made:
    // UiFonts::update).
    bool init();
    // Uploads the font atlas again (UiFonts::update made it anew).
    void upload_fonts();
    [[nodiscard]] const int* font_texture_size() const { return font_texture_size_; }  // {w, h} texels
    // Draws `data` over whatever the window holds (fb_w x fb_h framebuffer pixels).
    void draw(const ImDrawData& data, int fb_w, int fb_h);

private:
    unsigned program_ = 0, vao_ = 0, vertices_ = 0, indices_ = 0, font_tex_ = 0;
    int viewport_ = -1;  // u_viewport's location
    int font_texture_size_[2] = {0, 0};
};

}  // namespace essi::viewer
