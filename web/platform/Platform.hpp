// What the UI needs from the platform. One file per concern and platform, chosen by CMake:
//   MainLoopEmscripten.cpp / MainLoopGlfw.cpp    main(), the window, the frame loop
//   FilesEmscripten.cpp    / FilesGlfw.cpp       the Open button, dropped files
//   ClipboardEmscripten.cpp / ClipboardGlfw.cpp  copy and paste
//   ShareEmscripten.cpp    / ShareGlfw.cpp       share links (URL fragment)
//   SettingsEmscripten.cpp / SettingsGlfw.cpp    settings kept across sessions (localStorage, a file)
//   FontsEmscripten.cpp    / FontsGlfw.cpp       the CJK font, loaded when a text needs it (UiFonts)
//   SelectionEmscripten.cpp / SelectionGlfw.cpp  the selection told to the page (window.essikitSelected)
//   ApiEmscripten.cpp                            window.essikit (exported C functions)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "essi/i18n.hpp"

namespace essi::viewer {
class App;
class UiFonts;
}

namespace essi::viewer::platform {

// Opens the platform's file picker; the chosen file arrives through App::load.
void open_file_dialog(App& app);
[[nodiscard]] bool has_file_dialog();
// Where the Open button is drawn this frame (screen pixels). Browsers show a file picker only during the
// user's click or key press, and the frame that sees the click may come after that gesture has expired:
// the page opens the picker in the click event itself when it lands on this rectangle.
void open_button_at(float x, float y, float width, float height);

// Saves `text` as a file called `name`: the browser's download, or a file in the current folder natively.
void save_file(App& app, const std::string& name, const std::string& text);

// Saves the frame just drawn, cropped to `area` (framebuffer pixels, top-left origin), as a PNG file `name`: the
// browser's download; natively a message that the browser viewer does it.
struct PixelRect {
    float x, y, w, h;
};
void save_view_png(App& app, const std::string& name, PixelRect area);

// Copies text to the clipboard.
void copy_text(const std::string& text);
// Ctrl+V on the canvas: natively loads the clipboard's text; in the browser the page's paste event does it.
void paste(App& app);

// Makes a share link for the tape and the view (`view_query`: "c=X,Y,ZOOM&l=LINE"); the result arrives
// through App::share_done(ok, url_or_message).
void share(App& app, const std::string& name, std::string_view bytes, const std::string& view_query);
[[nodiscard]] bool has_share_links();

// A setting kept across sessions (the view's orientation): none when it was never saved.
[[nodiscard]] std::optional<int> load_setting(const char* name);
void save_setting(const char* name, int value);
// The same for text (one line: line ends are not kept).
[[nodiscard]] std::optional<std::string> load_text_setting(const char* name);
void save_text_setting(const char* name, const std::string& value);

// The language the browser asks for (navigator.languages: the first one essikit has texts for) or the environment
// (LC_ALL, LC_MESSAGES, LANG: essi::lang_from_environment); English when none (SettingsEmscripten/Glfw.cpp).
[[nodiscard]] Lang system_language();
// The page follows the viewer's language (<html lang>, the drop hint's text); nothing natively.
void show_language(Lang lang);

// The examples the server offers (essi serve's /examples/): the page fetches their list at start (App::set_examples)
// and a click opens one (the page fetches it and loads it). Natively there are none.
void open_example(App& app, const std::string& name);

// Loads the CJK font (render/UiFonts.hpp) and hands its bytes to fonts.cjk_loaded (null when it cannot be had): the
// browser fetches essi_cjk.ttc from the page's folder and calls back later, between frames; the desktop reads the
// file the build found (ESSI_CJK_FONT; the environment's ESSI_CJK_FONT overrides it) before it returns.
void load_cjk_font(UiFonts& fonts);
// This build has a CJK font to load (scripts/setup installs fonts-wqy-microhei).
[[nodiscard]] bool has_cjk_font();

// The selected line (0: none) and motion (-1: none) changed: the page hears of it through
// window.essikitSelected(line, motion) (<essi-viewer> fires essi-select); nothing natively.
void selection_changed(std::uint32_t line, long long motion);

}  // namespace essi::viewer::platform
