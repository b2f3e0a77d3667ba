// The viewer's UI, written once for the browser and the desktop: loading with progress, the drawing area
// (pan, zoom, fit, pick, measure, playback) and the panels (source, diagnostics, inspector, statistics,
// layers). The platform layer (web/platform) owns the window and the loop and calls frame().
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "app/Document.hpp"
#include "app/View.hpp"
#include "render/PathBuffers.hpp"
#include "render/Renderer.hpp"

struct GLFWwindow;

namespace essi::viewer {

struct ViewRequest {
    double x = 0, y = 0, zoom = 0;  // machine mm at the centre, pixels per mm (zoom 0: fit)
    std::uint32_t line = 0;         // selected line (0: none)
};

class App {
public:
    static constexpr std::size_t npos = ~std::size_t(0);

    explicit App(GLFWwindow* window);
    ~App();
    static App* instance();

    bool init_graphics();  // after the GL context and ImGui exist
    // One frame: UI, input, drawing. Called by the platform loop between NewFrame and Render.
    void frame();
    // Draws the frame: the scene frame() prepared, then the panels (ImGui's draw data, after ImGui::Render).
    // With `keep_unchanged` (the browser shows the last frame until the canvas is drawn again) a frame that would
    // draw the same pixels as the last one draws nothing: no GPU work while nothing moves.
    void render(bool keep_unchanged);
    // The segments are being made again at a new zoom's tolerance (not the load's first build), over the overview.
    [[nodiscard]] bool remaking() const { return building_ != nullptr && !first_build_ && renderer_.has_lod(); }
    // Loading or building work left to do (the browser loop also runs slices of it between frames).
    [[nodiscard]] bool has_background_work() const { return loader_ != nullptr || lod_building_ || building_ != nullptr; }
    // One slice (about kStepBudgetMs) of that work outside a frame; returns has_background_work().
    bool background_step();
    // Starts loading a tape (bytes as read from the file). `view`, when given, replaces the fit at the end.
    void load(std::string name, std::string bytes, std::optional<ViewRequest> view = std::nullopt);
    void set_view(double x, double y, double zoom);   // machine mm, px/mm; kept until a load completes
    void select_line(std::uint32_t line, bool reveal = true);
    void set_layer(int kind, bool visible);
    void share() { start_share(); }  // the Share button
    void share_done(bool ok, std::string text);
    void notify(std::string text);  // a short message in the toolbar (copied, paste ignored, ...)

    // window.essikit.state(): {status, name, stats, diagnostics, selection, view, ...} as JSON text.
    [[nodiscard]] std::string state_json() const;
    // One motion as JSON (for tests and embedding): {"index","line","kind","curve","start","end","segments"}.
    [[nodiscard]] std::string motion_json(std::size_t i) const;

    [[nodiscard]] const Document* document() const { return doc_.get(); }

private:
    void step_loading();
    void finish_loading();
    void maybe_rebuild();
    [[nodiscard]] bool loading() const;  // reading, or making the first drawing of a tape
    [[nodiscard]] float load_progress() const;
    [[nodiscard]] const char* load_stage() const;
    void draw_toolbar();
    void draw_left_panel();
    void draw_right_panel();
    void draw_source();
    void draw_inspector();
    void draw_overlays();
    void draw_help();
    void draw_messages();
    void handle_canvas_input();
    void handle_shortcuts();
    void fit();
    void select_motion(std::size_t motion);
    void start_share();
    [[nodiscard]] std::size_t pick(double sx, double sy) const;
    [[nodiscard]] Point snap(double sx, double sy, bool* snapped) const;
    [[nodiscard]] double desired_tolerance() const;
    [[nodiscard]] std::size_t playback_limit_motions() const;
    [[nodiscard]] std::pair<std::size_t, std::size_t> selection_segments() const;
    [[nodiscard]] int layer_mask() const;
    [[nodiscard]] std::string view_query() const;

    // Everything the scene's pixels depend on (what frame() hands to render()).
    struct SceneFrame {
        View view;
        int fb_w = 0, fb_h = 0;
        DrawOptions options;
        double grid_step = 0;
        Point origin;
        const GpuPath* path = nullptr;
        std::uint64_t path_version = 0;
        bool operator==(const SceneFrame&) const = default;
    };

    GLFWwindow* window_ = nullptr;
    Renderer renderer_;
    std::optional<SceneFrame> scene_;       // this frame's (none: nothing to draw)
    std::optional<SceneFrame> last_scene_;  // the last frame drawn
    std::uint64_t last_ui_hash_ = 0;
    std::uint64_t skipped_frames_ = 0;      // frames that drew nothing (the same pixels as the last)
    bool graphics_ok_ = false;

    // Loading
    std::unique_ptr<DocumentLoader> loader_;
    std::optional<ViewRequest> pending_view_;
    std::string loading_name_;
    std::size_t loading_bytes_ = 0;
    int frames_since_load_start_ = 0;
    double load_started_ = 0;
    double load_seconds_ = 0;

    // The document and its drawing
    std::unique_ptr<Document> doc_;
    PathBuffers buffers_;           // the drawn set's motion -> segment map (its segments are on the GPU only)
    GpuPath gpu_;                   // the drawn segments
    std::unique_ptr<PathBuffers> building_;  // being built (first build or a rebuild at a new tolerance)
    GpuPath gpu_building_;          // its segments, uploaded as they are made
    LodRaster lod_;                 // zoomed-out drawing of big tapes, made before the first build
    bool lod_building_ = false;     // lod_ is being made (the first build waits for it; a finer one waits for builds)
    int lod_cells_ = 0;             // cells on the longer side of the level of detail being made or drawn
    int lod_full_cells_ = 0;        // the tape's own (LodRaster::cells_for)
    bool lod_drawn_ = false;        // the last frame drew it
    bool tape_drawn_ = false;       // the last frame drew the tape (its segments or its level of detail)
    double shown_seconds_ = 0;      // from the start of the load to the first frame that drew the tape
    bool first_build_ = false;
    std::string profile_name_ = "iso6582";
    std::string banner_;            // a problem with the whole file ("not an ESSI tape ...")

    // View and interaction
    View view_;
    bool dragging_ = false;
    bool press_in_canvas_ = false;
    float press_x_ = 0, press_y_ = 0;
    std::uint32_t selected_line_ = 0;
    std::size_t selected_motion_ = npos;
    bool scroll_source_ = false;
    bool scroll_diagnostics_ = false;

    // Layers
    bool show_kind_[4] = {true, true, true, true};
    bool show_pierces_ = true;
    bool show_start_ = true;
    bool show_grid_ = true;

    // Playback
    bool playback_ = false;   // limit the drawing to the playback position
    bool playing_ = false;
    double play_pos_ = 0;     // in motions
    float play_speed_ = 20;   // motions per second

    // Measure
    bool measure_mode_ = false;
    int measure_count_ = 0;
    Point measure_a_, measure_b_;  // machine mm

    // Windows and messages
    bool show_help_ = false;
    std::string message_;
    double message_until_ = 0;
    std::string share_url_;
    bool share_popup_ = false;
};

}  // namespace essi::viewer
