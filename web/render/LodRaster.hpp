// The level of detail for zoomed-out views of big tapes: the drawing as a raster of kinds, built once per tape
// while its segments are made. Each cell of the finest level (kCells on the tape's longer side) holds a bit per
// motion kind that crosses it and one for a pierce in it; each coarser level ORs 2 x 2 cells, so a thin line
// never disappears when zooming out. When a cell is at most about a pixel the renderer draws this raster (one
// rectangle, a few texel reads a pixel) instead of millions of sub-pixel segments.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "essi/geom.hpp"

namespace essi::viewer {

class LodRaster {
public:
    static constexpr int kCells = 2048;           // finest level, on the longer side (GLES 3 guarantees 2048)
    static constexpr std::uint8_t kPierceBit = 16;  // bits 0-3: MotionKind

    // `bbox` in machine mm; the raster is relative to `origin` like the segments.
    void begin(const Box& bbox, Point origin);
    void add_segment(float x0, float y0, float x1, float y1, std::uint8_t kind);
    void add_pierce(float x, float y);
    void finish();  // builds the coarser levels
    void release();  // frees the CPU copy (once on the GPU)

    [[nodiscard]] bool active() const { return width_ > 0; }
    [[nodiscard]] bool finished() const { return finished_; }
    [[nodiscard]] double cell_mm() const { return cell_; }
    [[nodiscard]] float min_x() const { return min_x_; }
    [[nodiscard]] float min_y() const { return min_y_; }
    [[nodiscard]] int width(int level = 0) const { return level < static_cast<int>(sizes_.size()) ? sizes_[level].first : 0; }
    [[nodiscard]] int height(int level = 0) const { return level < static_cast<int>(sizes_.size()) ? sizes_[level].second : 0; }
    [[nodiscard]] int levels() const { return static_cast<int>(sizes_.size()); }
    [[nodiscard]] const std::vector<std::uint8_t>& level(int k) const { return data_[static_cast<std::size_t>(k)]; }
    [[nodiscard]] std::size_t memory_bytes() const;

private:
    void set(int cx, int cy, std::uint8_t bit) {
        if (cx >= 0 && cy >= 0 && cx < width_ && cy < height_)
            data_[0][static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(cx)] |= bit;
    }

    int width_ = 0, height_ = 0;
    double cell_ = 1;
    float min_x_ = 0, min_y_ = 0;
    float inv_cell_ = 1;
    bool finished_ = false;
    std::vector<std::pair<int, int>> sizes_;
    std::vector<std::vector<std::uint8_t>> data_;
};

}  // namespace essi::viewer
