#include "app/panels/UiText.hpp"

#include <algorithm>
#include <cmath>

#include "app/Language.hpp"

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

float tooltip_wrap_x() {
    const ImGuiStyle& st = ImGui::GetStyle();
    constexpr float kTooltipEms = 32, kScreenMarginPx = 8;
    const float room = ImGui::GetIO().DisplaySize.x - 2 * (st.DisplaySafeAreaPadding.x + kScreenMarginPx) -
                       st.WindowPadding.x;  // (the window's other padding is before the wrap position)
    return std::max(std::min(ImGui::GetFontSize() * kTooltipEms, room), ImGui::GetFontSize() * 4);
}

void wrapped_tooltip(const std::string& text) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(tooltip_wrap_x());
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

ImVec4 severity_color(Severity s) {
    const Rgba& c = severity_rgba(s);  // (the marks' colours: render/Palette.hpp)
    return ImVec4(c.r, c.g, c.b, c.a);
}

}  // namespace essi::viewer
