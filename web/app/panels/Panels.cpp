#include "app/panels/Panels.hpp"

#include <imgui_internal.h>

namespace essi::viewer::panels {

namespace {

// The tooltip the frame shows, if any (state().tooltip): ImGui's tooltip window begun this frame.
Rect tooltip_rect() {
    for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
        if ((w->Flags & ImGuiWindowFlags_Tooltip) && w->Active && !w->Hidden)
            return Rect{w->Pos.x, w->Pos.y, w->Size.x, w->Size.y};
    return Rect{0, 0, 0, 0};
}

}  // namespace

void Panels::draw() {
    p_.ui.controls.clear();
    p_.ui.group_rects.assign(p_.ui.group_rects.size(), Rect{0, 0, 0, 0});  // (drawn again, or not shown)
    toolbar();
    if (p_.ui.compact) {
        bottom_sheet();
        floating_problem_steps();
    } else {
        tape_panel();
        source_panel();
    }
    overlays();
    messages();
    if (p_.ui.help) help();
    p_.ui.tooltip = tooltip_rect();
}

void Panels::note_control(const char* id) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    p_.ui.controls.emplace_back(id, Rect{a.x, a.y, b.x - a.x, b.y - a.y});
}

}  // namespace essi::viewer::panels
