// The platform under the viewer: PlatformServices (app/PlatformServices.hpp) implemented for the browser
// (Emscripten) and the desktop (GLFW), one file per concern and platform, chosen by CMake:
//   MainLoopEmscripten.cpp / MainLoopGlfw.cpp    main(), the window, the frame loop
//   FilesEmscripten.cpp    / FilesGlfw.cpp       the Open button, dropped files, downloads
//   ClipboardEmscripten.cpp / ClipboardGlfw.cpp  copy and paste
//   ShareEmscripten.cpp    / ShareGlfw.cpp       share links (URL fragment)
//   SettingsEmscripten.cpp / SettingsGlfw.cpp    settings kept across sessions (localStorage, a file), the language
//   FontsEmscripten.cpp    / FontsGlfw.cpp       the CJK font, loaded when a text needs it (UiFonts)
//   SelectionEmscripten.cpp / SelectionGlfw.cpp  the selection told to the page (window.essikitSelected)
//   MirrorEmscripten.cpp   / MirrorGlfw.cpp      the page's title and its text for screen readers (PageMirror)
//   ReadingWorkerEmscripten.cpp / ReadingWorkerGlfw.cpp  the reading worker (a Web Worker; none on the desktop)
//   ApiEmscripten.cpp                            window.essikit (exported C functions, into app/Automation.hpp)
// web/platform includes web/app's headers; web/app includes nothing of web/platform.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "app/AppCallbacks.hpp"
#include "app/PlatformServices.hpp"

namespace essi::viewer::platform {

class Platform final : public PlatformServices {
public:
    // The app that hears what the platform's services did (a file chosen, written, the clipboard empty ...).
    void connect(AppCallbacks& app) { app_ = &app; }

    [[nodiscard]] std::optional<std::string> load_setting(const char* name) override;
    void save_setting(const char* name, const std::string& value) override;
    [[nodiscard]] bool has_cjk_font() const override;
    void load_cjk_font(UiFonts& fonts) override;
    void open_file_dialog() override;
    void open_button_at(float x, float y, float width, float height) override;
    void save_file(const std::string& name, const std::string& text) override;
    bool show_html(const std::string& name, const std::string& html) override;
    void save_view_png(const std::string& name, PixelRect area) override;
    void open_example(const std::string& name) override;
    void copy_text(const std::string& text) override;
    void paste() override;
    void share(const std::string& name, std::string_view bytes, const std::string& view_query) override;
    [[nodiscard]] bool has_share_links() const override;
    [[nodiscard]] Lang system_language() override;
    void show_language(Lang lang) override;
    void selection_changed(std::uint32_t line, long long motion) override;
    void show_mirror(const PageMirror& mirror) override;
    [[nodiscard]] ReadingWorker* reading_worker() override;

private:
    // The desktop's services say how they went in the toolbar, and load the file chosen or pasted.
    void notify(Msg id, const MessageArgs& args = {}) {
        if (app_ != nullptr) app_->notify(id, args);
    }
    void load(std::string name, std::string bytes) {
        if (app_ != nullptr) app_->load(std::move(name), std::move(bytes));
    }

    AppCallbacks* app_ = nullptr;
};

}  // namespace essi::viewer::platform
