// The Help window (H, ? or F1): the shortcuts and the colours.
#include "app/App.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {

namespace {

constexpr const char* kShortcuts[][2] = {
    {"drag (left, right or middle)", "pan"},
    {"mouse wheel", "zoom at the cursor"},
    {"+ / -", "zoom in / out at the centre"},
    {"F", "fit the whole tape"},
    {"click a segment", "select it and show its source line"},
    {"click a source line / diagnostic", "select its block and segment"},
    {"Esc", "clear the selection / leave measure / close help"},
    {"M", "measure: click two points (snaps to end points and arc centres)"},
    {"Space", "play / pause the playback"},
    {"Left / Right", "step the playback one motion"},
    {"Home / End", "playback from the start / show everything"},
    {"1 2 3 4", "toggle cut, travel+rapid, mark, pierces"},
    {"[ / ]", "hide or show the left / right panel (drag a panel's inner edge to resize it)"},
    {"touch", "tap: click; one finger: pan; two fingers: zoom"},
    {"G", "toggle the grid"},
    {"S", "share link (tape and view in the URL)"},
    {"Ctrl+O", "open a tape"},
    {"Ctrl+V", "paste a tape's text"},
    {"drop a file", "load it"},
    {"H, ? or F1", "this help"},
};

void colours() {
    ImGui::TextUnformatted("Colours:");
    for (MotionKind k : {MotionKind::Rapid, MotionKind::Travel, MotionKind::Cut, MotionKind::Mark}) {
        ImGui::SameLine();
        ImGui::TextColored(opaque(kind_color(k)), "%s", motion_kind_name(k));
    }
    ImGui::SameLine();
    ImGui::TextColored(opaque(marker_color(MarkerType::Pierce)), "pierce");
    ImGui::SameLine();
    ImGui::TextColored(opaque(marker_color(MarkerType::Start)), "start");
    ImGui::SameLine();
    ImGui::TextColored(opaque(kSelectionColor), "selection");
}

}  // namespace

void help(App& app) {
    const Rect& a = app.view().area;
    ImGui::SetNextWindowPos(ImVec2(a.x + a.w / 2, a.y + 40), ImGuiCond_Appearing, ImVec2(0.5f, 0));
    ImGui::Begin("Help: shortcuts", &app.ui().help, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (const auto& r : kShortcuts) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(to_vec4(kMessageColor), "%s", r[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r[1]);
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    colours();
    ImGui::End();
}

}  // namespace essi::viewer::panels
