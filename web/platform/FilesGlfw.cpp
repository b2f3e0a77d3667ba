// Desktop files: the Open button asks zenity (when installed) for a path; files dropped on the window load.
#include "platform/FilesGlfw.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "app/Language.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

bool read_file(const std::string& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    out = std::move(ss).str();
    return true;
}

void install_drop_handler(GLFWwindow* window, AppCallbacks& app) {
    glfwSetWindowUserPointer(window, &app);
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        auto* app = static_cast<AppCallbacks*>(glfwGetWindowUserPointer(w));
        if (app == nullptr || count < 1) return;
        std::string bytes;
        if (read_file(paths[0], bytes)) app->load(paths[0], std::move(bytes));
        else app->notify(Msg::UiCannotRead, {paths[0]});
    });
}

void Platform::open_button_at(float, float, float, float) {}  // a desktop dialog can open from any frame

void Platform::open_file_dialog() {
    const std::string command =
        std::string("zenity --file-selection --title='") + tr(Msg::UiOpenDialogTitle) + "' 2>/dev/null";
    FILE* p = popen(command.c_str(), "r");
    std::string path;
    if (p != nullptr) {
        char buf[4096];
        while (fgets(buf, sizeof buf, p) != nullptr) path += buf;
        pclose(p);
    }
    while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
    if (path.empty()) {
        notify(Msg::UiNoFileChosen);
        return;
    }
    std::string bytes;
    if (read_file(path, bytes)) load(path, std::move(bytes));
    else notify(Msg::UiCannotRead, {path});
}

void Platform::save_file(const std::string& name, const std::string& text) {
    std::ofstream out(name, std::ios::binary);
    out << text;
    notify(out ? Msg::UiWrote : Msg::UiCannotWrite, {name});
}

bool Platform::show_html(const std::string& name, const std::string& html) {
    save_file(name, html);  // (no browser here: the file, to open in one)
    return true;
}

void Platform::open_example(const std::string&) {}  // (the desktop viewer has no server: no examples are offered)

void Platform::save_view_png(const std::string&, PixelRect) { notify(Msg::UiPngBrowserOnly); }

}  // namespace essi::viewer::platform
