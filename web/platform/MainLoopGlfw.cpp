// Desktop main loop: a GLFW window with an OpenGL ES 3.0 context (the API WebGL2 has), so the shaders and
// the renderer are the same text as in the browser.
//
// Usage: essi_viewer [--frames N] [--screenshot FILE.ppm] [--state FILE.json] [--lang en|de|zh] [TAPE]
//   --frames N          draw N frames once the tape is loaded and drawn (or from the start without a tape), then
//                       exit (tests and scripts; without it the window stays until it is closed)
//   --screenshot FILE   with --frames: the last frame as a binary PPM (P6, RGB, top row first)
//   --state FILE        with --frames: the viewer's state JSON at the end (the page's window.essikit.state())
//   --lang L            the panels' language for this run (en, de, zh or a locale such as de_DE.UTF-8); without
//                       it the one chosen last in the viewer, else the environment's (LC_ALL, LC_MESSAGES, LANG)
#include <GLES3/gl3.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/App.hpp"
#include "app/KeyQueue.hpp"
#include "platform/FilesGlfw.hpp"
#include "platform/Platform.hpp"

namespace {

struct Options {
    std::string tape;
    long frames = -1;  // -1: run until the window closes
    std::string screenshot, state;
    std::optional<essi::Lang> lang;
};

int usage() {
    std::fprintf(
        stderr,
        "usage: essi_viewer [--frames N] [--screenshot FILE.ppm] [--state FILE.json] [--lang en|de|zh] [TAPE]\n");
    return 2;
}

// The back buffer of the frame just drawn (before the swap), bottom row first as GL reads it, written top first.
bool write_screenshot(const std::string& path, int w, int h) {
    std::vector<unsigned char> rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    if (glGetError() != GL_NO_ERROR) return false;
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << w << " " << h << "\n255\n";
    std::vector<unsigned char> row(static_cast<std::size_t>(w) * 3);
    for (int y = h - 1; y >= 0; --y) {
        const unsigned char* src = rgba.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w) * 4;
        for (int x = 0; x < w; ++x) std::memcpy(&row[static_cast<std::size_t>(x) * 3], src + x * 4, 3);
        out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size()));
    }
    return static_cast<bool>(out);
}

// The command line; false for a usage error.
bool parse(int argc, char** argv, Options& opt) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--frames" && has_value) {
            char* end = nullptr;
            opt.frames = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || opt.frames < 1) return false;
        } else if (a == "--screenshot" && has_value) {
            opt.screenshot = argv[++i];
        } else if (a == "--state" && has_value) {
            opt.state = argv[++i];
        } else if (a == "--lang" && has_value) {
            opt.lang = essi::parse_lang(argv[++i]);
            if (!opt.lang) return false;
        } else if (a == "--help" || a == "-h" || (a.size() > 1 && a[0] == '-') || !opt.tape.empty()) {
            return false;
        } else {
            opt.tape = a;
        }
    }
    return (opt.screenshot.empty() && opt.state.empty()) || opt.frames >= 0;
}

// A window with an OpenGL ES 3.0 context, current; null (and a message) when there is none.
GLFWwindow* open_window() {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    GLFWwindow* window = glfwCreateWindow(1600, 900, "essikit viewer", nullptr, nullptr);
    if (window == nullptr) {
        // Some drivers only give ES contexts through EGL.
        glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
        window = glfwCreateWindow(1600, 900, "essikit viewer", nullptr, nullptr);
    }
    if (window == nullptr) {
        std::fprintf(stderr, "essi_viewer: cannot open a window with an OpenGL ES 3.0 context\n");
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    return window;
}

// The last frame's screenshot and state, as --screenshot and --state ask; 0, or 1 when one cannot be written.
int write_outputs(const Options& opt, GLFWwindow* window, const essi::viewer::Automation& automation) {
    int status = 0;
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (!opt.screenshot.empty() && !write_screenshot(opt.screenshot, w, h)) {
        std::fprintf(stderr, "essi_viewer: cannot write %s\n", opt.screenshot.c_str());
        status = 1;
    }
    if (!opt.state.empty()) {
        std::ofstream out(opt.state, std::ios::binary);
        out << automation.state_json() << "\n";
        if (!out) {
            std::fprintf(stderr, "essi_viewer: cannot write %s\n", opt.state.c_str());
            status = 1;
        }
    }
    return status;
}

// Key events wait in a queue and reach ImGui a change per key and frame (app/KeyQueue.hpp): a key tapped within one
// frame is seen.
essi::viewer::KeyQueue& key_queue() {
    static essi::viewer::KeyQueue queue;
    return queue;
}

void on_key(GLFWwindow*, int key, int scancode, int action, int mods) {
    key_queue().push({key, scancode, action, mods});
}

void apply_keys(GLFWwindow* window) {
    for (const essi::viewer::KeyEvent& e : key_queue().take_frame())
        ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, e.action, e.mods);
}

// Loads the tape and runs the frames; the exit status.
int run(const Options& opt, GLFWwindow* window) {
    using namespace essi::viewer;
    platform::Platform platform;
    App app(platform);
    platform.connect(app);
    if (opt.lang)
        app.automation().set_language(*opt.lang, false);  // (for this run: the viewer's own choice stays kept)
    if (!app.init_graphics()) std::fprintf(stderr, "essi_viewer: the drawing programs did not compile\n");
    platform::install_drop_handler(window, app);
    if (!opt.tape.empty()) {
        std::string bytes;
        if (!platform::read_file(opt.tape, bytes)) {
            std::fprintf(stderr, "essi_viewer: cannot read %s\n", opt.tape.c_str());
            return 2;
        }
        app.load(opt.tape, std::move(bytes));
    }
    long frames_left = opt.frames;  // counted once the loading and the drawing's build are done
    while (!glfwWindowShouldClose(window)) {
        glfwPollEvents();
        apply_keys(window);
        ImGui_ImplGlfw_NewFrame();
        app.before_frame();  // (after the backend, which clears the navigation inputs)
        ImGui::NewFrame();
        app.frame();
        ImGui::Render();
        app.render(false);  // (after a swap the back buffer must be drawn again)
        if (frames_left > 0 && !app.has_background_work() && --frames_left == 0) {
            const int status = write_outputs(opt, window, app.automation());
            glfwSwapBuffers(window);
            return status;
        }
        glfwSwapBuffers(window);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!parse(argc, argv, opt)) return usage();
    glfwSetErrorCallback(
        [](int code, const char* text) { std::fprintf(stderr, "essi_viewer: GLFW error %d: %s\n", code, text); });
    if (!glfwInit()) {
        std::fprintf(stderr, "essi_viewer: cannot initialise GLFW (no display?)\n");
        return 2;
    }
    GLFWwindow* window = open_window();
    if (window == nullptr) {
        glfwTerminate();
        return 2;
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    glfwSetKeyCallback(window, on_key);  // replaces the backend's (apply_keys calls it)
    const int status = run(opt, window);
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}
