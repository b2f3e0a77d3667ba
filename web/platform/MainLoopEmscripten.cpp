// Browser main loop: Emscripten's GLFW on a WebGL2 canvas that fills the page; one frame per
// requestAnimationFrame. index.html owns the canvas, the drop zone and window.essikit.
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>

#include "app/App.hpp"

namespace {

GLFWwindow* g_window = nullptr;
essi::viewer::App* g_app = nullptr;

void fit_canvas() {
    double w = 0, h = 0;
    emscripten_get_element_css_size("#canvas", &w, &h);
    int cw = 0, ch = 0;
    glfwGetWindowSize(g_window, &cw, &ch);
    if (w >= 1 && h >= 1 && (cw != static_cast<int>(w) || ch != static_cast<int>(h)))
        glfwSetWindowSize(g_window, static_cast<int>(w), static_cast<int>(h));
}

void frame(void*) {
    fit_canvas();
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    g_app->frame();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace

int main() {
    if (!glfwInit()) {
        EM_ASM(if (window.essikitFatal) window.essikitFatal("GLFW could not start."));
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    double w = 1280, h = 720;
    emscripten_get_element_css_size("#canvas", &w, &h);
    g_window = glfwCreateWindow(static_cast<int>(w), static_cast<int>(h), "essikit viewer", nullptr, nullptr);
    if (g_window == nullptr) {
        EM_ASM(if (window.essikitFatal) window.essikitFatal("This browser cannot give the page WebGL 2 (needed to draw)."));
        return 1;
    }
    glfwMakeContextCurrent(g_window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui_ImplGlfw_InitForOpenGL(g_window, true);
    ImGui_ImplOpenGL3_Init("#version 300 es");
    g_app = new essi::viewer::App(g_window);
    if (!g_app->init_graphics()) std::fprintf(stderr, "essi_viewer: the drawing programs did not compile\n");
    emscripten_set_main_loop_arg(frame, nullptr, 0, false);
    EM_ASM(if (window.essikitStarted) window.essikitStarted());
    return 0;
}
