// The compact layout's bottom sheet (app/ScreenLayout.hpp): below the drawing, the whole width, a row of tabs
// (Problems, Statistics, Source, Inspector); a tab opens the sheet on it, the open tab closes it to its tabs.
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {

namespace {

struct TabInfo {
    SheetTab tab;
    Msg label;
    const char* id;  // the ImGui id, and the control's name in state().controls ("tab_" id)
};
constexpr TabInfo kTabs[kSheetTabs] = {{SheetTab::Problems, Msg::UiProblemsTab, "problems"},
                                       {SheetTab::Statistics, Msg::UiStatistics, "statistics"},
                                       {SheetTab::Source, Msg::UiSourcePanel, "source"},
                                       {SheetTab::Inspector, Msg::UiInspectorTab, "inspector"}};
constexpr const char* kTabControls[kSheetTabs] = {"tab_problems", "tab_statistics", "tab_source", "tab_inspector"};

}  // namespace

void Panels::bottom_sheet() {
    const ImGuiIO& io = ImGui::GetIO();
    BottomSheet& sheet = p_.ui.sheet;
    const float h = sheet_height(sheet, io.DisplaySize.y);
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - h));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, h));
    ImGui::Begin("##sheet", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration);
    // The tabs: as wide as the window shares out, tall enough for a finger.
    const ImGuiStyle& st = ImGui::GetStyle();
    const float tab_w = (ImGui::GetContentRegionAvail().x - st.ItemSpacing.x * (kSheetTabs - 1)) / kSheetTabs;
    const float tab_h = kSheetTabsHeight - 2 * st.WindowPadding.y;
    for (int k = 0; k < kSheetTabs; ++k) {
        const TabInfo& t = kTabs[k];
        if (k > 0) ImGui::SameLine();
        const bool active = sheet.open && sheet.tab == t.tab;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, st.Colors[ImGuiCol_ButtonActive]);
        if (ImGui::Button(tr_id(t.label, t.id).c_str(), ImVec2(tab_w, tab_h))) sheet.tap(t.tab);
        if (active) ImGui::PopStyleColor();
        note_control(kTabControls[k]);
    }
    if (sheet.open) {
        ImGui::BeginChild("sheet content", ImVec2(0, 0), false,
                          sheet.tab == SheetTab::Source ? ImGuiWindowFlags_HorizontalScrollbar : 0);
        switch (sheet.tab) {
            case SheetTab::Problems: problems_list(); break;
            case SheetTab::Statistics: statistics_section(); break;
            case SheetTab::Source: source_view(); break;
            case SheetTab::Inspector: inspector_view(); break;
        }
        ImGui::EndChild();
    }
    ImGui::End();
}

}  // namespace essi::viewer::panels
