// Over the drawing, for the diagnostics' marks (the marks themselves are the renderer's markers): the mark under the
// mouse (UiState::hovered_mark) with its tooltip (the message in the viewer's language, the related places), a ring
// around the hovered mark and the selected line's, and a collision's overlapping area filled row by row (the area
// inside every polygon of Diagnostic::overlap, essi::overlap_spans).
#include <algorithm>
#include <cmath>

#include "app/Problems.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/diagnostic_marks.hpp"

namespace essi::viewer::panels {

namespace {

constexpr float kRingGapPx = 3;  // the ring around an active mark, outside the mark
constexpr float kRingWidthPx = 2;
constexpr float kOverlapAlpha = 0.45f;          // the overlapping area's fill
constexpr float kOverlapRowPx = 1;              // its rows (window pixels)
constexpr std::size_t kTooltipDiagnostics = 4;  // diagnostics listed in one tooltip (more marks at one spot)
constexpr std::size_t kTooltipRelated = 6;      // related places listed for one diagnostic

ImU32 color_u32(Rgba c, float alpha) {
    c.a = alpha;
    return to_u32(c);
}

// The area inside every polygon of one diagnostic's overlap, in the drawing area: its rows' spans as rectangles.
void overlap_area(ImDrawList* dl, const Document& doc, const View& view, const Diagnostic& d) {
    std::vector<std::vector<Point>> screen(d.overlap().size());
    double top = HUGE_VAL, bottom = -HUGE_VAL, left = HUGE_VAL, right = -HUGE_VAL;
    for (std::size_t k = 0; k < d.overlap().size(); ++k)
        for (const Point& p : d.overlap()[k]) {
            const Point q = view.to_screen({p.x - doc.origin.x, p.y - doc.origin.y});
            screen[k].push_back(q);
            top = std::min(top, q.y);
            bottom = std::max(bottom, q.y);
            left = std::min(left, q.x);
            right = std::max(right, q.x);
        }
    const Rect& a = view.area;
    if (right < a.x || left > a.x + a.w) return;  // (out of view)
    top = std::max(top, static_cast<double>(a.y));
    bottom = std::min(bottom, static_cast<double>(a.y + a.h));
    const ImU32 fill = color_u32(severity_rgba(d.severity), kOverlapAlpha);
    for (double y = std::floor(top); y < bottom; y += kOverlapRowPx)
        for (const auto& [x0, x1] : overlap_spans(screen, y + kOverlapRowPx / 2))
            dl->AddRectFilled(ImVec2(static_cast<float>(x0), static_cast<float>(y)),
                              ImVec2(static_cast<float>(x1), static_cast<float>(y + kOverlapRowPx)), fill);
}

void ring(ImDrawList* dl, const Document& doc, const View& view, const DiagnosticMark& m, ImU32 color) {
    const Point p = mark_screen(doc, view, m);
    dl->AddCircle(ImVec2(static_cast<float>(p.x), static_cast<float>(p.y)), Renderer::kMarkRadiusPx + kRingGapPx, color,
                  24, kRingWidthPx);
}

// One diagnostic in the tooltip: its code and line in its colour, its message, its related places.
void tooltip_diagnostic(UiFonts& fonts, const Diagnostic& d) {
    const Lang lang = ui_lang();
    ImGui::TextColored(severity_color(d.severity), "%s  %s", code_name(d.code).c_str(),
                       tr(Msg::UiMarkAt, {d.line}).c_str());
    const std::string message = diagnostic_message(d, lang);
    fonts.require_glyphs(message);
    ImGui::TextUnformatted(message.c_str());
    for (std::size_t k = 0; k < d.related().size() && k < kTooltipRelated; ++k) {
        const RelatedLocation& r = d.related()[k];
        const std::string what = related_message(r, lang);
        const std::string text = r.end_line > r.line ? tr(Msg::UiMarkRelatedLines, {r.line, r.end_line, what})
                                                     : tr(Msg::UiMarkRelatedLine, {r.line, what});
        fonts.require_glyphs(text);
        ImGui::BulletText("%s", text.c_str());
    }
}

void tooltip(UiFonts& fonts, const Document& doc, const std::vector<std::size_t>& near) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(tooltip_wrap_x());
    for (std::size_t k = 0; k < near.size() && k < kTooltipDiagnostics; ++k) {
        if (k > 0) ImGui::Separator();
        tooltip_diagnostic(fonts, doc.diagnostics[doc.marks[near[k]].diagnostic]);
    }
    if (near.size() > kTooltipDiagnostics)
        ImGui::TextDisabled("%s", tr(Msg::UiMarkMore, {near.size() - kTooltipDiagnostics}).c_str());
    ImGui::TextDisabled("%s", tr(Msg::UiMarkClick));
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

}  // namespace

void Panels::problem_marks(ImDrawList* dl) {
    UiState& ui = p_.ui;
    ui.hovered_mark = kNoMark;
    const Document* doc = p_.session.document();
    if (!doc || doc->diagnostics.empty() || p_.load.loading()) return;
    const View& view = p_.navigation.view();
    for (const Diagnostic& d : doc->diagnostics)
        if (d.overlap().size() > 0) overlap_area(dl, *doc, view, d);
    const std::uint32_t line = p_.navigation.selection().line;
    for (const DiagnosticMark& m : doc->marks)
        if (line > 0 && doc->diagnostics[m.diagnostic].line == line) ring(dl, *doc, view, m, to_u32(kSelectionColor));
    const ImGuiIO& io = ImGui::GetIO();
    const bool over = view.area.contains(io.MousePos.x, io.MousePos.y) && !io.WantCaptureMouse;
    if (!over || p_.measure.active || ImGui::IsMouseDown(0)) return;
    const std::vector<std::size_t> near = marks_near(*doc, view, io.MousePos.x, io.MousePos.y);
    if (near.empty()) return;
    ui.hovered_mark = near.front();
    ring(dl, *doc, view, doc->marks[near.front()], IM_COL32(255, 255, 255, 230));
    tooltip(p_.fonts, *doc, near);
}

}  // namespace essi::viewer::panels
