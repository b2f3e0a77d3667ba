#include "app/panels/UiText.hpp"

#include <algorithm>
#include <cmath>

#include "app/App.hpp"
#include "app/Language.hpp"
#include "app/panels/Panels.hpp"

namespace essi::viewer {

namespace {
constexpr float kProgressSteps = 50;  // progress is shown in 2 % steps (stepped())
}

std::string hms(double seconds) {
    const long s = static_cast<long>(std::llround(seconds));
    return fmt("%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
}

std::string size_text(std::size_t bytes) {
    if (bytes < 1024) return tr(Msg::UiBytes, {bytes});
    if (bytes < 1024 * 1024) return fmt("%.1f KB", static_cast<double>(bytes) / 1024.0);
    return fmt("%.1f MB", static_cast<double>(bytes) / 1048576.0);
}

std::string printable(std::string_view s, std::size_t max) {
    std::string out;
    out.reserve(std::min(s.size(), max));
    for (std::size_t i = 0; i < s.size() && i < max; ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        out.push_back(c == '\t' ? ' ' : (c < 0x20 || c >= 0x7F) ? '?' : static_cast<char>(c));
    }
    if (s.size() > max) out += " ...";
    return out;
}

float stepped(float progress) { return std::floor(progress * kProgressSteps) / kProgressSteps; }

void same_line_if_fits(float width) {
    const float x = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x;
    if (x + width <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

void hint_wrapped(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

ImVec4 severity_color(Severity s) {
    const Rgba& c = severity_rgba(s);  // (the marks' colours: render/Palette.hpp)
    return ImVec4(c.r, c.g, c.b, c.a);
}

namespace panels {

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

bool begin_side_panel(App& app, const char* name, bool left) {
    PanelLayout& layout = app.ui().layout;
    if (!(left ? layout.left_shown : layout.right_shown)) return false;
    const ImGuiIO& io = ImGui::GetIO();
    const PanelWidths pw = panel_widths(layout, io.DisplaySize.x);
    const float w = left ? pw.left : pw.right, h = io.DisplaySize.y - kToolbarHeight;
    // The width is set when it changes from outside (the window, the layout); between, the user may drag it.
    static float set_width[2] = {-1, -1};
    float& set = set_width[left ? 0 : 1];
    ImGui::SetNextWindowPos(ImVec2(left ? 0 : io.DisplaySize.x - w, kToolbarHeight));
    if (w != set) ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(kMinPanelWidth, w), h), ImVec2(std::max(io.DisplaySize.x / 2, w), h));
    set = w;
    ImGui::Begin(name, nullptr, kPanelFlags | ImGuiWindowFlags_NoCollapse);
    const float now = ImGui::GetWindowWidth();
    if (std::fabs(now - w) > 0.5f) {  // dragged
        (left ? layout.left : layout.right) = now;
        set = now;
        app.ui().layout_changed = true;
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

}  // namespace panels

}  // namespace essi::viewer
