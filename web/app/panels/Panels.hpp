// The panels, one file per group: Toolbar.cpp (the buttons along the top), TapePanel.cpp (left: statistics,
// layers, playback, diagnostics), SourcePanel.cpp (right: the tape's text and the block inspector),
// Overlays.cpp (over the drawing: grid labels, the selection's direction, the measure), Messages.cpp (loading,
// drawing, welcome, problem and share windows) and Help.cpp. They read and change the App's parts.
#pragma once

#include <imgui.h>

#include "app/View.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {
class App;
}

namespace essi::viewer::panels {

inline constexpr float kToolbarHeight = 38;
inline constexpr float kLeftWidth = 310;
inline constexpr float kRightWidth = 470;
// The toolbar and the side panels draw no background: the renderer clears the window in their colour (ImGui's
// window background over the drawing's, as they looked), which saves SwiftShader filling a million pixels a frame.
inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                                ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoBackground;

// The drawing area of a window of w x h pixels: what the toolbar and the side panels leave.
[[nodiscard]] Rect drawing_area(float w, float h);
// What the panels looked like with their own background (the colour the window is cleared in around the drawing).
[[nodiscard]] Rgba panel_color();

void toolbar(App& app);
void tape_panel(App& app);
void source_panel(App& app);
void overlays(App& app);
void messages(App& app);
void help(App& app);

}  // namespace essi::viewer::panels
