#include "render/LodRaster.hpp"

#include <algorithm>
#include <cmath>

namespace essi::viewer {

void LodRaster::begin(const Box& bbox, Point origin) {
    *this = LodRaster{};
    if (bbox.empty) return;
    const double w = bbox.max_x - bbox.min_x, h = bbox.max_y - bbox.min_y;
    const double longer = std::max(w, h);
    if (!(longer > 0)) return;
    cell_ = longer / (kCells - 2);  // a cell of border on each side
    min_x_ = static_cast<float>(bbox.min_x - origin.x - cell_);
    min_y_ = static_cast<float>(bbox.min_y - origin.y - cell_);
    inv_cell_ = static_cast<float>(1.0 / cell_);
    int lw = std::clamp(static_cast<int>(std::ceil(w / cell_)) + 2, 1, kCells);
    int lh = std::clamp(static_cast<int>(std::ceil(h / cell_)) + 2, 1, kCells);
    width_ = lw;
    height_ = lh;
    for (;;) {
        sizes_.emplace_back(lw, lh);
        if (lw == 1 && lh == 1) break;
        lw = std::max(1, lw / 2);  // the sizes of a complete mipmap chain
        lh = std::max(1, lh / 2);
    }
    data_.assign(1, std::vector<std::uint8_t>(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0));
}

void LodRaster::add_segment(float x0, float y0, float x1, float y1, std::uint8_t kind) {
    if (width_ == 0 || finished_) return;
    const std::uint8_t bit = static_cast<std::uint8_t>(1u << (kind & 3));
    const float ax = (x0 - min_x_) * inv_cell_, ay = (y0 - min_y_) * inv_cell_;
    const float bx = (x1 - min_x_) * inv_cell_, by = (y1 - min_y_) * inv_cell_;
    // Samples at most a cell apart along the longer axis: every cell the segment crosses gets the bit
    // (8-connected, as a one-pixel line is drawn).
    const float span = std::max(std::fabs(bx - ax), std::fabs(by - ay));
    const int n = static_cast<int>(std::min(span, static_cast<float>(2 * kCells))) + 1;
    const float dx = (bx - ax) / static_cast<float>(n), dy = (by - ay) / static_cast<float>(n);
    for (int i = 0; i <= n; ++i)
        set(static_cast<int>(ax + dx * static_cast<float>(i)), static_cast<int>(ay + dy * static_cast<float>(i)), bit);
}

void LodRaster::add_pierce(float x, float y) {
    if (width_ == 0 || finished_) return;
    set(static_cast<int>((x - min_x_) * inv_cell_), static_cast<int>((y - min_y_) * inv_cell_), kPierceBit);
}

void LodRaster::finish() {
    if (width_ == 0 || finished_ || data_.empty()) return;
    data_.resize(sizes_.size());
    for (std::size_t k = 1; k < sizes_.size(); ++k) {
        const auto [pw, ph] = sizes_[k - 1];
        const auto [w, h] = sizes_[k];
        const std::vector<std::uint8_t>& src = data_[k - 1];
        std::vector<std::uint8_t>& dst = data_[k];
        dst.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
        for (int y = 0; y < ph; ++y)
            for (int x = 0; x < pw; ++x)
                // (an odd last row or column goes into the last cell)
                dst[static_cast<std::size_t>(std::min(y / 2, h - 1)) * static_cast<std::size_t>(w) +
                    static_cast<std::size_t>(std::min(x / 2, w - 1))] |=
                    src[static_cast<std::size_t>(y) * static_cast<std::size_t>(pw) + static_cast<std::size_t>(x)];
    }
    finished_ = true;
}

void LodRaster::release() {
    data_.clear();
    data_.shrink_to_fit();
}

std::size_t LodRaster::memory_bytes() const {
    std::size_t n = 0;
    for (const auto& d : data_) n += d.capacity();
    return n;
}

}  // namespace essi::viewer
