// Compare mode's window and drawing (docs/viewer.md, "Compare two revisions"): the differences listed, each a
// click from its contour, and B's contours drawn over the tape in their own colour.
#include <algorithm>

#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {
namespace {

constexpr ImU32 kSameColor = IM_COL32(80, 220, 255, 70);  // B's contours that are the same: a faint cyan
constexpr ImU32 kBColor = IM_COL32(80, 220, 255, 255);    // B's that differ
constexpr ImU32 kAColor = IM_COL32(255, 70, 90, 200);     // A's that differ (removed, changed, moved from)
constexpr std::size_t kMaxSamePoints = 200000;            // B's same contours drawn up to this many points
constexpr float kInsetPx = 8, kLowInsetPx = 2;            // the window from the drawing area's top right corner

void polyline(ImDrawList* dl, const View& view, Point o, const std::vector<Point>& pts, ImU32 colour, float width) {
    if (pts.size() < 2) return;
    std::vector<ImVec2> px;
    px.reserve(pts.size());
    for (const Point& p : pts) {
        const Point s = view.to_screen({p.x - o.x, p.y - o.y});
        px.emplace_back(static_cast<float>(s.x), static_cast<float>(s.y));
    }
    dl->AddPolyline(px.data(), static_cast<int>(px.size()), colour, ImDrawFlags_None, width);
}

bool overlap(const Box& a, const Box& b) {
    return !a.empty && !b.empty && a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
}

// A contour's points as drawn: the kept ones, or, once the view is so close that their chords would show as facets,
// the contour flattened again within kCompareMaxSagittaPx (only a contour in view: few are, that close).
const std::vector<Point>& drawn_points(const std::vector<Point>& kept, const DiffContour& c, const View& view,
                                       const Box& seen, std::vector<Point>& scratch) {
    if (kCompareChordMm * view.zoom <= kCompareMaxSagittaPx || !overlap(c.box, seen)) return kept;
    flatten_contour(c, kCompareMaxSagittaPx / view.zoom, scratch);
    return scratch;
}

}  // namespace

void Panels::compare_overlay(ImDrawList* dl) {
    const Compare* c = p_.compare.result();
    if (!c) return;
    const View& view = p_.navigation.view();
    const Point o = p_.navigation.origin();
    const Box seen = p_.navigation.visible_box();
    std::vector<Point> scratch;
    std::size_t points = 0;
    for (const ContourDiff& d : c->diff.contours) {
        if (d.change != ContourChange::Same && d.a >= 0) {
            const auto k = static_cast<std::size_t>(d.a);
            polyline(dl, view, o, drawn_points(c->a_lines[k], c->a.contours[k], view, seen, scratch), kAColor, 3.5f);
        }
        if (d.b < 0) continue;
        const auto k = static_cast<std::size_t>(d.b);
        const auto& pts = drawn_points(c->b_lines[k], c->b.contours[k], view, seen, scratch);
        if (d.change == ContourChange::Same && (points += pts.size()) > kMaxSamePoints) continue;
        polyline(dl, view, o, pts, d.change == ContourChange::Same ? kSameColor : kBColor,
                 d.change == ContourChange::Same ? 1.f : 2.f);
    }
}

void Panels::compare_window() {
    const Compare* c = p_.compare.result();
    if (!c) return;
    const Rect& a = p_.navigation.view().area;
    // In a low window it opens as its title bar alone, at the top of the fitted view's margin (the plate's edge
    // stays in sight); a click on its arrow opens it.
    const bool low = ImGui::GetIO().DisplaySize.y < kShortWindowPx;
    const float inset = low ? kLowInsetPx : kInsetPx;
    ImGui::SetNextWindowPos(ImVec2(a.x + a.w - inset, a.y + inset), ImGuiCond_Appearing, ImVec2(1.f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 2 * inset, 420.f), 0), ImGuiCond_Appearing);
    if (low) ImGui::SetNextWindowCollapsed(true, ImGuiCond_Appearing);
    bool open = true;
    ImGui::Begin(tr_id(Msg::UiCompareTitle, "Compare").c_str(), &open,
                 ImGuiWindowFlags_NoSavedSettings | (low ? 0 : ImGuiWindowFlags_NoCollapse));
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    p_.ui.controls.emplace_back("compare_window", Rect{at.x, at.y, size.x, size.y});
    const Document* doc = p_.session.document();
    ImGui::TextWrapped("A: %s  B: %s", doc ? doc->name.c_str() : "-", c->name.c_str());
    ImGui::TextColored(ImVec4(0.31f, 0.86f, 1, 1), "%s", tr(Msg::UiBContours));
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1, 0.27f, 0.35f, 1), "%s", tr(Msg::UiADiffer));
    ImGui::TextWrapped("%s", diff_counts_text(c->diff, ui_lang()).c_str());
    ImGui::Separator();
    const std::size_t rows = c->diff.contours.size() - c->diff.count(ContourChange::Same);
    const float list_h = ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(std::max<std::size_t>(rows, 1) + 1);
    ImGui::BeginChild("differences", ImVec2(0, std::min({list_h, 300.f, a.h / 2})), false,
                      ImGuiWindowFlags_HorizontalScrollbar);
    int row = 0;
    for (const ContourDiff& d : c->diff.contours) {
        if (d.change == ContourChange::Same) continue;
        ImGui::PushID(row++);
        if (ImGui::Selectable(difference_text(c->a, c->b, d, ui_lang()).c_str()))  // (essi diff's words)
            p_.compare.show_difference(d);
        ImGui::PopID();
    }
    if (row == 0) ImGui::TextColored(to_vec4(kOkColor), "%s", tr(Msg::UiSameCut));
    ImGui::EndChild();
    ImGui::End();
    if (!open) p_.compare.end();
}

}  // namespace essi::viewer::panels
