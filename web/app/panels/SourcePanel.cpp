// The right panel: the tape's text (a line a row, its diagnostics marked) and the block inspector of the
// selected line.
#include <algorithm>
#include <string>

#include "app/Describe.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/text_report.hpp"

namespace essi::viewer::panels {

namespace {

constexpr float kInspectorHeight = 220;

// The diagnostics of one line: [begin, end) of the sorted list.
struct LineDiagnostics {
    std::vector<Diagnostic>::const_iterator begin, end;
    Severity worst = Severity::Note;
    [[nodiscard]] bool any() const { return begin != end; }
};

LineDiagnostics diagnostics_of(const Document& d, std::uint32_t line) {
    LineDiagnostics r;
    r.begin = std::lower_bound(d.diagnostics.begin(), d.diagnostics.end(), line,
                               [](const Diagnostic& x, std::uint32_t l) { return x.line < l; });
    r.end = r.begin;
    while (r.end != d.diagnostics.end() && r.end->line == line) {
        r.worst = std::max(r.worst, r.end->severity);
        ++r.end;
    }
    return r;
}

// One row of the source: a selectable line, its number, its text and its first diagnostic's code.
void source_line(const Panels::Parts& p, const Document& d, std::uint32_t line, int digits) {
    Navigation& navigation = p.navigation;
    const LineDiagnostics diags = diagnostics_of(d, line);
    const ImVec2 pos = ImGui::GetCursorScreenPos();
    if (ImGui::Selectable("##line", line == navigation.selection().line,
                          ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap,
                          ImVec2(0, ImGui::GetTextLineHeight())))
        navigation.select_line(line);
    if (ImGui::BeginPopupContextItem("line menu")) {
        if (ImGui::Selectable(tr(Msg::UiCopyThisLine))) p.exports.copy(Exports::CopyWhat::Line, line);
        if (ImGui::Selectable(tr(Msg::UiCopyInspector))) {
            navigation.select_line(line, false);
            p.exports.copy(Exports::CopyWhat::Inspector);
        }
        ImGui::EndPopup();
    }
    if (diags.any() && ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(tooltip_wrap_x());  // (inside a narrow screen)
        for (auto k = diags.begin; k != diags.end; ++k) {
            ImGui::PushStyleColor(ImGuiCol_Text, severity_color(k->severity));
            ImGui::TextWrapped("%s %u:%u %s", code_name(k->code).c_str(), k->line, k->column,
                               diagnostic_message(*k, ui_lang()).c_str());
            ImGui::PopStyleColor();
        }
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    ImGui::SetCursorScreenPos(pos);
    const ImVec4 worst = severity_color(diags.worst);
    if (diags.any()) {
        ImGui::GetWindowDrawList()->AddRectFilled(pos, ImVec2(pos.x + 4, pos.y + ImGui::GetTextLineHeight()),
                                                  ImGui::ColorConvertFloat4ToU32(worst));
    }
    // (right-aligned with figure spaces, U+2007: a digit's width in the panels' proportional font)
    std::string number = std::to_string(line);
    for (int k = static_cast<int>(number.size()); k < digits; ++k) number.insert(0, "\xE2\x80\x87");
    ImGui::TextColored(diags.any() ? worst : to_vec4(kLineNumberColor), " %s ", number.c_str());
    ImGui::SameLine(0, 4);
    const std::string text = p.comments.line_text(d, line);
    ImGui::TextUnformatted(text.c_str());
    if (diags.any()) {
        ImGui::SameLine(0, 12);
        ImGui::TextColored(worst, "<- %s", code_name(diags.begin->code).c_str());
    }
}

void source(const Panels::Parts& p) {
    const Document* doc = p.session.document();
    if (!doc) {
        ImGui::TextDisabled("%s", tr(Msg::UiSourceEmpty));
        return;
    }
    const Document& d = *doc;
    Selection& sel = p.navigation.selection();
    const float lh = ImGui::GetTextLineHeightWithSpacing();
    if (sel.scroll_source && sel.line > 0) {
        const float target = (static_cast<float>(sel.line) - 1) * lh;
        const float top = ImGui::GetScrollY(), h = ImGui::GetWindowHeight();
        if (target < top || target > top + h - 2 * lh) ImGui::SetScrollY(std::max(0.f, target - h / 3));
        sel.scroll_source = false;
    }
    const int digits = static_cast<int>(std::to_string(d.line_count()).size());
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(d.line_count()), lh);
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            ImGui::PushID(i);
            source_line(p, d, static_cast<std::uint32_t>(i + 1), digits);
            ImGui::PopID();
        }
    }
}

void inspector(const Panels::Parts& p) {
    const Document* doc = p.session.document();
    const std::uint32_t line = p.navigation.selection().line;
    if (!doc || line == 0) {
        hint_wrapped(tr(Msg::UiInspectorEmpty));
        return;
    }
    const Document& d = *doc;
    ImGui::TextUnformatted(tr(Msg::UiLineN, {line}).c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton(tr_id(Msg::UiCopy, "copy").c_str())) p.exports.copy(Exports::CopyWhat::Inspector);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiCopyInspectorTip));
    ImGui::SameLine();
    ImGui::TextDisabled("%s", p.comments.line_text(d, line, 80).c_str());
    ImGui::Separator();
    // The blocks, the motions in their kind's colour, and where the torch goes (kerf compensation: the second
    // position of the line's motions).
    const std::vector<InspectorLine> lines = inspector_lines(d, line, ui_lang());
    for (const InspectorLine& l : lines) {
        using Of = InspectorLine::Of;
        if (l.of != Of::Block)
            ImGui::PushStyleColor(ImGuiCol_Text,
                                  opaque(l.of == Of::Torch ? kPathColorTable[kKerfPathKind] : kind_color(l.kind)));
        ImGui::TextWrapped("%s", l.text.c_str());
        if (l.of != Of::Block) ImGui::PopStyleColor();
    }
    if (lines.empty()) hint_wrapped(tr(Msg::UiNoBlockOnLine));
    const LineDiagnostics diags = diagnostics_of(d, line);
    for (auto it = diags.begin; it != diags.end; ++it) {
        ImGui::PushStyleColor(ImGuiCol_Text, severity_color(it->severity));
        ImGui::TextWrapped("%s %s: %s", std::string(essi::severity_text(it->severity, ui_lang())).c_str(),
                           code_name(it->code).c_str(), diagnostic_message(*it, ui_lang()).c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace

void Panels::source_panel() {
    if (!begin_side_panel(p_.ui.layout, p_.ui.layout_changed, tr_id(Msg::UiSourcePanel, "Source").c_str(), false))
        return;
    // (the inspector a third of a short window at most: the source keeps its lines)
    const float inspector_h = std::min(kInspectorHeight, ImGui::GetWindowHeight() / 3);
    ImGui::BeginChild("source", ImVec2(0, -inspector_h), true, ImGuiWindowFlags_HorizontalScrollbar);
    source(p_);
    ImGui::EndChild();
    ImGui::BeginChild("inspector", ImVec2(0, 0), true);
    inspector(p_);
    ImGui::EndChild();
    ImGui::End();
}

void Panels::source_view() { source(p_); }
void Panels::inspector_view() { inspector(p_); }

}  // namespace essi::viewer::panels
