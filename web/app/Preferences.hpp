// The user's choices kept across sessions that belong to no other part: the theme, the problems-only view, the side
// panels' layout and the panels' language (Language.hpp).
#pragma once

#include "app/Layers.hpp"
#include "app/PlatformServices.hpp"
#include "app/UiState.hpp"
#include "essi/i18n.hpp"
#include "render/Renderer.hpp"

namespace essi::viewer {

class Preferences {
public:
    static constexpr const char* kThemeSetting = "theme";
    static constexpr const char* kProblemsOnlySetting = "problems_only";
    static constexpr const char* kLayoutSetting = "layout";
    static constexpr const char* kLanguageSetting = "lang";

    // The problems-only view, the layout and the language as they were kept (the language: the setting, else the
    // platform's).
    Preferences(PlatformServices& platform, Renderer& renderer, Layers& layers, UiState& ui);
    // The graphics are made (ok or not): the theme as it was kept.
    void graphics_ready(bool ok);

    // The light theme beside the dark one (the drawing's background, the grid, the panels).
    void set_light_theme(bool light);
    [[nodiscard]] bool light_theme() const { return renderer_.theme().light; }
    // The problems-only view (Layers::problems_only, key P).
    void set_problems_only(bool on);
    [[nodiscard]] bool problems_only() const { return layers_.problems_only; }
    // The side panels shown or hidden, their widths (0: as they are).
    void set_layout(const panels::PanelLayout& layout);
    // A frame begins: a side panel's width the user dragged is kept once the mouse is up.
    void keep_dragged_layout();
    // The language of the panels. `remember`: kept across sessions (the user's switch); the native viewer's --lang
    // is not.
    void set_language(Lang lang, bool remember = true);
    [[nodiscard]] Lang language() const;

private:
    [[nodiscard]] Lang startup_language();

    PlatformServices& platform_;
    Renderer& renderer_;
    Layers& layers_;
    UiState& ui_;
    bool graphics_ok_ = false;
};

}  // namespace essi::viewer
