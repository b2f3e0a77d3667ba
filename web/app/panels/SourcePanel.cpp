// The right panel: the tape's text (a line a row, its diagnostics marked) and the block inspector of the
// selected line.
#include <algorithm>
#include <string>

#include "app/App.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {

namespace {

constexpr float kInspectorHeight = 220;
constexpr std::size_t kInspectorMotions = 8;  // motions of a line described at most

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
void source_line(App& app, const Document& d, std::uint32_t line, int digits) {
    const LineDiagnostics diags = diagnostics_of(d, line);
    const ImVec2 pos = ImGui::GetCursorScreenPos();
    if (ImGui::Selectable("##line", line == app.selection().line,
                          ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap,
                          ImVec2(0, ImGui::GetTextLineHeight())))
        app.select_line(line);
    if (diags.any() && ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        for (auto k = diags.begin; k != diags.end; ++k)
            ImGui::TextColored(severity_color(k->severity), "%s %u:%u %s", code_name(k->code).c_str(), k->line,
                               k->column, k->message.c_str());
        ImGui::EndTooltip();
    }
    ImGui::SetCursorScreenPos(pos);
    const ImVec4 worst = severity_color(diags.worst);
    if (diags.any()) {
        ImGui::GetWindowDrawList()->AddRectFilled(pos, ImVec2(pos.x + 4, pos.y + ImGui::GetTextLineHeight()),
                                                  ImGui::ColorConvertFloat4ToU32(worst));
    }
    ImGui::TextColored(diags.any() ? worst : to_vec4(kLineNumberColor), " %*u ", digits, line);
    ImGui::SameLine(0, 4);
    const std::string text = printable(d.line(line));
    ImGui::TextUnformatted(text.c_str());
    if (diags.any()) {
        ImGui::SameLine(0, 12);
        ImGui::TextColored(worst, "<- %s", code_name(diags.begin->code).c_str());
    }
}

void source(App& app) {
    const Document* doc = app.document();
    if (!doc) {
        ImGui::TextDisabled("The tape's text appears here.");
        return;
    }
    const Document& d = *doc;
    Selection& sel = app.selection();
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
            source_line(app, d, static_cast<std::uint32_t>(i + 1), digits);
            ImGui::PopID();
        }
    }
}

void inspector(App& app) {
    const Document* doc = app.document();
    const std::uint32_t line = app.selection().line;
    if (!doc || line == 0) {
        ImGui::TextDisabled("Click a segment or a source line to inspect its block.");
        return;
    }
    const Document& d = *doc;
    ImGui::Text("Line %u", line);
    ImGui::SameLine();
    ImGui::TextDisabled("%s", printable(d.line(line), 80).c_str());
    ImGui::Separator();
    const LineBlocks blocks = d.blocks_of_line(line);
    for (std::size_t b = blocks.first; b < blocks.last; ++b)
        ImGui::TextWrapped("%s", describe_block(*blocks.chunk, b, d.profile).c_str());
    const auto [m0, m1] = d.motions_of_line(line);
    for (std::size_t m = m0; m < m1 && m < m0 + kInspectorMotions; ++m) {
        const MotionRecord r = d.record(m);
        ImGui::PushStyleColor(ImGuiCol_Text, opaque(kind_color(r.kind)));
        ImGui::TextWrapped("%s", describe_motion(r).c_str());
        ImGui::PopStyleColor();
    }
    // Where the torch goes (kerf compensation): the second position of the line's motions.
    const std::vector<MotionRecord> torch = d.torch_path_of_line(line);
    for (std::size_t k = 0; k < torch.size() && k < kInspectorMotions; ++k) {
        ImGui::PushStyleColor(ImGuiCol_Text, opaque(kPathColorTable[kKerfPathKind]));
        ImGui::TextWrapped("torch (kerf): %s", describe_motion(torch[k]).c_str());
        ImGui::PopStyleColor();
    }
    if (blocks.empty() && m0 == m1) ImGui::TextDisabled("No block on this line (comment, empty line or part of a block).");
    const LineDiagnostics diags = diagnostics_of(d, line);
    for (auto it = diags.begin; it != diags.end; ++it) {
        ImGui::PushStyleColor(ImGuiCol_Text, severity_color(it->severity));
        ImGui::TextWrapped("%s %s: %s", std::string(severity_name(it->severity)).c_str(), code_name(it->code).c_str(),
                           it->message.c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace

void source_panel(App& app) {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kRightWidth, kToolbarHeight));
    ImGui::SetNextWindowSize(ImVec2(kRightWidth, io.DisplaySize.y - kToolbarHeight));
    ImGui::Begin("Source", nullptr, kPanelFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::BeginChild("source", ImVec2(0, -kInspectorHeight), true, ImGuiWindowFlags_HorizontalScrollbar);
    source(app);
    ImGui::EndChild();
    ImGui::BeginChild("inspector", ImVec2(0, 0), true);
    inspector(app);
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace essi::viewer::panels
