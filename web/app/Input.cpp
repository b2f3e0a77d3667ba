#include "app/Input.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/Problems.hpp"
#include "essi/geom.hpp"

namespace essi::viewer {

namespace {

constexpr double kPickRadiusPx = 6;
constexpr double kSnapRadiusPx = 10;
constexpr double kDragThresholdPx = 3;  // a press that moves further is a drag, not a click
constexpr double kWheelZoom = 1.2;      // a wheel notch
constexpr double kKeyZoom = 1.25;       // + and -
// Two motions this close (mm) to the cursor are equally near: cut and mark then win over travel.
constexpr double kPickTieMm = 1e-9;

double seg_distance(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

// Cheap rejections before the distance to the whole record: a line's box, an arc's ring between its two radii.
bool beyond(const Document& d, std::size_t i, Point p, double best) {
    const Motion& m = d.motions[i];
    if (m.curve == CurveKind::Line) {
        const Point a = d.start_of(i), e = d.end_of(i);
        return p.x < std::min(a.x, e.x) - best || p.x > std::max(a.x, e.x) + best || p.y < std::min(a.y, e.y) - best ||
               p.y > std::max(a.y, e.y) + best;
    }
    if (m.curve == CurveKind::Arc) {
        const Point c = d.arc_centre(i), a = d.start_of(i), e = d.end_of(i);
        const double rc = std::hypot(p.x - c.x, p.y - c.y);
        const double r0 = std::hypot(a.x - c.x, a.y - c.y), r1 = std::hypot(e.x - c.x, e.y - c.y);
        return rc < std::min(r0, r1) - best || rc > std::max(r0, r1) + best;
    }
    return false;
}

}  // namespace

std::size_t pick(const Document& d, const View& view, std::size_t limit, int kind_mask, double sx, double sy) {
    if (d.motions.empty()) return Selection::npos;
    const Point w = view.to_world(sx, sy);
    const Point p{w.x + d.origin.x, w.y + d.origin.y};
    double best = kPickRadiusPx / view.zoom;
    std::size_t best_motion = Selection::npos;
    std::vector<Point> pts;
    auto consider = [&](std::size_t i, double dist) {
        // Prefer cut and mark over travel when they overlap (<=: a later cut wins ties)
        if (dist < best || (dist <= best + kPickTieMm && d.motions[i].kind >= MotionKind::Cut)) {
            best = dist;
            best_motion = i;
        }
    };
    for (std::size_t i = 0; i < limit; ++i) {
        const Motion& m = d.motions[i];
        if ((kind_mask & kind_bit(m.kind)) == 0 || beyond(d, i, p, best)) continue;
        if (m.curve == CurveKind::Line) {
            const Point a = d.start_of(i), e = d.end_of(i);
            consider(i, seg_distance(p.x, p.y, a.x, a.y, e.x, e.y));
            continue;
        }
        pts.clear();
        flatten(d.record(i), view.chord_tolerance_mm(), pts, true);
        double dist = HUGE_VAL;
        for (std::size_t k = 1; k < pts.size(); ++k)
            dist = std::min(dist, seg_distance(p.x, p.y, pts[k - 1].x, pts[k - 1].y, pts[k].x, pts[k].y));
        consider(i, dist);
    }
    return best_motion;
}

Point snap(const Document* doc, const View& view, double sx, double sy, bool* snapped) {
    const Point w = view.to_world(sx, sy);  // relative to origin
    *snapped = false;
    const Point o = doc ? doc->origin : Point{};
    Point result = {w.x + o.x, w.y + o.y};
    if (!doc) return result;
    double best = kSnapRadiusPx / view.zoom;
    auto consider = [&](Point p) {
        const double d = std::hypot(p.x - o.x - w.x, p.y - o.y - w.y);
        if (d < best) {
            best = d;
            result = p;
            *snapped = true;
        }
    };
    // End points (every start is the end before it, or a jump) and arc centres.
    const Document& d = *doc;
    for (std::size_t i = 0; i < d.motions.size(); ++i) consider(d.end_of(i));
    for (const auto& j : d.jumps) consider(j.second);
    for (const UnitPoint& c : d.arc_centres) consider(d.point_mm(c));
    for (const auto& k : d.kept)
        if (k.second.curve == CurveKind::Arc) consider(k.second.centre);
    return result;
}

void Input::handle_shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;
    handle_characters();
    handle_keys();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_O)) p_.platform.open_file_dialog();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_V)) p_.platform.paste();
}

// Typed characters (queued by ImGui: never lost, whatever the keyboard layout).
void Input::handle_characters() {
    const ImGuiIO& io = ImGui::GetIO();
    View& view = p_.navigation.view();
    Layers& layers = p_.layers;
    for (int i = 0; i < io.InputQueueCharacters.Size; ++i) {
        switch (io.InputQueueCharacters[i]) {
            case 'f':
            case 'F': p_.navigation.fit(); break;
            case 'h':
            case 'H':
            case '?': p_.ui.help = !p_.ui.help; break;
            case 'm':
            case 'M': p_.measure.toggle(); break;
            case ' ':  // (on a focused control Space presses it)
                if (const Document* d = p_.session.document(); d && p_.ui.keyboard != KeyboardMode::Panels)
                    p_.playback.toggle(d->motions.size());
                break;
            case '+':
            case '=': view.zoom_at(view.ox(), view.oy(), kKeyZoom); break;
            case '-': view.zoom_at(view.ox(), view.oy(), 1 / kKeyZoom); break;
            case 'g':
            case 'G': layers.grid = !layers.grid; break;
            case 's':
            case 'S': p_.shares.share(); break;
            case 'p':
            case 'P': p_.preferences.set_problems_only(!p_.preferences.problems_only()); break;
            case 'n': p_.navigation.step_problem(1); break;  // (Shift+N: the one before)
            case 'N': p_.navigation.step_problem(-1); break;
            case '1': layers.kind(MotionKind::Cut) = !layers.kind(MotionKind::Cut); break;
            case '2':  // travel and rapid together
                layers.kind(MotionKind::Travel) = !layers.kind(MotionKind::Travel);
                layers.kind(MotionKind::Rapid) = layers.kind(MotionKind::Travel);
                break;
            case '3': layers.kind(MotionKind::Mark) = !layers.kind(MotionKind::Mark); break;
            case '4': layers.pierces = !layers.pierces; break;
            case '[': toggle_side_panel(true); break;
            case ']': toggle_side_panel(false); break;
            default: break;
        }
    }
}

// A side panel shown or hidden ([ and ]).
void Input::toggle_side_panel(bool left) {
    panels::PanelLayout l = p_.ui.layout;
    bool& shown = left ? l.left_shown : l.right_shown;
    shown = !shown;
    p_.preferences.set_layout(l);
}

// Keys without a character: Esc, F1, the playback's arrows, Home and End. While the keyboard's focus is on a control
// (KeyboardFocus) the arrows, Home and End move through the panels, and Esc backs out of a list, not the selection.
void Input::handle_keys() {
    const bool on_control = p_.ui.keyboard == KeyboardMode::Panels;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        if (p_.measure.active) p_.measure.leave();
        else if (p_.ui.help) p_.ui.help = false;
        else if (!on_control) p_.navigation.selection().clear();
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_F1)) p_.ui.help = !p_.ui.help;
    const Document* doc = p_.session.document();
    if (!doc || doc->motions.empty() || on_control) return;
    const std::size_t n = doc->motions.size();
    Playback& playback = p_.playback;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) playback.step_forward(n);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) playback.step_back();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home))) playback.rewind();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_End))) playback.show_all(n);
}

void Input::handle_canvas() {
    const ImGuiIO& io = ImGui::GetIO();
    View& view = p_.navigation.view();
    const ImVec2 mp = io.MousePos;
    const bool over = view.area.contains(mp.x, mp.y) && !io.WantCaptureMouse;
    if (over && io.MouseWheel != 0) view.zoom_at(mp.x, mp.y, std::pow(kWheelZoom, io.MouseWheel));
    if (over && ImGui::IsMouseClicked(0)) {
        press_in_canvas_ = true;
        dragging_ = false;
        press_x_ = mp.x;
        press_y_ = mp.y;
    }
    if (press_in_canvas_ && ImGui::IsMouseDown(0)) {
        if (!dragging_ && std::hypot(mp.x - press_x_, mp.y - press_y_) > kDragThresholdPx) dragging_ = true;
        if (dragging_) view.pan_by(io.MouseDelta.x, io.MouseDelta.y);
    }
    if (press_in_canvas_ && ImGui::IsMouseReleased(0)) {
        press_in_canvas_ = false;
        if (!dragging_) click(mp.x, mp.y);
        dragging_ = false;
    }
    // Right button or middle button drag pans too.
    if (over && (ImGui::IsMouseDragging(1) || ImGui::IsMouseDragging(2))) view.pan_by(io.MouseDelta.x, io.MouseDelta.y);
}

// A click on the drawing: a measure point, a diagnostic's mark (its block selected, as in the problems list), or
// the motion under it selected (none: the selection cleared).
void Input::click(double sx, double sy) {
    const Document* doc = p_.session.document();
    const View& view = p_.navigation.view();
    if (p_.measure.active) {
        bool snapped = false;
        p_.measure.click(snap(doc, view, sx, sy, &snapped));
        return;
    }
    if (const std::size_t mark = doc ? mark_at(*doc, view, sx, sy) : kNoMark; mark != kNoMark) {
        p_.navigation.select_diagnostic(doc->marks[mark].diagnostic);
        return;
    }
    const std::size_t n = doc ? doc->motions.size() : 0;
    const std::size_t m = doc ? pick(*doc, view, p_.playback.limit(n), p_.layers.kind_mask(), sx, sy) : Selection::npos;
    if (m != Selection::npos) p_.navigation.select_motion(m);
    else p_.navigation.selection().clear();
}

}  // namespace essi::viewer
