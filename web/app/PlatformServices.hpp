// What the viewer needs from the platform it runs on, declared here and implemented by web/platform (one file per
// concern and platform, chosen by CMake): the app includes nothing of web/platform. The platform's answers that come
// later (a file chosen or dropped, what a service did) reach the app through AppCallbacks.hpp.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "app/PageMirror.hpp"
#include "app/ReadingWorker.hpp"
#include "essi/i18n.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer {

// Settings kept across sessions (the browser's localStorage, a file on the desktop): one line of text each, by name;
// none when it was never saved.
class SettingsStore {
public:
    virtual ~SettingsStore() = default;
    [[nodiscard]] virtual std::optional<std::string> load_setting(const char* name) = 0;
    virtual void save_setting(const char* name, const std::string& value) = 0;

    // A whole number kept as its decimal text.
    [[nodiscard]] std::optional<int> load_int_setting(const char* name) {
        const std::optional<std::string> text = load_setting(name);
        if (!text) return std::nullopt;
        return std::atoi(text->c_str());
    }
    void save_int_setting(const char* name, int value) { save_setting(name, std::to_string(value)); }
};

// A rectangle of the framebuffer (its pixels, top-left origin).
struct PixelRect {
    float x, y, w, h;
};

class PlatformServices : public SettingsStore, public CjkFontSource {
public:
    // --- Files ---
    // Opens the platform's file picker; the chosen file arrives through AppCallbacks::load.
    virtual void open_file_dialog() = 0;
    // Where the Open button is drawn this frame (screen pixels). Browsers show a file picker only during the user's
    // click or key press, and the frame that sees the click may come after that gesture has expired: the page opens
    // the picker in the click event itself when it lands on this rectangle.
    virtual void open_button_at(float x, float y, float width, float height) = 0;
    // Saves `text` as a file called `name`: the browser's download, or a file in the current folder natively.
    virtual void save_file(const std::string& name, const std::string& text) = 0;
    // Shows `html`, a whole page, in a new tab of the browser (to read and print); where none opens (a pop-up
    // blocker, the desktop viewer) saves it as the file `name` instead and returns false.
    virtual bool show_html(const std::string& name, const std::string& html) = 0;
    // Saves the frame just drawn, cropped to `area`, as a PNG file `name`: the browser's download; natively a
    // message that the browser viewer does it.
    virtual void save_view_png(const std::string& name, PixelRect area) = 0;
    // The examples the server offers (essi serve's /examples/): the page fetches their list at start and a click
    // opens one (the page fetches it and loads it). Natively there are none.
    virtual void open_example(const std::string& name) = 0;

    // --- Clipboard ---
    virtual void copy_text(const std::string& text) = 0;
    // Ctrl+V on the canvas: natively loads the clipboard's text; in the browser the page's paste event does it.
    virtual void paste() = 0;

    // --- Share links ---
    // Makes a share link for the tape and the view (`view_query`: "c=X,Y,ZOOM&l=LINE"); the page hands the result
    // to the page API (Automation::share_done, share_failed).
    virtual void share(const std::string& name, std::string_view bytes, const std::string& view_query) = 0;
    [[nodiscard]] virtual bool has_share_links() const = 0;

    // --- The language and the page ---
    // The language the browser asks for (navigator.languages: the first one essikit has texts for) or the
    // environment (LC_ALL, LC_MESSAGES, LANG: essi::lang_from_environment); English when none.
    [[nodiscard]] virtual Lang system_language() = 0;
    // The page follows the viewer's language (<html lang>, the drop hint's text); nothing natively.
    virtual void show_language(Lang lang) = 0;
    // The selected line (0: none) and motion (-1: none) changed: the page hears of it through
    // window.essikitSelected(line, motion) (<essi-viewer> fires essi-select); nothing natively.
    virtual void selection_changed(std::uint32_t line, long long motion) = 0;
    // What the page shows for screen readers changed (PageMirror: the title, the live region, the problems): the
    // browser puts it in the page's title and its elements beside the canvas (window.essikitMirror); the desktop
    // sets its window's title.
    virtual void show_mirror(const PageMirror& mirror) = 0;
    // The reading worker, where tapes too big to load at once are read and checked off the drawing's thread (a
    // Web Worker in the browser, ReadingWorkerEmscripten.cpp); null: the page reads them itself (the desktop).
    [[nodiscard]] virtual ReadingWorker* reading_worker() { return nullptr; }
};

}  // namespace essi::viewer
