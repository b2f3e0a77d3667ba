// The panels, one file per group: Toolbar.cpp (the buttons along the top), TapePanel.cpp (left: statistics,
// layers, playback, diagnostics), SourcePanel.cpp (right: the tape's text and the block inspector), ProblemsPanel.cpp
// (the problems list), BottomSheet.cpp (a narrow window's tabs below the drawing instead of the side panels),
// Overlays.cpp (over the drawing: grid labels, the selection's direction, the measure; ProblemMarks.cpp the
// diagnostics' marks, ComparePanel.cpp compare mode), Messages.cpp (loading, drawing, welcome, problem and share
// windows) and Help.cpp. They read and change the parts App gives them.
#pragma once

#include <imgui.h>

#include "app/ViewerParts.hpp"
#include "app/panels/Layout.hpp"

namespace essi::viewer::panels {

class Panels {
public:
    using Parts = ViewerParts;
    explicit Panels(const Parts& parts) : p_(parts) {}

    // A frame's panels (between ImGui::NewFrame and ImGui::Render).
    void draw();

private:
    void toolbar();
    void tape_panel();
    void source_panel();
    // The compact layout's bottom sheet (BottomSheet.cpp): its tabs, and the open tab's content.
    void bottom_sheet();
    // What the panels and the sheet both show: the problems list (ProblemsPanel.cpp) with next and previous
    // problem, the statistics (TapePanel.cpp), the source and the block inspector (SourcePanel.cpp).
    void problems_list();
    void problem_steps();
    void floating_problem_steps();  // the compact layout's, over the drawing's corner
    void statistics_section();
    void source_view();
    void inspector_view();
    // The last item, by name, in state().controls.
    void note_control(const char* id);
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
