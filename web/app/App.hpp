// The viewer's UI, written once for the browser and the desktop. App owns the parts and wires them:
//   LoadController  loading and the rebuilds of the drawing         SceneAssembly  what the renderer draws
//   Input           picking, snapping, measuring, the shortcuts     Playback       the playback position
//   panels/         the toolbar, side panels, overlays and windows  Automation.cpp window.essikit's state
// The platform layer (web/platform) owns the window and the loop and calls frame() and render().
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/Compare.hpp"
#include "app/Coordinates.hpp"
#include "app/Document.hpp"
#include "app/Input.hpp"
#include "app/Language.hpp"
#include "app/Layers.hpp"
#include "app/LoadController.hpp"
#include "app/Playback.hpp"
#include "app/SceneAssembly.hpp"
#include "app/Selection.hpp"
#include "app/View.hpp"
#include "app/panels/Panels.hpp"
#include "essi/report_json.hpp"
#include "essi/share_link.hpp"
#include "essi/text_encoding.hpp"
#include "render/Renderer.hpp"
#include "render/UiFonts.hpp"
#include "render/UiRenderer.hpp"

struct GLFWwindow;

namespace essi::viewer {

struct ViewRequest {
    double x = 0, y = 0, zoom = 0;  // machine mm at the centre, pixels per mm (zoom 0: fit)
    std::uint32_t line = 0;         // selected line (0: none)
};

// One item of the toolbar as the last frame drew it (state().toolbar): in the bar, or in its overflow menu (drawn
// there only while the menu is open).
struct ToolbarItem {
    const char* id = "";
    Rect rect;             // screen pixels (nothing while it is in the closed menu)
    bool in_menu = false;
};

// The windows and messages over the drawing.
struct UiState {
    bool help = false;
    Phrase message;             // a short message in the toolbar, shown until message_until
    double message_until = 0;
    std::string share_url;      // the last share link
    Phrase share_problem;       // or why the last one could not be made
    bool share_popup = false;
    Msg banner = Msg::None;     // a problem with the whole file ("not an ESSI tape ...": App::banner_text)
    Phrase link_problem;        // a share link that could not be opened (cut off, damaged, its tape gone ...)
    std::size_t hovered_mark = ~std::size_t(0);  // the diagnostic's mark under the mouse (Document::marks), or none
    std::vector<ToolbarItem> toolbar;  // the toolbar's items (panels::toolbar)
    Rect toolbar_more;                 // its overflow menu's button (w 0: every item fits)
    bool toolbar_menu_open = false;
    std::string copied;         // the last text copied to the clipboard (state().copied)
    std::vector<std::string> examples;  // the tapes the server offers (the start screen), none natively
    std::vector<std::string> recent;    // the names of the last tapes opened (newest first), kept across sessions
    panels::PanelLayout layout;         // the side panels (kept across sessions: App::save_layout)
    bool layout_changed = false;        // by the user this frame: saved once the mouse is up
};

class App {
public:
    static constexpr std::size_t npos = Selection::npos;

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
    // Loading or building work left to do (the browser loop also runs slices of it between frames).
    [[nodiscard]] bool has_background_work() const { return load_.has_work(); }
    // One slice (about LoadController::kStepBudgetMs) of that work outside a frame; returns has_background_work().
    bool background_step();
    // Frames begun so far (state().frame; the frame numbers of state().load, LoadController::LoadFrames).
    [[nodiscard]] std::uint64_t frames() const { return frames_; }

    // --- Actions (the panels, the shortcuts, the platform and window.essikit) ---
    // Starts loading a tape (bytes as read from the file). `view`, when given, replaces the fit at the end.
    void load(std::string name, std::string bytes, std::optional<ViewRequest> view = std::nullopt);
    // Loads a share link's tape as its sender read it: the link's profile (a built-in name, or the user profile
    // it carries) and input format (essi/share_link.hpp). The page applies the link's view after it.
    void load_shared(std::string name, std::string bytes, const ShareLink& link);
    // A share link that could not be opened: says why, over the start screen.
    void link_problem(Phrase why);
    // Compare mode: the next tape opened (dropped, Open..., essikit.compare) is compared with this one instead of
    // replacing it (Compare.hpp); end_compare leaves the mode.
    void begin_compare();
    void compare_with(std::string name, const std::string& bytes);
    void end_compare();
    [[nodiscard]] const Compare* compare() const { return compare_.get(); }
    [[nodiscard]] bool compare_pending() const { return compare_next_; }
    // Shows contour `index` of A (or of B: `of_b`): its lines selected, the view on it.
    void show_contour(std::size_t index, bool of_b);
    // The examples the server offers (their names), for the start screen.
    void set_examples(std::vector<std::string> names);
    static constexpr const char* kRecentSetting = "recent";
    static constexpr const char* kLayoutSetting = "layout";
    // The light theme beside the dark one (the drawing's background, the grid, the panels); kept across sessions.
    void set_light_theme(bool light);
    [[nodiscard]] bool light_theme() const { return renderer_.theme().light; }
    static constexpr const char* kThemeSetting = "theme";
    // The text of comments (3 ... 4 sections, EIA "( )"): UTF-8 or GB 18030, detected per tape
    // (essi::detect_text_encoding) unless the user chose one (kept across sessions; nullopt: detect).
    void set_text_encoding(std::optional<TextEncoding> chosen);
    [[nodiscard]] std::optional<TextEncoding> chosen_text_encoding() const { return chosen_encoding_; }
    [[nodiscard]] TextEncoding detected_text_encoding() const { return detected_encoding_; }
    [[nodiscard]] TextEncoding text_encoding() const { return chosen_encoding_.value_or(detected_encoding_); }
    // A source line as the panels show it: decoded in the text encoding (at most `max` bytes of it).
    [[nodiscard]] std::string line_text(const Document& d, std::size_t line, std::size_t max = 400) const;
    static constexpr const char* kTextEncodingSetting = "comment_encoding";
    // The side panels shown or hidden, their widths (0: as they are); kept across sessions.
    void set_layout(const panels::PanelLayout& layout);
    static constexpr std::size_t kRecentNames = 8;
    void set_profile(const std::string& name);  // loads the tape again with another profile, keeping the view
    void set_view(double x, double y, double zoom);   // machine mm, px/mm; kept until a load completes
    void select_line(std::uint32_t line, bool reveal = true);
    void select_motion(std::size_t motion);
    // A diagnostic chosen (its mark clicked, as a click in the problems list): its block selected and in view.
    void select_diagnostic(std::size_t index);
    // The problems-only view (Layers::problems_only, key P); kept across sessions.
    void set_problems_only(bool on);
    [[nodiscard]] bool problems_only() const { return layers_.problems_only; }
    static constexpr const char* kProblemsOnlySetting = "problems_only";
    void set_layer(int layer, bool visible);  // window.essikit.setLayer: 0-3 MotionKind, 4 pierces, 5 start, 6-7 kerf
    // The machine's view orientation (View::turns, Orientation): kept across sessions (platform settings).
    void set_orientation(int quarter_turns);
    static constexpr const char* kOrientationSetting = "orientation";
    // Program or machine coordinates (Coordinates): the numbers, the grid and the drawing's turn; kept across
    // sessions.
    void set_machine_coordinates(bool machine);
    static constexpr const char* kCoordinatesSetting = "coordinates";
    [[nodiscard]] bool machine_coordinates() const { return machine_coordinates_; }
    // The coordinates shown: the machine's through the document's profile, or the program's.
    [[nodiscard]] Coordinates coordinates() const;
    void fit();
    void share();  // the Share button and S
    // The tape converted (`essi convert`: "essi", "eia", "gcode" in the profile it is read with) or drawn
    // ("dxf"); empty without a tape. export_file saves it (a download in the browser).
    [[nodiscard]] std::string export_text(const std::string& format) const;
    void export_file(const std::string& format);
    // The view as a PNG picture (the drawing area as drawn, the browser's download), taken after the next frame.
    void export_view_png();
    // The part of the program the drawing area shows (program mm; its box when the view is turned).
    [[nodiscard]] Box visible_box() const;
    void share_done(std::string url);        // the link is made (and copied)
    void share_failed(Phrase why);           // it could not be made
    // The share link, or why there is none (the Share link window, state().share_url).
    [[nodiscard]] std::string share_text() const;
    // The tape's report: as `essi check` makes it (its path the tape's name).
    [[nodiscard]] FileReport report() const;
    // Copies to the clipboard: the report as `essi check` prints it, one problem (`index` in the diagnostics) as
    // its line, one source line (`index` its number) or the inspector's text of the selected line.
    enum class CopyWhat { Report, Diagnostic, Line, Inspector };
    [[nodiscard]] std::string copy_text(CopyWhat what, std::uint32_t index = 0) const;
    void copy(CopyWhat what, std::uint32_t index = 0);
    void notify(Msg id, const MessageArgs& args = {});  // a short message in the toolbar (copied, paste ignored, ...)
    // A problem with the whole file, in the viewer's language ("" when there is none).
    [[nodiscard]] std::string banner_text() const;

    // The language of the panels (Language.hpp): the setting "lang", else the browser's or the environment's
    // (platform::system_language). `remember`: kept across sessions (the user's switch); the native viewer's
    // --lang is not.
    void set_language(Lang lang, bool remember = true);
    [[nodiscard]] Lang language() const { return ui_lang(); }
    static constexpr const char* kLanguageSetting = "lang";

    // window.essikit.state(): {status, name, stats, diagnostics, selection, view, ...} as JSON text.
    [[nodiscard]] std::string state_json() const;
    // One motion as JSON (for tests and embedding): {"index","line","kind","curve","start","end","segments"}.
    [[nodiscard]] std::string motion_json(std::size_t i) const;

    // --- The parts (read and changed by the panels and the input) ---
    [[nodiscard]] const Document* document() const { return load_.document(); }
    [[nodiscard]] const LoadController& loads() const { return load_; }
    [[nodiscard]] const Renderer& renderer() const { return renderer_; }
    // The panels' fonts (render/UiFonts.hpp): fonts().require_glyphs(text) for a text that may need glyphs the atlas
    // lacks (Chinese); the atlas is made again between frames (render()).
    [[nodiscard]] UiFonts& fonts() { return fonts_; }
    [[nodiscard]] const UiFonts& fonts() const { return fonts_; }
    [[nodiscard]] bool graphics_ok() const { return graphics_ok_; }
    // The last frame drew the tape (its segments, or its level of detail while they are made).
    [[nodiscard]] bool tape_drawn() const { return scene_.tape_drawn(); }
    [[nodiscard]] const std::string& profile_name() const { return profile_name_; }
    // The profile file dropped on the page (docs/viewer.md), if any.
    [[nodiscard]] const std::optional<Profile>& dropped_profile() const { return dropped_profile_; }
    [[nodiscard]] View& view() { return view_; }
    [[nodiscard]] Layers& layers() { return layers_; }
    [[nodiscard]] Playback& playback() { return playback_; }
    [[nodiscard]] Selection& selection() { return selection_; }
    [[nodiscard]] Input& input() { return input_; }
    [[nodiscard]] UiState& ui() { return ui_; }
    // The document's origin (GPU and view coordinates are relative to it).
    [[nodiscard]] Point origin() const { return document() ? document()->origin : Point{}; }
    // "c=X,Y,ZOOM&l=LINE&p=PROFILE[&pj=JSON]&i=FORMAT": the view, the selection and how the tape is read, for
    // a share link.
    [[nodiscard]] std::string share_query() const;

private:
    void step_loading();
    void document_loaded();
    void apply_pending_view(const Document& d);
    [[nodiscard]] double desired_tolerance() const;
    [[nodiscard]] float framebuffer_scale() const;
    [[nodiscard]] std::pair<int, int> framebuffer_size() const;
    void draw_panels();
    void follow_playback(const Document& d);  // the source view and the inspector show the playback's line

    GLFWwindow* window_ = nullptr;
    UiFonts fonts_;
    std::optional<TextEncoding> chosen_encoding_;
    TextEncoding detected_encoding_ = TextEncoding::Utf8;
    void require_comment_glyphs(const Document& d);
    bool fonts_changed_ = false;  // the atlas was made again after the last frame: the next one is drawn in full
    Renderer renderer_;
    UiRenderer ui_renderer_;
    bool graphics_ok_ = false;
    LoadController load_{renderer_};
    SceneAssembly scene_;
    std::optional<ViewRequest> pending_view_;  // set_view / select_line before the document is there
    std::string profile_name_ = std::string(kAutoProfile);  // a built-in profile, the dropped one, or "auto"
    std::optional<Profile> dropped_profile_;  // a profile file dropped on the page (its name is a choice too)
    std::optional<InputFormat> input_format_;  // the format a share link said the tape was read as (else the content's)
    std::unique_ptr<Compare> compare_;         // compare mode: the other revision and the differences
    bool compare_next_ = false;                // the next tape opened is the other revision
    bool png_pending_ = false;                 // the view is saved as PNG after the next frame is drawn
    std::uint64_t frames_ = 0;                 // frames begun (frame())
    bool in_frame_ = false;                    // inside frame(): the panels may hold the document
    bool use_profile_file(const std::string& name, const std::string& bytes);
    void read(std::string name, std::string bytes, std::optional<ViewRequest> view);  // with the profile and format chosen
    void use_link_profile(const ShareLink& link);
    static Lang startup_language();  // the setting "lang", else the platform's (Language.cpp)

    View view_;
    bool machine_coordinates_ = false;
    Layers layers_;
    Playback playback_;
    Selection selection_;
    Selection announced_;  // the selection the page last heard of (platform::selection_changed)
    Input input_;
    UiState ui_;
};

}  // namespace essi::viewer
