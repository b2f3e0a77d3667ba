// The panels, one file per group: Toolbar.cpp (the buttons along the top), TapePanel.cpp (left: statistics,
// layers, playback, diagnostics), SourcePanel.cpp (right: the tape's text and the block inspector),
// Overlays.cpp (over the drawing: grid labels, the selection's direction, the measure; ProblemMarks.cpp the
// diagnostics' marks, ComparePanel.cpp compare mode), Messages.cpp (loading, drawing, welcome, problem and share
// windows) and Help.cpp. They read and change the parts App gives them.
#pragma once

#include <imgui.h>

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
#include "app/panels/Layout.hpp"
#include "render/Renderer.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer::panels {

class Panels {
public:
    // What the panels show and change.
    struct Parts {
        Session& session;
        const LoadController& load;
        Navigation& navigation;
        Layers& layers;
        Playback& playback;
        Measure& measure;
        CompareMode& compare;
        CommentText& comments;
        Exports& exports;
        ShareLinks& shares;
        Preferences& preferences;
        const Notices& notices;
        UiState& ui;
        UiFonts& fonts;
        const Renderer& renderer;
        const SceneAssembly& scene;
        PlatformServices& platform;
        const bool& graphics_ok;  // the drawing programs compiled
    };
    explicit Panels(const Parts& parts) : p_(parts) {}

    // A frame's panels (between ImGui::NewFrame and ImGui::Render).
    void draw();

private:
    void toolbar();
    void tape_panel();
    void source_panel();
    void overlays();
    // The diagnostics' marks (ProblemMarks.cpp): the hovered mark and its tooltip, the active marks' rings, the
    // collisions' overlapping areas; drawn by overlays().
    void problem_marks(ImDrawList* dl);
    void messages();
    // Compare mode (ComparePanel.cpp): the differences' window, and B's contours over the drawing.
    void compare_window();
    void compare_overlay(ImDrawList* dl);
    void help();

    Parts p_;
};

}  // namespace essi::viewer::panels
