// The layout by the screen's width (docs/viewer.md, "Layout"): side panels on a wide screen; below
// kCompactBelowPx a bottom sheet with tabs (Problems, Statistics, Source, Inspector) under the drawing, which takes
// the whole width. The sheet starts collapsed to its tabs; a tab opens it, the open tab closes it again.
#pragma once

#include <cstdint>

#include "app/View.hpp"

namespace essi::viewer {

inline constexpr float kCompactBelowPx = 700;    // a window narrower than this has the bottom sheet
inline constexpr float kSheetTabsHeight = 40;    // the collapsed sheet: its row of tabs (a finger's height)
inline constexpr float kSheetOpenShare = 0.45f;  // the open sheet: this share of the window's height

enum class SheetTab : std::uint8_t { Problems, Statistics, Source, Inspector };
inline constexpr int kSheetTabs = 4;
// "problems", "statistics", "source", "inspector" (state().sheet).
[[nodiscard]] const char* sheet_tab_name(SheetTab t);

// The bottom sheet: which tab is open (none: collapsed to its tabs).
struct BottomSheet {
    bool open = false;
    SheetTab tab = SheetTab::Problems;
    // A tab tapped: it opens the sheet on it, or closes the sheet when it is the open one.
    void tap(SheetTab t) {
        open = !(open && tab == t);
        tab = t;
    }
};

// The bottom sheet for a window `w` wide (the side panels otherwise).
[[nodiscard]] inline bool compact_layout(float w) { return w < kCompactBelowPx; }
// The sheet's height in a window `h` high.
[[nodiscard]] float sheet_height(const BottomSheet& sheet, float h);
// The drawing area of the compact layout: the width of the window, between the toolbar (`top` high) and the sheet.
[[nodiscard]] Rect compact_drawing_area(float w, float h, float top, const BottomSheet& sheet);

}  // namespace essi::viewer
