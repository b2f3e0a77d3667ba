// Desktop main loop: a GLFW window with an OpenGL ES 3.0 context (the API WebGL2 has), so the shaders and
// the renderer are the same text as in the browser. Usage: essi_viewer [TAPE]
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/App.hpp"

namespace essi::viewer::platform {
bool read_file(const std::string& path, std::string& out);  // FilesGlfw.cpp
void install_drop_handler(GLFWwindow* window);               // FilesGlfw.cpp
}  // namespace essi::viewer::platform

int main(int argc, char** argv) {
    using namespace essi::viewer;
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "essi_viewer: GLFW error %d: %s\n", code, text); });
    if (!glfwInit()) {
        std::fprintf(stderr, "essi_viewer: cannot initialise GLFW (no display?)\n");
        return 2;
    }
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
        glfwTerminate();
        return 2;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui_ImplGlfw_InitForOpenGL(window, true);

    {
        App app(window);
        if (!app.init_graphics()) std::fprintf(stderr, "essi_viewer: the drawing programs did not compile\n");
        platform::install_drop_handler(window);
        if (argc > 1) {
            std::string bytes;
            if (platform::read_file(argv[1], bytes)) app.load(argv[1], std::move(bytes));
            else std::fprintf(stderr, "essi_viewer: cannot read %s\n", argv[1]);
        }
        while (!glfwWindowShouldClose(window)) {
            glfwPollEvents();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            app.frame();
            ImGui::Render();
            app.render(false);  // (after a swap the back buffer must be drawn again)
            glfwSwapBuffers(window);
        }
    }
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}
