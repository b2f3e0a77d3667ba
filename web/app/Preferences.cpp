#include "app/Preferences.hpp"

#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/Language.hpp"

namespace essi::viewer {

namespace {

// The side panels as one setting: {"left", "right", "left_shown", "right_shown"} (one line).
panels::PanelLayout layout_from_setting(const std::optional<std::string>& text) {
    panels::PanelLayout l;
    if (!text) return l;
    const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
    if (!j.is_object()) return l;
    const auto width = [&](const char* k, float& to) {
        if (j.contains(k) && j[k].is_number() && j[k].get<double>() >= panels::kMinPanelWidth &&
            j[k].get<double>() <= 4000)
            to = j[k].get<float>();
    };
    width("left", l.left);
    width("right", l.right);
    if (j.contains("left_shown") && j["left_shown"].is_boolean()) l.left_shown = j["left_shown"].get<bool>();
    if (j.contains("right_shown") && j["right_shown"].is_boolean()) l.right_shown = j["right_shown"].get<bool>();
    return l;
}

std::string layout_setting(const panels::PanelLayout& l) {
    return nlohmann::json{
        {"left", l.left}, {"right", l.right}, {"left_shown", l.left_shown}, {"right_shown", l.right_shown}}
        .dump();
}

}  // namespace

Preferences::Preferences(PlatformServices& platform, Renderer& renderer, Layers& layers, UiState& ui)
    : platform_(platform), renderer_(renderer), layers_(layers), ui_(ui) {
    ui_.layout = layout_from_setting(platform_.load_setting(kLayoutSetting));
    layers_.problems_only = platform_.load_int_setting(kProblemsOnlySetting).value_or(0) == 1;
    set_language(startup_language(), false);
}

void Preferences::graphics_ready(bool ok) {
    graphics_ok_ = ok;
    set_light_theme(platform_.load_int_setting(kThemeSetting).value_or(0) == 1);
}

void Preferences::set_light_theme(bool light) {
    if (light) ImGui::StyleColorsLight();
    else ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0;
    st.FrameRounding = 3;
    st.WindowBorderSize = 0;
    if (graphics_ok_) renderer_.set_theme(light ? kLightTheme : kDarkTheme);
    platform_.save_int_setting(kThemeSetting, light ? 1 : 0);
}

void Preferences::set_problems_only(bool on) {
    layers_.problems_only = on;
    platform_.save_int_setting(kProblemsOnlySetting, on ? 1 : 0);
}

void Preferences::set_layout(const panels::PanelLayout& layout) {
    panels::PanelLayout l = layout;
    if (!(l.left > 0)) l.left = ui_.layout.left;
    if (!(l.right > 0)) l.right = ui_.layout.right;
    l.left = std::max(l.left, panels::kMinPanelWidth);
    l.right = std::max(l.right, panels::kMinPanelWidth);
    ui_.layout = l;
    platform_.save_setting(kLayoutSetting, layout_setting(l));
}

void Preferences::keep_dragged_layout() {
    if (!ui_.layout_changed || ImGui::IsMouseDown(0)) return;  // (a drag of a panel's edge is saved once, at its end)
    ui_.layout_changed = false;
    platform_.save_setting(kLayoutSetting, layout_setting(ui_.layout));
}

// The user's choice (the setting), else what the browser or the environment asks for.
Lang Preferences::startup_language() {
    if (const auto setting = platform_.load_setting(kLanguageSetting))
        if (const auto lang = parse_lang(*setting)) return *lang;
    return platform_.system_language();
}

void Preferences::set_language(Lang lang, bool remember) {
    set_ui_lang(lang);
    if (remember) platform_.save_setting(kLanguageSetting, std::string(lang_code(lang)));
    platform_.show_language(lang);
}

Lang Preferences::language() const { return ui_lang(); }

}  // namespace essi::viewer
