// The window's pixels: its size (ImGui's, in CSS pixels in the browser) times the framebuffer scale (a hi-DPI
// screen's device pixel ratio: the browser's canvas is that much larger than the page's CSS pixels,
// web/platform/MainLoopEmscripten.cpp).
#pragma once

#include <imgui.h>

#include <cmath>
#include <utility>

namespace essi::viewer {

[[nodiscard]] inline float framebuffer_scale() {
    const float s = ImGui::GetIO().DisplayFramebufferScale.x;
    return s > 0 ? s : 1.f;
}

[[nodiscard]] inline std::pair<int, int> framebuffer_size() {
    const ImGuiIO& io = ImGui::GetIO();
    return {static_cast<int>(std::lround(io.DisplaySize.x * framebuffer_scale())),
            static_cast<int>(std::lround(io.DisplaySize.y * framebuffer_scale()))};
}

}  // namespace essi::viewer
