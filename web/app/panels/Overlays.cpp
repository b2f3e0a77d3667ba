// Drawn over the drawing area every frame: the grid's labels and scale bar, the table and plate, the parts layer
// (group numbers, plates, remnants), the diagnostics' marks' hover and overlapping areas (ProblemMarks.cpp), the
// direction of the selected motions, and the measure (its points, its line and its window).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

#include "app/Input.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/geom.hpp"
#include "essi/placement.hpp"

namespace essi::viewer::panels {

namespace {

constexpr ImU32 kTableColor = IM_COL32(120, 200, 255, 200);  // the machine's table (its travel limits)
constexpr ImU32 kPlateColor = IM_COL32(200, 200, 200, 110);  // the plate: the box of what is cut
constexpr ImU32 kMeasureColor = IM_COL32(255, 255, 0, 255);
// The parts layer: the plates and their remnants in essi render --remnant's colour (kSvgRemnantColor, #9467bd),
// the remnant filled faintly; the group numbers.
constexpr ImU32 kRemnantColor = IM_COL32(0x94, 0x67, 0xbd, 230);
constexpr ImU32 kRemnantFill = IM_COL32(0x94, 0x67, 0xbd, 48);
constexpr ImU32 kPartLabelColor = IM_COL32(255, 255, 255, 220);
// A part's group number is written when its box is at least this wide on the screen (pixels), for at most this many
// parts a frame (the first in the cutting order that are in view).
constexpr float kPartLabelMinPx = 18;
constexpr std::size_t kMaxPartLabels = 2000;
constexpr std::size_t kMaxArrows = 64;  // direction arrows drawn on a selected line at most
constexpr float kArrowPx = 9;
constexpr double kArrowAt = 0.5, kArrowAhead = 0.01;  // the arrow's place along the motion, its direction's look-ahead
// A label this close to 0 (a share of the step) is 0: no "-0" from rounding.
constexpr double kZeroLabelShare = 1e-6;
// A motion whose middle moves less than this (pixels) kArrowAhead further along gets no arrow (no direction).
constexpr double kMinArrowPx = 1e-9;

ImVec2 to_im(Point p) { return ImVec2(static_cast<float>(p.x), static_cast<float>(p.y)); }

// Labels on the major grid lines along the bottom and left edges, in the shown coordinates (the grid lies along
// their axes: the screen shows them turned by quarter turns only), and a scale bar of one major step.
void grid_labels(ImDrawList* dl, const View& view, const Coordinates& cs, Point o, const Theme& theme) {
    const ImU32 kLabelColor = to_u32(theme.label), kScaleBarColor = to_u32(theme.scale_bar);
    const Rect& a = view.area;
    const double step = grid_step(view.zoom) * 10;
    const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step)));
    const auto label = [&](double v) { return fmt("%.*f", decimals, std::fabs(v) < step * kZeroLabelShare ? 0.0 : v); };
    const auto shown = [&](double sx, double sy) {
        const Point w = view.to_world(sx, sy);
        return cs.shown({w.x + o.x, w.y + o.y});
    };
    const Point c0 = shown(a.x, a.y + a.h), c1 = shown(a.x + a.w, a.y);  // (opposite corners)
    const double lo[2] = {std::min(c0.x, c1.x), std::min(c0.y, c1.y)};
    const double hi[2] = {std::max(c0.x, c1.x), std::max(c0.y, c1.y)};
    // The shown axis along the screen's x (the bottom labels) and the one along its y (the left labels): x and y,
    // or y and x when the view is turned a quarter (View::turns).
    const bool x_across = turned({1, 0}, view.turns).x != 0;
    const auto at = [&](int axis, double v) {  // a point on the grid line `axis` = v
        const Point p = cs.program(axis == 0 ? Point{v, lo[1]} : Point{lo[0], v});
        return view.to_screen({p.x - o.x, p.y - o.y});
    };
    const int across = x_across ? 0 : 1, up = 1 - across;
    for (double g = std::ceil(lo[across] / step) * step; g <= hi[across]; g += step) {
        const Point s = at(across, g);
        dl->AddText(ImVec2(static_cast<float>(s.x) + 3, a.y + a.h - 18), kLabelColor, label(g).c_str());
    }
    for (double g = std::ceil(lo[up] / step) * step; g <= hi[up]; g += step) {
        const Point s = at(up, g);
        dl->AddText(ImVec2(a.x + 4, static_cast<float>(s.y) - 16), kLabelColor, label(g).c_str());
    }
    const float bar = static_cast<float>(step * view.zoom);
    const ImVec2 p(a.x + a.w - bar - 20, a.y + a.h - 30);
    dl->AddLine(p, ImVec2(p.x + bar, p.y), kScaleBarColor, 2);
    dl->AddLine(p, ImVec2(p.x, p.y - 5), kScaleBarColor, 2);
    dl->AddLine(ImVec2(p.x + bar, p.y), ImVec2(p.x + bar, p.y - 5), kScaleBarColor, 2);
    dl->AddText(ImVec2(p.x + bar / 2 - 20, p.y - 20), kScaleBarColor,
                (step >= 1000 ? fmt("%g m", step / 1000) : fmt("%g mm", step)).c_str());
}

// An arrow at the middle of each selected motion, pointing the way it runs.
void selection_arrows(ImDrawList* dl, const Document& doc, const Selection& sel, const View& view) {
    const Point o = doc.origin;
    auto [m0, m1] = doc.motions_of_line(sel.line);
    if (sel.motion != Selection::npos && (sel.motion < m0 || sel.motion >= m1)) {
        m0 = sel.motion;
        m1 = sel.motion + 1;
    }
    for (std::size_t m = m0; m < m1 && m < m0 + kMaxArrows; ++m) {
        const MotionRecord r = doc.record(m);
        const Point p = point_at(r, kArrowAt), q = point_at(r, std::min(1.0, kArrowAt + kArrowAhead));
        const Point ps = view.to_screen({p.x - o.x, p.y - o.y});
        const Point qs = view.to_screen({q.x - o.x, q.y - o.y});
        double dx = qs.x - ps.x, dy = qs.y - ps.y;
        const double len = std::hypot(dx, dy);
        if (len < kMinArrowPx) continue;
        dx /= len;
        dy /= len;
        const double s = kArrowPx;
        const ImVec2 tip(static_cast<float>(ps.x + dx * s), static_cast<float>(ps.y + dy * s));
        const ImVec2 l(static_cast<float>(ps.x - dx * s - dy * s * 0.7),
                       static_cast<float>(ps.y - dy * s + dx * s * 0.7));
        const ImVec2 rr(static_cast<float>(ps.x - dx * s + dy * s * 0.7),
                        static_cast<float>(ps.y - dy * s - dx * s * 0.7));
        dl->AddTriangleFilled(tip, l, rr, to_u32(kSelectionColor));
    }
}

// Where the Measure window goes: the corner of the drawing area farthest from the points it must not cover (the
// mouse, A, B), the top left when that is as far as any other; its position and pivot.
std::pair<ImVec2, ImVec2> measure_corner(const Rect& a, std::initializer_list<ImVec2> keep_clear) {
    constexpr float kInset = 10;
    const ImVec2 pivots[] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};  // top left, top right, bottom left, bottom right
    std::pair<ImVec2, ImVec2> best;
    float best_clearance = -1;
    for (const ImVec2& pivot : pivots) {
        const ImVec2 at(pivot.x == 0 ? a.x + kInset : a.x + a.w - kInset,
                        pivot.y == 0 ? a.y + kInset : a.y + a.h - kInset);
        float clearance = std::numeric_limits<float>::max();
        for (const ImVec2& p : keep_clear) clearance = std::min(clearance, std::hypot(p.x - at.x, p.y - at.y));
        if (clearance > best_clearance + 1) {
            best_clearance = clearance;
            best = {at, pivot};
        }
    }
    return best;
}

// The measure's numbers in the shown coordinates (a and b: program mm), in the corner `corner` (measure_corner);
// where it was drawn goes to `drawn`.
void measure_window(const Measure& m, Point b, const Coordinates& cs, std::pair<ImVec2, ImVec2> corner, Rect& drawn) {
    ImGui::SetNextWindowPos(corner.first, ImGuiCond_Always, corner.second);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin(tr_id(Msg::UiMeasureTitle, "Measure").c_str(), nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    if (m.points == 0) {
        ImGui::TextUnformatted(tr(Msg::UiMeasureFirst));
    } else {
        const Point sa = cs.shown(m.a), sb = cs.shown(b);
        const double dx = sb.x - sa.x, dy = sb.y - sa.y;
        ImGui::Text("A (%.3f, %.3f)", sa.x, sa.y);
        ImGui::Text("B (%.3f, %.3f)%s%s", sb.x, sb.y, m.points == 2 ? "" : "  ",
                    m.points == 2 ? "" : tr(Msg::UiMeasureClickToFix));
        ImGui::TextUnformatted(tr(Msg::UiDistance, {fmt("%.3f", std::hypot(dx, dy))}).c_str());
        ImGui::Text("dx %.3f mm   dy %.3f mm (%s)", dx, dy,
                    tr(cs.machine() ? Msg::UiMachineCoordinates : Msg::UiProgramCoordinates));
    }
    ImGui::TextDisabled("%s", tr(Msg::UiMeasureLeave));
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    drawn = Rect{at.x, at.y, size.x, size.y};
    ImGui::End();
}

// The snapped point under the mouse, the line from A to B (or to the mouse), and the numbers.
void measure(ImDrawList* dl, const Document* doc, const Measure& m, const View& view, const Coordinates& cs, Point o,
             Rect& window) {
    const ImGuiIO& io = ImGui::GetIO();
    bool snapped = false;
    const Point hover = snap(doc, view, io.MousePos.x, io.MousePos.y, &snapped);
    const ImVec2 hs = to_im(view.to_screen({hover.x - o.x, hover.y - o.y}));
    if (snapped) dl->AddCircle(hs, 7, kMeasureColor, 16, 2);
    const Point b = m.points == 2 ? m.b : hover;
    const ImVec2 as = to_im(view.to_screen({m.a.x - o.x, m.a.y - o.y}));
    const ImVec2 bs = to_im(view.to_screen({b.x - o.x, b.y - o.y}));
    if (m.points >= 1) {
        dl->AddLine(as, bs, kMeasureColor, 1.5f);
        dl->AddCircleFilled(as, 3.5f, kMeasureColor);
        dl->AddCircleFilled(bs, 3.5f, kMeasureColor);
    }
    const ImVec2 mouse = io.MousePos;
    const auto corner = m.points == 0 ? measure_corner(view.area, {mouse}) : measure_corner(view.area, {mouse, as, bs});
    measure_window(m, b, cs, corner, window);
}

// The machine's table (the profile's `table`, docs/semantics.md §12) where it lies under the program: turned and
// moved back through the placement; and the plate on it, the box of what is cut. Only with a table.
void table_and_plate(ImDrawList* dl, const Document& doc, const View& view, Point o) {
    if (!doc.profile.table) return;
    const auto screen = [&](Point p) { return to_im(view.to_screen({p.x - o.x, p.y - o.y})); };
    const auto corners = Placement(doc.profile).table_in_program(*doc.profile.table);
    ImVec2 pts[4];
    for (int k = 0; k < 4; ++k) pts[k] = screen(corners[k]);
    dl->AddPolyline(pts, 4, kTableColor, ImDrawFlags_Closed, 2.f);
    dl->AddText(ImVec2(pts[3].x + 4, pts[3].y + 2), kTableColor, tr(Msg::UiLayerTable));
    const Box& b = doc.stats.cut_bbox;
    if (b.empty) return;
    const ImVec2 plate[4] = {screen({b.min_x, b.min_y}), screen({b.max_x, b.min_y}), screen({b.max_x, b.max_y}),
                             screen({b.min_x, b.max_y})};
    dl->AddPolyline(plate, 4, kPlateColor, ImDrawFlags_Closed, 1.f);
}

// The parts layer: each plate's area and its remnant (with its size), each part's group number at its label point.
void parts_layer(ImDrawList* dl, const PartsList& parts, const View& view, Point o) {
    const auto screen = [&](Point p) { return to_im(view.to_screen({p.x - o.x, p.y - o.y})); };
    const auto corners = [&](const Box& b, ImVec2* out) {
        out[0] = screen({b.min_x, b.min_y});
        out[1] = screen({b.max_x, b.min_y});
        out[2] = screen({b.max_x, b.max_y});
        out[3] = screen({b.min_x, b.max_y});
    };
    ImVec2 pts[4];
    for (const PlateUse& plate : parts.plates) {
        corners(plate.area, pts);
        dl->AddPolyline(pts, 4, kRemnantColor, ImDrawFlags_Closed, 1.f);
        if (!plate.remnant) continue;
        const Box& r = *plate.remnant;
        corners(r, pts);
        dl->AddQuadFilled(pts[0], pts[1], pts[2], pts[3], kRemnantFill);
        dl->AddPolyline(pts, 4, kRemnantColor, ImDrawFlags_Closed, 2.f);
        const ImVec2 top_left(std::min({pts[0].x, pts[1].x, pts[2].x, pts[3].x}),
                              std::min({pts[0].y, pts[1].y, pts[2].y, pts[3].y}));
        dl->AddText(ImVec2(top_left.x + 4, top_left.y + 2), kRemnantColor,
                    tr(Msg::UiRemnantSize, {fmt("%.0f", r.max_x - r.min_x), fmt("%.0f", r.max_y - r.min_y)}).c_str());
    }
    const Rect& a = view.area;
    std::size_t labels = 0;
    for (const Part& part : parts.parts) {
        if (labels == kMaxPartLabels) break;
        const ImVec2 lo = screen({part.box.min_x, part.box.min_y}), hi = screen({part.box.max_x, part.box.max_y});
        if (std::max(std::fabs(hi.x - lo.x), std::fabs(hi.y - lo.y)) < kPartLabelMinPx) continue;
        const ImVec2 at = screen(part.label_at);
        if (at.x < a.x || at.y < a.y || at.x > a.x + a.w || at.y > a.y + a.h) continue;
        const std::string number = std::to_string(part.group);
        const ImVec2 size = ImGui::CalcTextSize(number.c_str());
        dl->AddText(ImVec2(at.x - size.x / 2, at.y - size.y / 2), kPartLabelColor, number.c_str());
        ++labels;
    }
}

}  // namespace

void Panels::overlays() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const View& view = p_.navigation.view();
    const Rect& a = view.area;
    dl->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.x + a.w, a.y + a.h), true);
    const Document* doc = p_.session.document();
    const Point o = p_.navigation.origin();
    const Coordinates cs = p_.navigation.coordinates();
    if (p_.layers.grid) grid_labels(dl, view, cs, o, p_.renderer.theme());
    if (doc && p_.layers.table) table_and_plate(dl, *doc, view, o);
    if (doc && p_.layers.parts)
        if (const PartsList* parts = p_.tape_facts.parts()) parts_layer(dl, *parts, view, o);
    compare_overlay(dl);
    problem_marks(dl);
    const Selection& sel = p_.navigation.selection();
    if (doc && (sel.motion != Selection::npos || sel.line > 0)) selection_arrows(dl, *doc, sel, view);
    p_.ui.measure_window = Rect{0, 0, 0, 0};
    if (p_.measure.active) measure(dl, doc, p_.measure, view, cs, o, p_.ui.measure_window);
    dl->PopClipRect();
}

}  // namespace essi::viewer::panels
