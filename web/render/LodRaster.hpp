// The level of detail for zoomed-out views of big tapes: the drawing as a raster of kinds, built once per tape
// in its own pass over the motions (in steps, before the exact segments are made, so that a big tape is on the
// screen from the raster while they are). Each cell of the finest level (at most kMaxCells on the tape's longer
// side, fewer for smaller tapes: see cells_for) holds a bit per motion kind that crosses it and one for a pierce
// in it; each coarser level ORs 2 x 2 cells, so a thin line never disappears when zooming out. When a cell is at
// most about a pixel the renderer draws this raster (one rectangle, a few texel reads a pixel) instead of
// millions of sub-pixel segments.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "app/Document.hpp"
#include "essi/geom.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

class LodRaster {
public:
    static constexpr int kMaxCells = 2048;  // finest level, on the longer side (GLES 3 guarantees 2048)
    static constexpr int kMinCells = 256;   // (a tape with fewer motions than a few thousand has no LOD)
    // The finest level holds at most this many cells a motion (one byte a cell, while it is built on the CPU):
    // a tape of 100 000-250 000 motions gets a raster of ~900-1 400 cells on its longer side instead of 2 048,
    // which keeps the page's memory peak within its budget (docs/performance.md) and still covers a fitted view
    // of this window size at a cell a pixel; from ~520 000 motions (square tapes) it is the full kMaxCells.
    static constexpr double kCellsPerMotion = 8;
    static constexpr std::uint8_t kPierceBit = 1 << kMotionKinds;  // bits 0-3: MotionKind (kind_bit)
    // The chord tolerance of the arcs rasterised, in cells.
    static constexpr double kChordCells = 0.25;
    // Each level is held in strips of whole rows of about this many bytes, not one block: at the end of a load the
    // heap has holes of a few hundred KB (the loader's buffers, just freed) that strips fill and a raster of a
    // megabyte or more would not, so it would grow the heap's peak by its whole size.
    static constexpr std::size_t kStripBytes = 64u << 10;
    // Cells on the longer side of a box w x h mm for a tape of `motions` motions.
    [[nodiscard]] static int cells_for(double w, double h, std::size_t motions);

    // `bbox` in machine mm; the raster is relative to `origin` like the segments; `cells` on the longer side.
    void begin(const Box& bbox, Point origin, int cells = kMaxCells);
    // The whole document with `cells` on the longer side (default: cells_for), its pierces; then step()
    // rasterises its motions.
    void begin(const Document& doc, int cells = 0);
    // Rasterises up to `max_motions` more motions of the document given to begin(doc); true when all are in.
    bool step(std::size_t max_motions);
    [[nodiscard]] float progress() const;
    void finish();   // builds the coarser levels
    void release();  // frees the CPU copy (once on the GPU)

    [[nodiscard]] bool active() const { return width_ > 0; }
    [[nodiscard]] bool finished() const { return finished_; }
    [[nodiscard]] double cell_mm() const { return cell_; }
    [[nodiscard]] float min_x() const { return min_x_; }
    [[nodiscard]] float min_y() const { return min_y_; }
    [[nodiscard]] int width(int level = 0) const {
        return level < static_cast<int>(sizes_.size()) ? sizes_[level].first : 0;
    }
    [[nodiscard]] int height(int level = 0) const {
        return level < static_cast<int>(sizes_.size()) ? sizes_[level].second : 0;
    }
    [[nodiscard]] int levels() const { return static_cast<int>(sizes_.size()); }
    // Level k as strips of whole rows, bottom row first: strip j holds rows [j x strip_rows(k), ...).
    [[nodiscard]] const std::vector<std::vector<std::uint8_t>>& strips(int k) const {
        return data_[static_cast<std::size_t>(k)];
    }
    [[nodiscard]] int strip_rows(int k) const { return rows_for(width(k)); }
    // The cell (x, y) of level k (tests).
    [[nodiscard]] std::uint8_t at(int k, int x, int y) const;
    [[nodiscard]] std::size_t memory_bytes() const;

private:
    [[nodiscard]] static int rows_for(int width) {  // (a power of two)
        int rows = 1;
        while (static_cast<std::size_t>(rows) * 2 * static_cast<std::size_t>(std::max(width, 1)) <= kStripBytes)
            rows *= 2;
        return rows;
    }
    [[nodiscard]] static std::vector<std::vector<std::uint8_t>> blank(int w, int h);
    [[nodiscard]] static std::uint8_t& cell(std::vector<std::vector<std::uint8_t>>& level, int w, int x, int y) {
        const int rows = rows_for(w);
        return level[static_cast<std::size_t>(y / rows)]
                    [static_cast<std::size_t>(y % rows) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)];
    }
    // The segment a -> b in cells (fractions: cell (i, j) is [i, i+1) x [j, j+1)): `bit` in every cell it crosses.
    void add_cells(Point a, Point b, std::uint8_t bit);
    // Arc `motion` (compact, starting at `start`), chords within `tolerance` cells.
    void put_arc(std::size_t motion, UnitPoint start, double tolerance, std::uint8_t bit);
    [[nodiscard]] Point cells_of(UnitPoint u) const {
        return {u.x * units_to_cells_ + cells_at_zero_x_, u.y * units_to_cells_ + cells_at_zero_y_};
    }
    [[nodiscard]] Point to_cells(Point mm) const;
    void set(int cx, int cy, std::uint8_t bit) {
        if (cx >= 0 && cy >= 0 && cx < width_ && cy < height_) rows_[static_cast<std::size_t>(cy)][cx] |= bit;
    }

    int width_ = 0, height_ = 0;
    double cell_ = 1;
    float min_x_ = 0, min_y_ = 0;
    bool finished_ = false;
    int cells_ = kMaxCells;
    const Document* doc_ = nullptr;
    std::size_t next_ = 0;
    std::vector<Point> scratch_;
    double units_to_cells_ = 0, cells_at_zero_x_ = 0, cells_at_zero_y_ = 0;  // (begin(doc))
    UnitPoint last_end_;  // of the motion before, when it was compact
    bool last_in_units_ = false;
    std::vector<std::pair<int, int>> sizes_;
    std::vector<std::vector<std::vector<std::uint8_t>>> data_;  // level, strip, cells
    std::vector<std::uint8_t*> rows_;  // the finest level's rows (no division by the strip height per cell)
};

}  // namespace essi::viewer
