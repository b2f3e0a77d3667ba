// App's parts as the panels (panels::Panels) and the page's API (Automation) are given them: those two show or report
// nearly every part, so they share one list.
#pragma once

#include "app/CommentText.hpp"
#include "app/Compare.hpp"
#include "app/Exports.hpp"
#include "app/Layers.hpp"
#include "app/LoadController.hpp"
#include "app/Measure.hpp"
#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "app/Playback.hpp"
#include "app/PlatformServices.hpp"
#include "app/Preferences.hpp"
#include "app/SceneAssembly.hpp"
#include "app/Session.hpp"
#include "app/ShareLinks.hpp"
#include "app/UiState.hpp"
#include "app/WarmUp.hpp"
#include "render/Renderer.hpp"
#include "render/UiFonts.hpp"
#include "render/UiRenderer.hpp"

namespace essi::viewer {

struct ViewerParts {
    Session& session;
    const LoadController& load;
    Navigation& navigation;
    Layers& layers;
    Playback& playback;
    Measure& measure;
    CompareMode& compare;
    CommentText& comments;
    Exports& exports;
    const TapeFacts& tape_facts;
    ShareLinks& shares;
    Preferences& preferences;
    const Notices& notices;
    UiState& ui;
    UiFonts& fonts;
    const Renderer& renderer;
    const UiRenderer& ui_renderer;
    const SceneAssembly& scene;
    const WarmUp& warm_up;
    PlatformServices& platform;
    const bool& graphics_ok;  // the drawing programs compiled
};

}  // namespace essi::viewer
