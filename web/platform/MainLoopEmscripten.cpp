// Browser main loop: Emscripten's GLFW on a WebGL2 canvas that fills the page; one frame per
// requestAnimationFrame. index.html owns the canvas, the drop zone and window.essikit.
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "app/App.hpp"
#include "app/KeyQueue.hpp"
#include "platform/ApiEmscripten.hpp"
#include "platform/Platform.hpp"

namespace {

using essi::viewer::App;
using essi::viewer::KeyEvent;
using essi::viewer::KeyQueue;

// The page's loop: its window, its app, and what the loop keeps between frames.
struct Loop {
    GLFWwindow* window = nullptr;
    App* app = nullptr;
    bool background_queued = false;  // a background slice is queued (queue_background)
    int frames = 0;                  // frames drawn
    double pixel_ratio = 1;          // the device pixel ratio the canvas is drawn at (a hi-DPI screen: 2)
};

// The warm-up (app/WarmUp.hpp) starts once the page has drawn this many frames: its start comes first.
constexpr int kWarmUpAfterFrames = 3;

// Emscripten's GLFW (3.1.6) passes the browser's wheel deltas as the scroll offsets: pixels (about 100 a
// notch; 3 a notch in line mode), positive downwards. GLFW's offsets are notches, positive upwards: without
// this, one notch zoomed the drawing 1.2^120 times the wrong way and scrolled the panels by 120 lines.
constexpr double kWheelPixelsPerNotch = 100;
constexpr double kWheelLinesPerNotch = 3;
constexpr double kWheelLineModeBelow = 10;  // deltas smaller than this come in lines

void on_scroll(GLFWwindow* window, double dx, double dy) {
    auto notches = [](double d) {
        return -d / (std::fabs(d) < kWheelLineModeBelow ? kWheelLinesPerNotch : kWheelPixelsPerNotch);
    };
    ImGui_ImplGlfw_ScrollCallback(window, notches(dx), notches(dy));
}

// Key events wait in a queue and reach ImGui a change per key and frame (app/KeyQueue.hpp): a key tapped within one
// frame, or several arrows at once, are all seen.
KeyQueue& key_queue() {
    static KeyQueue queue;
    return queue;
}

void on_key(GLFWwindow*, int key, int scancode, int action, int mods) {
    key_queue().push({key, scancode, action, mods});
}

void apply_keys(GLFWwindow* window) {
    for (const KeyEvent& e : key_queue().take_frame())
        ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, e.action, e.mods);
}

// While the viewer loads, slices of its work also run between two animation frames (a task queued after each
// slice): under SwiftShader a frame takes 33-80 ms, nearly all of it outside this thread, and the loading would
// otherwise get only the ~30 ms slice inside each frame. No task is longer than a slice. The task is queued with
// a MessageChannel message: chained setTimeout(0) calls are held back 4 ms each by the browser. The message is the
// loop's address, handed back to essi_background_slice.
void queue_background(Loop* loop) {
    // clang-format off
    EM_ASM({
        if (!Module.essiBackgroundChannel) {
            Module.essiBackgroundChannel = new MessageChannel();
            Module.essiBackgroundChannel.port1.onmessage = function(e) { Module._essi_background_slice(e.data); };
        }
        Module.essiBackgroundChannel.port2.postMessage($0);
    }, loop);
    // clang-format on
}

}  // namespace

// `arg`: the Loop queue_background posted.
extern "C" EMSCRIPTEN_KEEPALIVE void essi_background_slice(void* arg) {
    Loop* loop = static_cast<Loop*>(arg);
    if (loop->app->background_step()) {
        queue_background(loop);
    } else {
        loop->background_queued = false;
    }
}

namespace {

// The canvas at its CSS size times the device pixel ratio (the canvas twice the CSS size each way at a ratio of 2).
void fit_canvas(Loop& loop) {
    double w = 0, h = 0;
    emscripten_get_element_css_size("#canvas", &w, &h);
    const double ratio = std::clamp(emscripten_get_device_pixel_ratio(), 0.5, 4.0);
    int cw = 0, ch = 0;
    glfwGetWindowSize(loop.window, &cw, &ch);
    if (w >= 1 && h >= 1 && (cw != static_cast<int>(w) || ch != static_cast<int>(h) || ratio != loop.pixel_ratio)) {
        // The canvas in device pixels, GLFW's window in CSS pixels (what ImGui lays out in). Not glfwSetWindowSize:
        // Emscripten's asks for fullscreen instead of sizing the canvas when the size is the screen's (F11, a
        // kiosk), and the canvas is left stretched.
        // clang-format off
        EM_ASM({
            Browser.setCanvasSize($2, $3);
            if (GLFW.active) {
                GLFW.active.width = $0;
                GLFW.active.height = $1;
            }
        }, static_cast<int>(w), static_cast<int>(h), static_cast<int>(std::lround(w * ratio)),
           static_cast<int>(std::lround(h * ratio)));
        // clang-format on
        loop.pixel_ratio = ratio;
    }
}

// Emscripten's GLFW gives the mouse in canvas (device) pixels: ImGui works in CSS pixels, drawn at the ratio.
void apply_pixel_ratio(double pixel_ratio) {
    ImGuiIO& io = ImGui::GetIO();
    const auto ratio = static_cast<float>(pixel_ratio);
    io.DisplayFramebufferScale = ImVec2(ratio, ratio);
    if (io.MousePos.x > -FLT_MAX / 2 && pixel_ratio != 1) {
        io.MousePos.x /= ratio;
        io.MousePos.y /= ratio;
    }
}

// A finger touched the screen (essi_touch_start): the mouse is not where it was any more, so nothing is hovered (no
// tooltip stays) until the browser's mouse events of a tap come, a press or a move.
bool g_touch_lifted_hover = false;
ImVec2 g_mouse_at;        // where GLFW says the mouse is (this frame)
ImVec2 g_touch_mouse_at;  // where it was when the finger touched

void touch_hover(ImGuiIO& io) {
    g_mouse_at = io.MousePos;
    if (!g_touch_lifted_hover) return;
    const bool pressed = std::any_of(std::begin(io.MouseDown), std::end(io.MouseDown), [](bool d) { return d; });
    if (pressed || io.MousePos.x != g_touch_mouse_at.x || io.MousePos.y != g_touch_mouse_at.y) {
        g_touch_lifted_hover = false;
        return;
    }
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
}

void frame(void* arg) {
    Loop& loop = *static_cast<Loop*>(arg);
    fit_canvas(loop);
    glfwPollEvents();
    apply_keys(loop.window);
    ImGui_ImplGlfw_NewFrame();
    loop.app->before_frame();  // (after the backend, which clears the navigation inputs)
    apply_pixel_ratio(loop.pixel_ratio);
    touch_hover(ImGui::GetIO());
    ImGui::NewFrame();
    loop.app->frame();
    ImGui::Render();
    loop.app->render(true);  // (the browser keeps showing an unchanged frame)
    if (++loop.frames == kWarmUpAfterFrames) loop.app->start_warm_up();
    if (loop.app->has_background_work() && !loop.background_queued) {
        loop.background_queued = true;
        queue_background(&loop);
    }
}

}  // namespace

int main() {
    if (!glfwInit()) {
        // clang-format off
        EM_ASM(if (window.essikitFatal) window.essikitFatal("GLFW could not start."));
        // clang-format on
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    // An opaque canvas with no depth or stencil buffer (the viewer draws neither): the WebGL context attributes
    // alpha, depth and stencil false. (With an alpha channel, the blended grid left the drawing area a little
    // translucent over the page.)
    glfwWindowHint(GLFW_ALPHA_BITS, 0);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    double w = 1280, h = 720;
    emscripten_get_element_css_size("#canvas", &w, &h);
    GLFWwindow* window = glfwCreateWindow(static_cast<int>(w), static_cast<int>(h), "essikit viewer", nullptr, nullptr);
    if (window == nullptr) {
        // clang-format off
        EM_ASM(if (window.essikitFatal) window.essikitFatal("This browser cannot give the page WebGL 2 (needed to draw)."));
        // clang-format on
        return 1;
    }
    glfwMakeContextCurrent(window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    glfwSetScrollCallback(window, on_scroll);  // replaces the backend's (on_scroll calls it)
    glfwSetKeyCallback(window, on_key);        // replaces the backend's (apply_keys calls it)
    // The platform, the app and the loop live as long as the page (main returns; the runtime stays).
    static essi::viewer::platform::Platform platform;
    static App app(platform);
    platform.connect(app);
    essi::viewer::platform::serve_page_api(app.automation());
    if (!app.init_graphics()) std::fprintf(stderr, "essi_viewer: the drawing programs did not compile\n");
    static Loop loop{window, &app};
    emscripten_set_main_loop_arg(frame, &loop, 0, false);
    // clang-format off
    EM_ASM(if (window.essikitStarted) window.essikitStarted());
    // clang-format on
    return 0;
}

extern "C" {
// The page's touchstart (index.html).
EMSCRIPTEN_KEEPALIVE void essi_touch_start() {
    g_touch_lifted_hover = true;
    g_touch_mouse_at = g_mouse_at;
}
}
