// The viewer's UI, written once for the browser and the desktop. App owns the parts, makes each with the references
// it needs, and runs the frame:
//   Session        the tape shown: opening, reading (LoadController), what a new tape starts over
//   Navigation     the view and the selection                 Playback      the playback position
//   Input          the mouse and the shortcuts                 SceneAssembly what the renderer draws
//   CompareMode    compare mode                                CommentText   the comments' text encoding
//   Exports        copies, exports, the view as PNG            ShareLinks    share links
//   TapeFacts      its parts and plates, its planned speeds (the Job panel, the parts layer, colour by)
//   Preferences    the theme, the problems-only view, the layout, the language
//   panels::Panels the toolbar, side panels, overlays and windows
//   Automation     window.essikit: the page's API and the state it reads
// The platform (web/platform) owns the window and the loop: it makes the App with its PlatformServices, calls
// init_graphics, frame and render, and hands the app's AppCallbacks and automation() to its event handlers.
#pragma once

#include <string>

#include "app/AppCallbacks.hpp"
#include "app/Automation.hpp"
#include "app/CommentText.hpp"
#include "app/Compare.hpp"
#include "app/Exports.hpp"
#include "app/Input.hpp"
#include "app/KeyboardFocus.hpp"
#include "app/Layers.hpp"
#include "app/LoadController.hpp"
#include "app/Measure.hpp"
#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "app/PageMirror.hpp"
#include "app/Playback.hpp"
#include "app/PlatformServices.hpp"
#include "app/Preferences.hpp"
#include "app/SceneAssembly.hpp"
#include "app/Selection.hpp"
#include "app/Session.hpp"
#include "app/TapeFacts.hpp"
#include "app/ShareLinks.hpp"
#include "app/UiState.hpp"
#include "app/ViewerParts.hpp"
#include "app/WarmUp.hpp"
#include "app/panels/Panels.hpp"
#include "render/Renderer.hpp"
#include "render/UiFonts.hpp"
#include "render/UiRenderer.hpp"

namespace essi::viewer {

class App final : public AppCallbacks {
public:
    // Reads the settings kept across sessions (through `platform`, which must outlive the App).
    explicit App(PlatformServices& platform);
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    bool init_graphics();  // after the GL context and ImGui exist
    // Before ImGui's frame begins (ImGui::NewFrame), once the frame's key events are in ImGui's IO and after the
    // platform backend's NewFrame.
    void before_frame() { keyboard_.before_new_frame(); }
    // One frame: UI, input, drawing. Called by the platform loop between NewFrame and Render.
    void frame();
    // Draws the frame: the scene frame() prepared, then the panels (ImGui's draw data, after ImGui::Render).
    // With `keep_unchanged` (the browser shows the last frame until the canvas is drawn again) a frame that would
    // draw the same pixels as the last one draws nothing: no GPU work while nothing moves.
    void render(bool keep_unchanged);
    // Loading or building work left to do (the browser loop also runs slices of it between frames).
    [[nodiscard]] bool has_background_work() const { return load_.has_work() || warm_up_.has_work(); }
    // One slice (about LoadController::kStepBudgetMs) of that work outside a frame; returns has_background_work().
    bool background_step();
    // Runs the load path on the built-in tapes before the first tape (app/WarmUp.hpp): the browser's choice, once
    // its page has started (its code is compiled while it runs; the desktop's is compiled already).
    void start_warm_up() { warm_up_.start(graphics_ok_); }

    // AppCallbacks: a file opened, dropped or pasted; a platform service's message.
    void load(std::string name, std::string bytes) override;
    void notify(Msg id, const MessageArgs& args = {}) override { notices_.notify(id, args); }

    // The page's API (window.essikit) and the desktop viewer's --state and --lang.
    [[nodiscard]] Automation& automation() { return automation_; }

private:
    void prepare_scene();
    void announce_selection();               // the selection told to the page when it changed
    void announce_mirror();                  // the page's title and text for screen readers, when they changed
    void save_view_png(int fb_w, int fb_h);  // Export > View as PNG: the scene and its overlays, no window

    PlatformServices& platform_;
    UiFonts fonts_;
    Notices notices_;
    UiState ui_;
    Renderer renderer_;
    UiRenderer ui_renderer_;
    bool graphics_ok_ = false;
    bool fonts_changed_ = false;  // the atlas was made again after the last frame: the next one is drawn in full
    LoadController load_;
    WarmUp warm_up_{renderer_, load_};
    TapeFacts tape_facts_;
    SceneAssembly scene_;
    Layers layers_;
    Playback playback_;
    Measure measure_;
    Preferences preferences_;
    Navigation navigation_;
    CommentText comments_;
    CompareMode compare_;
    Session session_;
    Exports exports_;
    ShareLinks shares_;
    Input input_;
    KeyboardFocus keyboard_{ui_};
    ViewerParts parts_;  // (what the panels and the page's API are given)
    panels::Panels panels_;
    Automation automation_;
    Selection announced_;  // the selection the page last heard of (PlatformServices::selection_changed)
    PageMirrorKeeper mirror_;
};

}  // namespace essi::viewer
