// What the panels share between frames that belongs to no other part: the windows shown, where the toolbar's items
// are, the diagnostic's mark under the mouse, the side panels' layout, the examples the server offers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "app/ProblemList.hpp"
#include "app/ScreenLayout.hpp"
#include "app/ShownProgress.hpp"
#include "app/View.hpp"
#include "app/panels/Layout.hpp"

namespace essi::viewer {

// One item of the toolbar as the last frame drew it (state().toolbar): in the bar, or in its overflow menu (drawn
// there only while the menu is open).
struct ToolbarItem {
    const char* id = "";
    Rect rect;  // screen pixels (nothing while it is in the closed menu)
    bool in_menu = false;
};

// Where the keyboard's focus is (KeyboardFocus): nowhere in particular (the mouse's way: the shortcuts act on the
// drawing), on the drawing (reached with Tab: the shortcuts act on it, a focus ring around it), or on a control of the
// toolbar, a panel or a window (ImGui's keyboard navigation: arrows, Enter, Esc; the playback's keys wait).
enum class KeyboardMode : std::uint8_t { Mouse, Drawing, Panels };

struct UiState {
    bool help = false;
    bool share_popup = false;                    // the Share link window (ShareLinks::text)
    ShownProgress loading_progress;              // the loading window's bar
    std::size_t hovered_mark = ~std::size_t(0);  // the diagnostic's mark under the mouse (Document::marks), or none
    std::vector<ToolbarItem> toolbar;            // the toolbar's items (Panels::toolbar)
    Rect toolbar_more;                           // its overflow menu's button (w 0: every item fits)
    bool toolbar_menu_open = false;
    Rect measure_window;                // where the Measure window was drawn (w 0: not shown)
    std::vector<std::string> examples;  // the tapes the server offers (the start screen), none natively
    panels::PanelLayout layout;         // the side panels (kept across sessions: Preferences::set_layout)
    bool layout_changed = false;        // by the user this frame: saved once the mouse is up
    KeyboardMode keyboard = KeyboardMode::Mouse;
    std::string keyboard_window;  // the window the keyboard's focus is in (ImGui's name), empty: none
    std::string keyboard_list;    // the list (child window) whose box has the focus, empty: none
    bool compact = false;         // the window is narrow: the bottom sheet instead of the side panels
    BottomSheet sheet;            // the bottom sheet of the compact layout
    // The problems list (ProblemList) of the document's diagnostics, made again when they change (another load,
    // more findings), and its groups that are open.
    struct ProblemsOf {
        const void* document = nullptr;
        std::uint64_t handed_frame = 0;  // its load's (LoadController::LoadFrames::handed)
        std::size_t diagnostics = 0;
        friend bool operator==(const ProblemsOf&, const ProblemsOf&) = default;
    };
    ProblemList problems;
    ProblemsOf problems_of;
    std::vector<bool> open_groups;
    std::vector<Rect> group_rects;  // the groups' rows as the last frame drew them (w 0: not drawn)
    // Controls the last frame drew, by name (state().controls): the sheet's tabs, next and previous problem.
    std::vector<std::pair<std::string, Rect>> controls;
    Rect tooltip;  // the tooltip the last frame showed (w 0: none), state().tooltip
};

}  // namespace essi::viewer
