// The camera: which millimetres are drawn where. Pixels are window (ImGui) pixels, top-left origin.
#pragma once

#include <algorithm>
#include <cmath>

#include "essi/geom.hpp"

namespace essi::viewer {

struct Rect {
    float x = 0, y = 0, w = 1, h = 1;
    [[nodiscard]] bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
    bool operator==(const Rect&) const = default;
};

struct View {
    double cx = 0, cy = 0;  // mm, relative to the document origin, drawn at the centre of `area`
    double zoom = 1;        // pixels per mm
    Rect area;              // the drawing area (the window minus the side panels)

    [[nodiscard]] double ox() const { return area.x + area.w * 0.5; }
    [[nodiscard]] double oy() const { return area.y + area.h * 0.5; }
    [[nodiscard]] Point to_screen(Point p) const { return {ox() + (p.x - cx) * zoom, oy() - (p.y - cy) * zoom}; }
    [[nodiscard]] Point to_world(double sx, double sy) const { return {cx + (sx - ox()) / zoom, cy - (sy - oy()) / zoom}; }

    void fit(const Box& b, Point origin, float margin_px = 24) {
        if (b.empty) {
            cx = cy = 0;
            zoom = 1;
            return;
        }
        const double w = std::max(b.max_x - b.min_x, 1e-3), h = std::max(b.max_y - b.min_y, 1e-3);
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

    bool operator==(const View&) const = default;

    static constexpr double kMinZoom = 1e-4;  // px/mm
    static constexpr double kMaxZoom = 1e4;
};

}  // namespace essi::viewer
