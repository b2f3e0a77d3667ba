// The problems list (ProblemList): next and previous problem, Copy the report, a row per diagnostic, and one row per
// code with many findings that opens to list them (the kept ones and the core's summary of those left out). In the
// left panel's Diagnostics section and in the bottom sheet's Problems tab.
#include <algorithm>

#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {

namespace {

// The list made again when the document's diagnostics change (the cut plan's findings join them later).
void keep_current(UiState& ui, const Document& doc, const LoadController& load) {
    const UiState::ProblemsOf now{&doc, load.load_frames().handed, doc.diagnostics.size()};
    if (ui.problems_of == now) return;
    ui.problems.build(doc.diagnostics);
    ui.problems_of = now;
    ui.open_groups.assign(ui.problems.groups().size(), false);
}

void diagnostic_row(const Document& doc, std::size_t i, Navigation& navigation, Exports& exports) {
    const Diagnostic& d = doc.diagnostics[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(d.severity));
    const std::string label = tr(Msg::UiDiagLabel, {code_name(d.code), d.line, d.column});
    if (ImGui::Selectable(label.c_str(), d.line != 0 && d.line == navigation.selection().line))
        navigation.select_diagnostic(i);
    ImGui::PopStyleColor();
    if (ImGui::BeginPopupContextItem("diagnostic menu")) {
        if (ImGui::Selectable(tr(Msg::UiCopyThisProblem)))
            exports.copy(Exports::CopyWhat::Diagnostic, static_cast<std::uint32_t>(i));
        if (ImGui::Selectable(tr(Msg::UiCopyReport))) exports.copy(Exports::CopyWhat::Report);
        ImGui::EndPopup();
    }
    const std::string message = diagnostic_message(d, ui_lang());
    if (ImGui::IsItemHovered()) wrapped_tooltip(message + "\n" + std::string(code_summary(d.code, ui_lang())));
    ImGui::SameLine();
    ImGui::TextWrapped("%s", message.c_str());
    ImGui::PopID();
}

// A code's findings in one row: "E602: 58 780 findings" and what the rule checks; a click opens it.
void group_row(UiState& ui, const Document& doc, std::size_t g) {
    const ProblemGroup& group = ui.problems.groups()[g];
    ImGui::PushID("group");
    ImGui::PushID(static_cast<int>(g));
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(group.severity));
    const std::string label = tr(Msg::UiProblemGroup, {code_name(group.code), count_text(group.total),
                                                       static_cast<unsigned long long>(group.total)});
    ImGui::SetNextItemOpen(ui.open_groups[g]);
    ui.open_groups[g] = ImGui::TreeNodeEx("group", ImGuiTreeNodeFlags_NoTreePushOnOpen, "%s", label.c_str());
    ImGui::PopStyleColor();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    ui.group_rects[g] = Rect{a.x, a.y, b.x - a.x, b.y - a.y};
    if (ImGui::IsItemHovered())
        wrapped_tooltip(tr(Msg::UiProblemGroupTip, {static_cast<unsigned long long>(doc.profile.max_per_code)}));
    ImGui::SameLine();
    ImGui::TextWrapped("%s", std::string(code_summary(group.code, ui_lang())).c_str());
    ImGui::PopID();
    ImGui::PopID();
}

}  // namespace

void Panels::problem_steps() {
    if (ImGui::SmallButton(tr_id(Msg::UiPrevProblem, "previous problem").c_str())) p_.navigation.step_problem(-1);
    note_control("previous_problem");
    if (ImGui::IsItemHovered()) wrapped_tooltip(tr(Msg::UiPrevProblemTip));
    ImGui::SameLine();
    if (ImGui::SmallButton(tr_id(Msg::UiNextProblem, "next problem").c_str())) p_.navigation.step_problem(1);
    note_control("next_problem");
    if (ImGui::IsItemHovered()) wrapped_tooltip(tr(Msg::UiNextProblemTip));
}

void Panels::floating_problem_steps() {
    const Document* doc = p_.session.document();
    if (!doc || doc->diagnostics.empty() || p_.load.loading()) return;
    const Rect& a = p_.navigation.view().area;
    constexpr float kMarginPx = 8;
    ImGui::SetNextWindowPos(ImVec2(a.x + a.w - kMarginPx, a.y + a.h - kMarginPx), ImGuiCond_Always, ImVec2(1, 1));
    ImGui::Begin("##problem steps", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing);
    const float side = ImGui::GetFrameHeight() * 1.6f;  // (a finger's size)
    if (ImGui::Button("<###previous problem", ImVec2(side, side))) p_.navigation.step_problem(-1);
    note_control("previous_problem");
    if (ImGui::IsItemHovered()) wrapped_tooltip(tr(Msg::UiPrevProblemTip));
    ImGui::SameLine();
    if (ImGui::Button(">###next problem", ImVec2(side, side))) p_.navigation.step_problem(1);
    note_control("next_problem");
    if (ImGui::IsItemHovered()) wrapped_tooltip(tr(Msg::UiNextProblemTip));
    ImGui::End();
}

void Panels::problems_list() {
    const Document* doc = p_.session.document();
    if (!doc) {
        ImGui::TextDisabled("-");
        return;
    }
    if (doc->diagnostics.empty()) {
        ImGui::TextColored(to_vec4(kOkColor), "%s", tr(Msg::UiNoProblems));
        return;
    }
    UiState& ui = p_.ui;
    keep_current(ui, *doc, p_.load);
    if (!ui.compact) {  // (the compact layout has them over the drawing: floating_problem_steps)
        problem_steps();
        same_line_if_fits(ImGui::CalcTextSize(tr(Msg::UiCopyReport)).x + ImGui::GetStyle().FramePadding.x * 2);
    }
    if (ImGui::SmallButton(tr_id(Msg::UiCopyReport, "copy report").c_str())) p_.exports.copy(Exports::CopyWhat::Report);
    if (ImGui::IsItemHovered()) wrapped_tooltip(tr(Msg::UiCopyReportTip));
    ui.group_rects.assign(ui.problems.groups().size(), Rect{0, 0, 0, 0});
    const std::vector<ProblemRow> rows = ui.problems.rows(ui.open_groups);
    // No horizontal scrolling: the rows' texts wrap at the list's visible width (beside its scroll bar). With it the
    // widest row widened the region they wrap in, and the texts ran on under the scroll bar.
    ImGui::BeginChild("diaglist", ImVec2(0, 0), false);
    float right = 0;  // where the rows' texts end (state().controls.problems_rows)
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(rows.size()));
    while (clipper.Step()) {
        for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k) {
            const ProblemRow& r = rows[static_cast<std::size_t>(k)];
            const bool member = r.kind == ProblemRow::Kind::Member;
            if (member) ImGui::Indent();
            if (r.kind == ProblemRow::Kind::Group) group_row(ui, *doc, r.index);
            else diagnostic_row(*doc, r.index, p_.navigation, p_.exports);
            if (member) ImGui::Unindent();
            right = std::max(right, ImGui::GetItemRectMax().x);
        }
    }
    const ImVec2 at = ImGui::GetWindowPos();
    const float visible_right = at.x + ImGui::GetWindowContentRegionMax().x;
    ui.controls.emplace_back("problems_list", Rect{at.x, at.y, visible_right - at.x, ImGui::GetWindowHeight()});
    ui.controls.emplace_back("problems_rows", Rect{at.x, at.y, right - at.x, ImGui::GetWindowHeight()});
    ImGui::EndChild();
}

}  // namespace essi::viewer::panels
