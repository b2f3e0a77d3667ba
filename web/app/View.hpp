// The camera: which millimetres are drawn where. Pixels are window (ImGui) pixels, top-left origin.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "essi/geom.hpp"

namespace essi::viewer {

struct Rect {
    float x = 0, y = 0, w = 1, h = 1;
    [[nodiscard]] bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
    bool operator==(const Rect&) const = default;
};

// The machine's view orientation: where the tape's +x points on the screen (the world turned by quarter turns,
// counter-clockwise). ISO drawings: +x right, +y up; Woyda's operator's view (docs/semantics.md §3): +x back (up),
// +y left, one quarter turn.
enum class Orientation : int { XRight = 0, XUp = 1, XLeft = 2, XDown = 3 };

// A vector turned by `quarter_turns` x 90 degrees counter-clockwise (exact: no trigonometry).
[[nodiscard]] inline Point turned(Point v, int quarter_turns) {
    switch (((quarter_turns % 4) + 4) % 4) {
        case 1: return {-v.y, v.x};
        case 2: return {-v.x, -v.y};
        case 3: return {v.y, -v.x};
        default: return v;
    }
}

// A rotation (cos, sin of its angle, counter-clockwise). Quarter turns are exact.
struct Rotation {
    double c = 1, s = 0;
    [[nodiscard]] static Rotation quarter(int quarter_turns) {
        const Point u = turned({1, 0}, quarter_turns);
        return {u.x, u.y};
    }
    [[nodiscard]] Point apply(Point v) const { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
    [[nodiscard]] Point undo(Point v) const { return {c * v.x + s * v.y, -s * v.x + c * v.y}; }
    // This rotation, then `next`.
    [[nodiscard]] Rotation then(Rotation next) const { return {next.c * c - next.s * s, next.s * c + next.c * s}; }
    bool operator==(const Rotation&) const = default;
};

struct View {
    double cx = 0, cy = 0;  // mm, relative to the document origin, drawn at the centre of `area`
    double zoom = 1;        // pixels per mm
    Rect area;              // the drawing area (the window minus the side panels)
    int turns = 0;          // Orientation: the world turned this many quarter turns on the screen
    // Machine coordinates (Coordinates): the plate's rotation on the table, applied before the quarter turns;
    // none in program coordinates.
    Rotation plate;

    // The whole turn from the world (program mm) to the screen: the plate's, then the orientation's.
    [[nodiscard]] Rotation rotation() const { return plate.then(Rotation::quarter(turns)); }
    [[nodiscard]] double ox() const { return area.x + area.w * 0.5; }
    [[nodiscard]] double oy() const { return area.y + area.h * 0.5; }
    [[nodiscard]] Point to_screen(Point p) const {
        const Point d = rotation().apply({p.x - cx, p.y - cy});
        return {ox() + d.x * zoom, oy() - d.y * zoom};
    }
    [[nodiscard]] Point to_world(double sx, double sy) const {
        const Point d = rotation().undo({(sx - ox()) / zoom, -(sy - oy()) / zoom});
        return {cx + d.x, cy + d.y};
    }

    // Moves the drawing by (dx, dy) screen pixels (a drag).
    void pan_by(double dx_px, double dy_px) {
        const Point d = rotation().undo({dx_px / zoom, -dy_px / zoom});
        cx -= d.x;
        cy -= d.y;
    }

    // The box (world mm) in the middle of the area, as large as fits: its corners turned as the screen shows them.
    void fit(const Box& b, Point origin, float margin_px = 24) {
        if (b.empty) {
            cx = cy = 0;
            zoom = 1;
            return;
        }
        const Rotation r = rotation();
        const double hw = std::max(b.max_x - b.min_x, kMinFitSizeMm) / 2,
                     hh = std::max(b.max_y - b.min_y, kMinFitSizeMm) / 2;
        const double w = 2 * (std::fabs(r.c) * hw + std::fabs(r.s) * hh),
                     h = 2 * (std::fabs(r.s) * hw + std::fabs(r.c) * hh);
        const double aw = std::max(area.w - 2 * margin_px, 10.f), ah = std::max(area.h - 2 * margin_px, 10.f);
        zoom = std::clamp(std::min(aw / w, ah / h), kMinZoom, kMaxZoom);
        cx = (b.min_x + b.max_x) / 2 - origin.x;
        cy = (b.min_y + b.max_y) / 2 - origin.y;
    }

    // Zooms by `factor` keeping the world point under (sx, sy) fixed.
    void zoom_at(double sx, double sy, double factor) {
        const Point before = to_world(sx, sy);
        zoom = std::clamp(zoom * factor, kMinZoom, kMaxZoom);
        const Point after = to_world(sx, sy);
        cx += before.x - after.x;
        cy += before.y - after.y;
    }

    // The chord tolerance that draws the curves smooth at this zoom: a quarter pixel, never finer than the core
    // allows.
    [[nodiscard]] double chord_tolerance_mm() const { return std::max(kChordPixels / zoom, kMinChordTolerance); }

    bool operator==(const View&) const = default;

    static constexpr double kChordPixels = 0.25;

    static constexpr double kMinZoom = 1e-4;  // px/mm
    static constexpr double kMaxZoom = 1e4;
    // fit() treats a box thinner than this (a line, a point) as this wide: its zoom stays finite.
    static constexpr double kMinFitSizeMm = 1e-3;
};

// Grid step (mm) so that minor lines are at least `px` apart: 1, 2, 5 x 10^k.
inline double grid_step(double zoom, double px = 12) {
    const double raw = px / zoom;
    const double e = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * e >= raw) return m * e;
    return 10 * e;
}

// The grid step of a scene without the grid: wider than any drawing, so no line shows.
inline constexpr double kNoGrid = 1e30;

}  // namespace essi::viewer
