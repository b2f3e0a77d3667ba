// Where the panels are: the toolbar along the top, a side panel on each side (shown or hidden, their widths dragged
// at their inner edge), the drawing area between them.
#pragma once

#include <imgui.h>

#include "app/View.hpp"
#include "render/Palette.hpp"

namespace essi::viewer::panels {

inline constexpr float kToolbarHeight = 38;
inline constexpr float kLeftWidth = 310;
inline constexpr float kRightWidth = 470;
// The toolbar and the side panels draw no background: the renderer clears the window in their colour (ImGui's
// window background over the drawing's, as they looked), which saves SwiftShader filling a million pixels a frame.
inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                                ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoBackground;

inline constexpr float kMinPanelWidth = 160;  // a side panel is no narrower (when shown)
// A window lower than this (1024 x 600) opens the left panel with its reading and diagnostics only, and the Compare
// window collapsed to its title: the problems list and the plate's edges stay in sight.
inline constexpr float kShortWindowPx = 720;

// The side panels as the user set them (docs/viewer.md, "Layout"): widths dragged at their inner edge, shown or
// hidden; kept across sessions (setting "layout").
struct PanelLayout {
    float left = kLeftWidth, right = kRightWidth;
    bool left_shown = true, right_shown = true;
    friend bool operator==(const PanelLayout&, const PanelLayout&) = default;
};
// The panels' widths in a window `w` wide: the drawing keeps at least half of it (the panels give way in
// proportion, down to kMinPanelWidth), a hidden panel takes nothing.
struct PanelWidths {
    float left = 0, right = 0;
};
[[nodiscard]] PanelWidths panel_widths(const PanelLayout& layout, float w);
// The drawing area of a window of w x h pixels: what the toolbar and the side panels leave.
[[nodiscard]] Rect drawing_area(float w, float h, const PanelLayout& layout);
// Begins a side panel's window (`left` or right) at its width, resizable at its inner edge: a drag sets the
// layout's width and `dragged` (Preferences keeps it once the mouse is up). False when the panel is hidden (nothing
// to end then).
bool begin_side_panel(PanelLayout& layout, bool& dragged, const char* name, bool left);
// What the panels looked like with their own background (the colour the window is cleared in around the drawing).
[[nodiscard]] Rgba panel_color(const Rgba& background);

}  // namespace essi::viewer::panels
