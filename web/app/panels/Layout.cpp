#include "app/panels/Layout.hpp"

#include <algorithm>
#include <cmath>

namespace essi::viewer::panels {

PanelWidths panel_widths(const PanelLayout& layout, float w) {
    PanelWidths p{layout.left_shown ? std::max(layout.left, kMinPanelWidth) : 0.f,
                  layout.right_shown ? std::max(layout.right, kMinPanelWidth) : 0.f};
    const float room = w / 2;  // (the drawing keeps the other half)
    if (p.left + p.right > room && p.left + p.right > 0) {
        const float k = room / (p.left + p.right);
        if (p.left > 0) p.left = std::max(p.left * k, std::min(kMinPanelWidth, room / 2));
        if (p.right > 0) p.right = std::max(p.right * k, std::min(kMinPanelWidth, room / 2));
    }
    return p;
}

bool begin_side_panel(PanelLayout& layout, bool& dragged, const char* name, bool left) {
    if (!(left ? layout.left_shown : layout.right_shown)) return false;
    const ImGuiIO& io = ImGui::GetIO();
    const PanelWidths pw = panel_widths(layout, io.DisplaySize.x);
    const float w = left ? pw.left : pw.right, h = io.DisplaySize.y - kToolbarHeight;
    // The width is set when it changes from outside (the window, the layout); between, the user may drag it.
    static float set_width[2] = {-1, -1};
    float& set = set_width[left ? 0 : 1];
    ImGui::SetNextWindowPos(ImVec2(left ? 0 : io.DisplaySize.x - w, kToolbarHeight));
    if (w != set) ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(kMinPanelWidth, w), h),
                                        ImVec2(std::max(io.DisplaySize.x / 2, w), h));
    set = w;
    ImGui::Begin(name, nullptr, kPanelFlags | ImGuiWindowFlags_NoCollapse);
    const float now = ImGui::GetWindowWidth();
    if (std::fabs(now - w) > 0.5f) {  // dragged
        (left ? layout.left : layout.right) = now;
        set = now;
        dragged = true;
    }
    return true;
}

Rect drawing_area(float w, float h, const PanelLayout& layout) {
    const PanelWidths p = panel_widths(layout, w);
    return Rect{p.left, kToolbarHeight, std::max(w - p.left - p.right, 50.f), std::max(h - kToolbarHeight, 50.f)};
}

// ImGui's window background blended over the drawing's background, in the 8-bit steps the GPU blends in (the
// same pixels).
Rgba panel_color(const Rgba& background) {
    const auto byte = [](float v) { return std::round(std::clamp(v, 0.f, 1.f) * 255.f) / 255.f; };
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    const float a = byte(bg.w);
    const auto over = [&](float top, float below) { return byte(top) * a + byte(below) * (1 - a); };
    return {over(bg.x, background.r), over(bg.y, background.g), over(bg.z, background.b), 1.f};
}

}  // namespace essi::viewer::panels
