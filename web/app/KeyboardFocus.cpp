#include "app/KeyboardFocus.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace essi::viewer {

namespace {

constexpr float kRowBandPx = 40;   // windows whose tops are this close are in one row of the Tab order
constexpr float kRingWidthPx = 3;  // the drawing's focus ring
constexpr ImGuiWindowFlags kNotInTabOrder = ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip |
                                            ImGuiWindowFlags_Popup | ImGuiWindowFlags_NoNavInputs |
                                            ImGuiWindowFlags_NoNavFocus;

// A window with a control to focus (a message with text only has none: the page's live region says it), in the
// last frame or this one.
bool has_controls(const ImGuiWindow* w) {
    constexpr int kMain = 1 << ImGuiNavLayer_Main;
    return ((w->DC.NavLayersActiveMask | w->DC.NavLayersActiveMaskNext) & kMain) != 0;
}

// The windows Tab goes through, shown in the last frame, in reading order: by rows (the toolbar and the side panels,
// then the windows over the drawing), left to right, top first.
std::vector<ImGuiWindow*> tab_order() {
    std::vector<ImGuiWindow*> out;
    for (ImGuiWindow* w : GImGui->Windows)
        if (w->WasActive && !w->Hidden && (w->Flags & kNotInTabOrder) == 0 && has_controls(w)) out.push_back(w);
    std::stable_sort(out.begin(), out.end(), [](const ImGuiWindow* a, const ImGuiWindow* b) {
        const float ra = std::floor(a->Pos.y / kRowBandPx), rb = std::floor(b->Pos.y / kRowBandPx);
        if (ra != rb) return ra < rb;
        return a->Pos.x != b->Pos.x ? a->Pos.x < b->Pos.x : a->Pos.y < b->Pos.y;
    });
    return out;
}

// The focus on a window's first control, with ImGui's highlight (the focus ring) shown.
void enter(ImGuiWindow* w) {
    ImGuiContext& g = *GImGui;
    ImGui::NavMoveRequestCancel();
    ImGui::FocusWindow(w);
    ImGui::NavInitWindow(w, true);
    g.NavDisableHighlight = false;
    g.NavDisableMouseHover = true;
}

bool enter_pressed() {
    const ImGuiIO& io = ImGui::GetIO();
    return io.KeysDown[GLFW_KEY_ENTER] || io.KeysDown[GLFW_KEY_KP_ENTER];
}

}  // namespace

void KeyboardFocus::init() { ImGui::GetIO().KeyMap[ImGuiKey_Tab] = -1; }

void KeyboardFocus::before_new_frame() {
    ImGuiIO& io = ImGui::GetIO();
    if (ui_.keyboard == KeyboardMode::Panels && !io.WantTextInput && enter_pressed())
        io.NavInputs[ImGuiNavInput_Activate] = 1;  // (ImGui 1.86 maps Space to it, Enter only to text input)
}

void KeyboardFocus::begin_frame() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGuiContext& g = *GImGui;
    if (tabbed_) {
        // A tab only moves the focus: ImGui's tabbing would start editing a slider's number it lands on.
        g.NavActivateId = g.NavActivateDownId = g.NavActivatePressedId = g.NavActivateInputId = 0;
        g.NavDisableHighlight = false;
        tabbed_ = false;
    }
    tabbing_ = Tabbing::None;
    if (ui_.keyboard != KeyboardMode::Mouse && (io.MouseClicked[0] || io.MouseClicked[1] || io.MouseClicked[2]))
        leave();
    if (pending_ != Tabbing::None && ui_.keyboard == KeyboardMode::Panels)
        next_window(pending_ == Tabbing::Forward);  // (a window is entered before its Begin)
    pending_ = Tabbing::None;
    if (ImGui::IsKeyPressed(GLFW_KEY_TAB) && !io.WantTextInput && !io.KeyCtrl && !io.KeyAlt) tab(!io.KeyShift);
    note_focus();
}

// Where the focus is, for state().keyboard: its window, and the list whose box it is on (a child window's).
void KeyboardFocus::note_focus() {
    const ImGuiContext& g = *GImGui;
    const bool on_control = ui_.keyboard == KeyboardMode::Panels && g.NavWindow != nullptr;
    ui_.keyboard_window = on_control ? g.NavWindow->Name : "";
    ui_.keyboard_list.clear();
    if (!on_control || g.NavId == 0) return;
    for (const ImGuiWindow* w : g.Windows)
        if ((w->Flags & ImGuiWindowFlags_ChildWindow) && w->ChildId == g.NavId) ui_.keyboard_list = w->Name;
}

void KeyboardFocus::tab(bool forward) {
    ImGuiContext& g = *GImGui;
    if (ui_.keyboard != KeyboardMode::Panels || g.NavWindow == nullptr) {
        // From the drawing (or the mouse's way): the first (last) window.
        const std::vector<ImGuiWindow*> order = tab_order();
        if (order.empty()) return focus_drawing();
        ui_.keyboard = KeyboardMode::Panels;
        ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
        enter(forward ? order.front() : order.back());
        return;
    }
    if (g.NavWindow->Flags & ImGuiWindowFlags_Popup) return;  // (a menu or a list's choices: arrows, Enter, Esc)
    if (g.NavWindow->Flags & ImGuiWindowFlags_ChildWindow) {
        // Out of a list, to the next control after it.
        ImGuiWindow* child = g.NavWindow;
        ImGuiWindow* parent = child->ParentWindow;
        ImGui::FocusWindow(parent);
        ImGui::SetNavID(child->ChildId, ImGuiNavLayer_Main, 0, ImGui::WindowRectAbsToRel(parent, child->Rect()));
    }
    // Through the window's controls (ImGui's tabbing request, over every control and not only text fields); whether
    // it ran past the last one is known once the panels are drawn (end_frame).
    // With no control focused yet in the window (its first one is still being found: two quick Tabs), forward goes to
    // its first control and backward to its last.
    from_start_ = g.NavId == 0;
    g.NavTabbingDir = forward ? (from_start_ ? 0 : 1) : -1;
    ImGui::NavMoveRequestSubmit(ImGuiDir_None, forward ? ImGuiDir_Down : ImGuiDir_Up,
                                ImGuiNavMoveFlags_Tabbing | ImGuiNavMoveFlags_FocusApi,
                                ImGuiScrollFlags_KeepVisibleEdgeX | ImGuiScrollFlags_KeepVisibleEdgeY);
    g.NavTabbingResultFirst.Clear();
    g.NavTabbingCounter = -1;
    g.NavDisableHighlight = false;
    tabbing_ = forward ? Tabbing::Forward : Tabbing::Backward;
    tabbed_ = true;
    tab_window_ = g.NavWindow->RootWindow;
}

void KeyboardFocus::next_window(bool forward) {
    const std::vector<ImGuiWindow*> order = tab_order();
    const auto at = std::find(order.begin(), order.end(), static_cast<const ImGuiWindow*>(tab_window_));
    if (at == order.end()) return focus_drawing();
    if (forward) {
        if (at + 1 == order.end()) return focus_drawing();
        enter(*(at + 1));
    } else {
        if (at == order.begin()) return focus_drawing();
        enter(*(at - 1));
    }
}

void KeyboardFocus::end_frame(const Rect& a) {
    ImGuiContext& g = *GImGui;
    // A tab that found no control after (before) the focused one in its window: on to the next (previous) window.
    const bool found = g.NavMoveResultLocal.ID != 0 || g.NavTabbingResultFirst.ID != 0;
    if (tabbing_ != Tabbing::None && g.NavMoveScoringItems && (g.NavMoveFlags & ImGuiNavMoveFlags_Tabbing) &&
        !(from_start_ && found)) {
        ImGui::NavMoveRequestCancel();  // (ImGui would wrap around to the window's first control)
        pending_ = tabbing_;
    }
    tabbing_ = Tabbing::None;
    if (ui_.keyboard != KeyboardMode::Drawing) return;
    const float inset = kRingWidthPx / 2 + 1;
    ImGui::GetForegroundDrawList()->AddRect(ImVec2(a.x + inset, a.y + inset),
                                            ImVec2(a.x + a.w - inset, a.y + a.h - inset),
                                            ImGui::GetColorU32(ImGuiCol_NavHighlight), 0, 0, kRingWidthPx);
}

void KeyboardFocus::focus_drawing() {
    ImGui::NavMoveRequestCancel();
    ImGui::FocusWindow(nullptr);
    ImGui::GetIO().ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
    ui_.keyboard = KeyboardMode::Drawing;
}

void KeyboardFocus::leave() {
    ImGui::GetIO().ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
    ui_.keyboard = KeyboardMode::Mouse;
}

}  // namespace essi::viewer
