// The keyboard's focus through the viewer (docs/viewer.md, "Keyboard and screen readers"). Tab and Shift+Tab move it
// from control to control of a window (the toolbar, the Tape panel, the Source panel, the windows shown), on to the
// next window after a window's last control, and to the drawing after the last window; a list (the diagnostics, the
// source lines) is one stop: Enter goes into it, the arrows move through it, Enter chooses, Esc or Tab leave it.
// ImGui's keyboard navigation (its highlight is the focus ring) is on while the focus is on a control; a mouse press
// ends it. On the drawing a ring is drawn around it and the shortcuts act on it as with the mouse.
#pragma once

#include "app/UiState.hpp"
#include "app/View.hpp"

namespace essi::viewer {

class KeyboardFocus {
public:
    explicit KeyboardFocus(UiState& ui) : ui_(ui) {}

    // Once the ImGui context exists: Tab is read here, not by ImGui's own tabbing (which knows only text fields).
    void init();
    // Before ImGui's frame begins: Enter chooses the focused control, as Space does.
    void before_new_frame();
    // Before the panels: a mouse press ends the keyboard's focus; Tab moves it.
    void begin_frame();
    // After the panels: a Tab past a window's last (first) control goes on to the next (previous) window, or the
    // drawing; the ring around the drawing when it has the focus.
    void end_frame(const Rect& drawing_area);

private:
    enum class Tabbing { None, Forward, Backward };
    void tab(bool forward);
    void next_window(bool forward);
    void focus_drawing();
    void leave();
    void note_focus();

    UiState& ui_;
    Tabbing tabbing_ = Tabbing::None;   // a tab through a window's controls asked for this frame
    Tabbing pending_ = Tabbing::None;   // a tab that ran past its window's controls: the next window, next frame
    bool from_start_ = false;           // that tab began with no control focused in its window
    bool tabbed_ = false;               // a tab was asked for in the last frame (its landing activates nothing)
    const void* tab_window_ = nullptr;  // the window that tab runs through (its root: where the next one is found)
};

}  // namespace essi::viewer
