#include "app/Navigation.hpp"

#include <algorithm>
#include <utility>

#include "app/Document.hpp"
#include "app/LoadController.hpp"
#include "app/ProblemList.hpp"
#include "app/Playback.hpp"

namespace essi::viewer {

Navigation::Navigation(const LoadController& load, SettingsStore& settings) : load_(load), settings_(settings) {
    view_.turns = ((settings_.load_int_setting(kOrientationSetting).value_or(0) % 4) + 4) % 4;
    machine_coordinates_ = settings_.load_int_setting(kCoordinatesSetting).value_or(0) == 1;
}

const Document* Navigation::settled_document() const { return load_.reading() ? nullptr : load_.document(); }

void Navigation::fit() {
    if (const Document* d = load_.document()) view_.fit(d->bbox, d->origin);
}

void Navigation::set_view(double x, double y, double zoom) {
    const Document* d = settled_document();
    if (!d) {
        ViewRequest v = pending_.value_or(ViewRequest{});
        v.x = x;
        v.y = y;
        v.zoom = zoom;
        pending_ = v;
        return;
    }
    view_.zoom = std::clamp(zoom, View::kMinZoom, View::kMaxZoom);
    view_.cx = x - d->origin.x;
    view_.cy = y - d->origin.y;
}

void Navigation::select_line(std::uint32_t line, bool reveal) {
    const Document* d = settled_document();
    if (!d) {
        ViewRequest v = pending_.value_or(ViewRequest{});
        v.line = line;
        pending_ = v;
        return;
    }
    selection_.line = line;
    selection_.motion = Selection::npos;
    selection_.scroll_source = true;
    const auto [a, b] = d->motions_of_line(line);
    if (a >= b) return;
    selection_.motion = a;
    if (reveal) reveal_motions(*d, a, b);
}

// Motions [first, last) into view when they are not all in it.
void Navigation::reveal_motions(const Document& d, std::size_t first, std::size_t last) {
    Box box;
    for (std::size_t i = first; i < last; ++i) box.add(bounding_box(d.record(i)));
    const Rect& r = view_.area;
    bool inside = true;  // (every corner: the view may be turned)
    for (const double x : {box.min_x, box.max_x})
        for (const double y : {box.min_y, box.max_y}) {
            const Point p = view_.to_screen({x - d.origin.x, y - d.origin.y});
            inside = inside && r.contains(static_cast<float>(p.x), static_cast<float>(p.y));
        }
    if (!inside) {
        view_.cx = (box.min_x + box.max_x) / 2 - d.origin.x;
        view_.cy = (box.min_y + box.max_y) / 2 - d.origin.y;
    }
}

void Navigation::select_motion(std::size_t motion) {
    const Document* d = load_.document();
    if (!d || motion >= d->motions.size()) {
        selection_.clear();
        return;
    }
    selection_.motion = motion;
    selection_.line = d->motions[motion].line;
    selection_.scroll_source = true;
}

void Navigation::select_diagnostic(std::size_t index) {
    const Document* d = load_.document();
    if (!d || index >= d->diagnostics.size()) return;
    problem_ = index;  // (next and previous problem go on from it)
    if (d->diagnostics[index].line > 0) select_line(d->diagnostics[index].line);
}

void Navigation::show_problem(std::size_t index) {
    const Document* d = settled_document();
    if (!d || index >= d->diagnostics.size()) return;
    const Diagnostic& diag = d->diagnostics[index];
    problem_ = index;
    if (diag.line > 0) select_line(diag.line, false);
    Box box;
    for (const LineRange& lines : concerned_lines(diag)) {
        const auto [a, b] = d->motions_of_lines(lines);
        for (std::size_t i = a; i < b; ++i) box.add(bounding_box(d->record(i)));
    }
    for (const DiagnosticMark& m : d->marks)  // (a block that is no motion: where its mark is)
        if (box.empty && m.diagnostic == index) box.add(m.at);
    if (box.empty) return;
    const double cx = (box.min_x + box.max_x) / 2, cy = (box.min_y + box.max_y) / 2;
    const double half = kProblemViewMm / 2;
    box.add(Point{std::min(box.min_x, cx - half), std::min(box.min_y, cy - half)});
    box.add(Point{std::max(box.max_x, cx + half), std::max(box.max_y, cy + half)});
    show_box(box);
}

void Navigation::step_problem(int step) {
    const Document* d = settled_document();
    if (!d) return;
    const std::size_t next = viewer::step_problem(d->diagnostics, problem_, step);
    if (next != Selection::npos) show_problem(next);
}

void Navigation::show_box(const Box& box) {
    if (const Document* d = load_.document()) view_.fit(box, d->origin, kContourMarginPx);
}

void Navigation::follow(const Document& d, const Playback& playback) {
    if (d.motions.empty()) return;
    const std::uint32_t line = d.motions[playback.at(d.motions.size()).motion].line;
    if (line != selection_.line) select_line(line, false);
}

void Navigation::set_orientation(int quarter_turns) {
    view_.turns = ((quarter_turns % 4) + 4) % 4;
    settings_.save_int_setting(kOrientationSetting, view_.turns);
}

void Navigation::set_machine_coordinates(bool machine) {
    machine_coordinates_ = machine;
    settings_.save_int_setting(kCoordinatesSetting, machine ? 1 : 0);
    view_.plate = coordinates().plate();  // (the drawing turns about the view's centre)
}

Coordinates Navigation::coordinates() const {
    const Document* d = load_.document();
    return machine_coordinates_ && d ? Coordinates(d->profile) : Coordinates();
}

Point Navigation::origin() const {
    const Document* d = load_.document();
    return d ? d->origin : Point{};
}

Box Navigation::visible_box() const {
    const Rect& a = view_.area;
    const Point o = origin();
    Box b;
    for (const auto& [x, y] : {std::pair{a.x, a.y}, {a.x + a.w, a.y}, {a.x, a.y + a.h}, {a.x + a.w, a.y + a.h}}) {
        const Point w = view_.to_world(x, y);
        b.add(Point{w.x + o.x, w.y + o.y});
    }
    return b;
}

ViewRequest Navigation::current() const {
    const Point o = origin();
    return {view_.cx + o.x, view_.cy + o.y, view_.zoom, selection_.line};
}

void Navigation::document_loaded(const Document& d) {
    selection_.clear();
    problem_ = Selection::npos;
    view_.plate = coordinates().plate();
    view_.fit(d.bbox, d.origin);
    apply_request(d);
}

void Navigation::apply_request(const Document& d) {
    if (!pending_) return;
    const ViewRequest v = *pending_;
    if (v.zoom > 0) {
        view_.zoom = std::clamp(v.zoom, View::kMinZoom, View::kMaxZoom);
        view_.cx = v.x - d.origin.x;
        view_.cy = v.y - d.origin.y;
    }
    if (v.line > 0) select_line(v.line, false);
    pending_.reset();
}

}  // namespace essi::viewer
