// A uniform grid over boxes (the cut plan's spatial index): each box is listed in the cells it covers, and a query
// visits each box whose cells meet the query's once.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "essi/geom.hpp"

namespace essi::plan {

class BoxGrid {
public:
    // About one cell per box over the boxes' extent; at most kMaxCellsPerAxis a side. A grid is built again for
    // each plate (its arrays kept: a thread's grid is reused, see plate.cpp); `boxes` must outlive the queries.
    void build(const std::vector<Box>& boxes) {
        boxes_ = &boxes;
        stamp_.assign(boxes.size(), 0);
        generation_ = 0;
        nx_ = ny_ = 0;
        Box all;
        for (const Box& b : boxes) all.add(b);
        if (all.empty) return;
        origin_ = {all.min_x, all.min_y};
        const double w = std::max(all.max_x - all.min_x, 1e-9), h = std::max(all.max_y - all.min_y, 1e-9);
        const double cell = std::sqrt(w * h / static_cast<double>(std::max<std::size_t>(boxes.size(), 1)));
        // Boxes that each cover many cells (contours piled over each other) would list each box in most cells: the
        // cells grow until the entries are at most kEntriesPerBox a box (one cell holds every box once at worst).
        const std::size_t max_entries = kEntriesPerBox * boxes.size() + kEntriesBase;
        for (cell_ = std::max(cell, std::max(w, h) / kMaxCellsPerAxis);; cell_ *= 2) {
            inverse_cell_ = 1 / cell_;
            nx_ = static_cast<int>(w / cell_) + 1;
            ny_ = static_cast<int>(h / cell_) + 1;
            std::size_t entries = 0;
            for_each_box_span([&](std::size_t cells) { entries += cells; });
            if (entries <= max_entries || (nx_ == 1 && ny_ == 1)) break;
        }
        // Two passes (count, then fill): one array of ids, cell by cell.
        start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
        for_each_box_cell([&](std::size_t cell, int) { ++start_[cell + 1]; });
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        ids_.resize(start_.back());
        fill_.assign(start_.begin(), start_.end() - 1);
        for_each_box_cell([&](std::size_t cell, int id) { ids_[fill_[cell]++] = id; });
    }

    // Calls f(id) once for each box listed in a cell the query box meets (the caller tests the boxes themselves).
    // When f returns a bool, false stops the query.
    template <class F>
    void query(const Box& q, F&& f) {
        if (q.empty || nx_ == 0) return;
        ++generation_;
        int x0, y0, x1, y1;
        cells_of(q, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const std::size_t c = static_cast<std::size_t>(y) * nx_ + x;
                for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                    const int id = ids_[k];
                    if (stamp_[id] == generation_) continue;
                    stamp_[id] = generation_;
                    if constexpr (std::is_same_v<decltype(f(id)), bool>) {
                        if (!f(id)) return;
                    } else {
                        f(id);
                    }
                }
            }
    }

private:
    static constexpr double kMaxCellsPerAxis = 1024;
    static constexpr std::size_t kEntriesPerBox = 16, kEntriesBase = 65536;

    // f(cells) for each box: how many cells it covers.
    template <class F>
    void for_each_box_span(F&& f) const {
        for (const Box& b : *boxes_) {
            if (b.empty) continue;
            int x0, y0, x1, y1;
            cells_of(b, x0, y0, x1, y1);
            f(static_cast<std::size_t>(x1 - x0 + 1) * static_cast<std::size_t>(y1 - y0 + 1));
        }
    }

    void cells_of(const Box& b, int& x0, int& y0, int& x1, int& y1) const {
        // (clamped before the cast: a box far outside the grid is its border cells; NaN is cell 0)
        const auto cell = [&](double v, double origin, int n) {
            const double c = (v - origin) * inverse_cell_;
            return c >= 0 ? static_cast<int>(std::min(c, static_cast<double>(n - 1))) : 0;
        };
        const auto cx = [&](double v) { return cell(v, origin_.x, nx_); };
        const auto cy = [&](double v) { return cell(v, origin_.y, ny_); };
        x0 = cx(b.min_x);
        x1 = cx(b.max_x);
        y0 = cy(b.min_y);
        y1 = cy(b.max_y);
    }
    template <class F>
    void for_each_box_cell(F&& f) const {
        for (std::size_t id = 0; id < boxes_->size(); ++id) {
            const Box& b = (*boxes_)[id];
            if (b.empty) continue;
            int x0, y0, x1, y1;
            cells_of(b, x0, y0, x1, y1);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) f(static_cast<std::size_t>(y) * nx_ + x, static_cast<int>(id));
        }
    }

    const std::vector<Box>* boxes_ = nullptr;
    Point origin_;
    double cell_ = 1, inverse_cell_ = 1;
    int nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> start_;
    std::vector<int> ids_;
    std::vector<std::uint32_t> fill_;
    std::vector<std::uint32_t> stamp_;
    std::uint32_t generation_ = 0;
};

// Whether two boxes meet once `a` is grown by `margin` on every side.
[[nodiscard]] inline bool boxes_meet(const Box& a, const Box& b, double margin) {
    return !a.empty && !b.empty && a.min_x - margin <= b.max_x && b.min_x <= a.max_x + margin &&
           a.min_y - margin <= b.max_y && b.min_y <= a.max_y + margin;
}

}  // namespace essi::plan
