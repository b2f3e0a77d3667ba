// The scene of a frame: what the renderer is asked to draw (the view, the layers, the playback limit and tool, the
// selection, the level of detail or the segments), put together by frame() and drawn by render() under the
// panels. A frame whose scene and panels equal the last drawn frame's can be skipped (the browser keeps showing
// the canvas, and the GPU process idles while nothing moves).
#pragma once

#include <cstdint>
#include <optional>

#include "app/Layers.hpp"
#include "app/LoadController.hpp"
#include "app/Playback.hpp"
#include "app/Selection.hpp"
#include "app/View.hpp"
#include "render/Renderer.hpp"
#include "render/UiRenderer.hpp"

namespace essi::viewer {

// What the scene of a frame depends on.
struct SceneInputs {
    const View& view;
    int fb_w, fb_h;
    float framebuffer_scale;
    Rgba panel_color;
    const Layers& layers;
    const Playback& playback;
    const Selection& selection;
    const LoadController& load;
    Point grid_origin;  // the document origin in the shown coordinates (Coordinates): the grid sits on their multiples
    std::size_t hovered_mark;  // the diagnostic's mark under the mouse (UiState::hovered_mark)
};

class SceneAssembly {
public:
    // Puts this frame's scene together; false (no scene) when there is no framebuffer or no GPU.
    bool prepare(const SceneInputs& in, const Renderer& renderer, bool graphics_ok);
    // Draws the scene, then the panels. With `keep_unchanged` a frame that would draw the same pixels as the last
    // one draws nothing. `Windows::LeftOut` draws the scene and the overlays on it (ImGui's background draw list:
    // marks, grid labels, measure) but no window, menu or tooltip: the view as a picture.
    enum class Windows { Drawn, LeftOut };
    void render(Renderer& renderer, UiRenderer& ui, int fb_w, int fb_h, bool keep_unchanged,
                Windows windows = Windows::Drawn);

    [[nodiscard]] bool tape_drawn() const { return tape_drawn_; }  // the tape's segments or its level of detail
    [[nodiscard]] bool lod_drawn() const { return lod_drawn_; }
    [[nodiscard]] std::uint64_t skipped_frames() const { return skipped_frames_; }

private:
    // Everything the scene's pixels depend on (what frame() hands to render()).
    struct SceneFrame {
        View view;
        int fb_w = 0, fb_h = 0;
        DrawOptions options;
        double grid_step = 0;
        Point grid_origin;
        const GpuPath* path = nullptr;
        std::uint64_t path_version = 0;
        bool operator==(const SceneFrame&) const = default;
    };
    static void add_playback_and_selection(const SceneInputs& in, DrawOptions& o);
    static void add_problems(const SceneInputs& in, DrawOptions& o);

    std::optional<SceneFrame> scene_;       // this frame's (none: nothing to draw)
    bool whole_ = false;                    // its image is drawn whole, not filled over frames (a load at once)
    std::optional<SceneFrame> last_scene_;  // the last frame drawn
    std::uint64_t last_ui_hash_ = 0;
    std::uint64_t skipped_frames_ = 0;  // frames that drew nothing (the same pixels as the last)
    bool lod_drawn_ = false;            // the last frame drew the level of detail
    bool tape_drawn_ = false;           // the last frame drew the tape (its segments or its level of detail)
};

}  // namespace essi::viewer
