// The Help window (H, ? or F1): the shortcuts and the colours.
#include "app/Describe.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {

namespace {

// The key (a catalogue row, or a key's name that is the same in every language) and what it does.
struct Shortcut {
    Msg key;
    const char* key_name;  // when key is None
    Msg does;
};
constexpr Shortcut kShortcuts[] = {
    {Msg::UiKeyDrag, nullptr, Msg::UiKeyDragDoes},
    {Msg::UiKeyWheel, nullptr, Msg::UiKeyWheelDoes},
    {Msg::None, "+ / -", Msg::UiKeyPlusMinusDoes},
    {Msg::None, "F", Msg::UiKeyFitDoes},
    {Msg::UiKeyClickSegment, nullptr, Msg::UiKeyClickSegmentDoes},
    {Msg::UiKeyClickLine, nullptr, Msg::UiKeyClickLineDoes},
    {Msg::None, "Esc", Msg::UiKeyEscDoes},
    {Msg::None, "M", Msg::UiKeyMeasureDoes},
    {Msg::UiKeySpace, nullptr, Msg::UiKeySpaceDoes},
    {Msg::UiKeyLeftRight, nullptr, Msg::UiKeyLeftRightDoes},
    {Msg::UiKeyHomeEnd, nullptr, Msg::UiKeyHomeEndDoes},
    {Msg::None, "1 2 3 4", Msg::UiKeyLayersDoes},
    {Msg::None, "[ / ]", Msg::UiKeyPanelsDoes},
    {Msg::UiKeyTouch, nullptr, Msg::UiKeyTouchDoes},
    {Msg::None, "G", Msg::UiKeyGridDoes},
    {Msg::None, "S", Msg::UiKeyShareDoes},
    {Msg::None, "P", Msg::UiKeyProblemsOnlyDoes},
    {Msg::UiKeyProblemSteps, nullptr, Msg::UiKeyProblemStepsDoes},
    {Msg::UiKeyCtrlO, nullptr, Msg::UiKeyCtrlODoes},
    {Msg::UiKeyCtrlV, nullptr, Msg::UiKeyCtrlVDoes},
    {Msg::UiKeyDrop, nullptr, Msg::UiKeyDropDoes},
    {Msg::UiKeyHelp, nullptr, Msg::UiKeyHelpDoes},
    {Msg::UiKeyTab, nullptr, Msg::UiKeyTabDoes},
    {Msg::UiKeyArrowsEnter, nullptr, Msg::UiKeyArrowsEnterDoes},
};

void colours() {
    const Lang lang = ui_lang();
    ImGui::TextUnformatted(tr(Msg::UiColours));
    for (MotionKind k : {MotionKind::Rapid, MotionKind::Travel, MotionKind::Cut, MotionKind::Mark}) {
        ImGui::SameLine();
        ImGui::TextColored(opaque(kind_color(k)), "%s", motion_kind_text(k, lang));
    }
    ImGui::SameLine();
    ImGui::TextColored(opaque(marker_color(MarkerType::Pierce)), "%s", tr(Msg::UiPierce));
    ImGui::SameLine();
    ImGui::TextColored(opaque(marker_color(MarkerType::Start)), "%s", tr(Msg::UiStart));
    ImGui::SameLine();
    ImGui::TextColored(opaque(kSelectionColor), "%s", tr(Msg::UiSelection));
}

}  // namespace

void Panels::help() {
    const Rect& a = p_.navigation.view().area;
    ImGui::SetNextWindowPos(ImVec2(a.x + a.w / 2, a.y + 40), ImGuiCond_Appearing, ImVec2(0.5f, 0));
    ImGui::Begin(tr_id(Msg::UiHelpTitle, "Help").c_str(), &p_.ui.help,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (const auto& r : kShortcuts) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(to_vec4(kMessageColor), "%s", r.key == Msg::None ? r.key_name : tr(r.key));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(tr(r.does));
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    colours();
    ImGui::End();
}

}  // namespace essi::viewer::panels
