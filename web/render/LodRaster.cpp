#include "render/LodRaster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "essi/interp.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

int LodRaster::cells_for(double w, double h, std::size_t motions) {
    const double longer = std::max(w, h), shorter = std::min(w, h);
    if (!(longer > 0)) return kMinCells;
    // longer_cells x (longer_cells x shorter / longer) <= kCellsPerMotion x motions
    const double ratio = std::max(shorter / longer, 1.0 / kMaxCells);
    const double cells = std::sqrt(kCellsPerMotion * static_cast<double>(motions) / ratio);
    return static_cast<int>(std::clamp(cells, static_cast<double>(kMinCells), static_cast<double>(kMaxCells)));
}

void LodRaster::begin(const Document& doc, int cells) {
    const Box& b = doc.bbox;
    if (cells <= 0) cells = b.empty ? kMaxCells : cells_for(b.max_x - b.min_x, b.max_y - b.min_y, doc.motions.size());
    begin(b, doc.origin, cells);
    if (width_ == 0) return;
    doc_ = &doc;
    // A position in units to cells: cells = units x unit_mm / cell + (- origin - the raster's corner) / cell.
    const Profile& p = doc.profile;
    units_to_cells_ = p.unit_mm / cell_;
    cells_at_zero_x_ = (-doc.origin.x - min_x_) / cell_;
    cells_at_zero_y_ = (-doc.origin.y - min_y_) / cell_;
    for (const std::uint32_t i : doc.pierces) {
        const Point c = to_cells(doc.start_of(i));
        set(static_cast<int>(std::floor(c.x)), static_cast<int>(std::floor(c.y)), kPierceBit);
    }
}

Point LodRaster::to_cells(Point mm) const {
    return {(mm.x - doc_->origin.x - min_x_) / cell_, (mm.y - doc_->origin.y - min_y_) / cell_};
}

bool LodRaster::step(std::size_t max_motions) {
    if (doc_ == nullptr || width_ == 0) return true;
    const Document& doc = *doc_;
    const double tolerance_cells = std::max(kChordCells, kMinChordTolerance / cell_);
    const std::size_t stop = std::min(doc.motions.size(), next_ + max_motions);
    // The motions one after the other, in units: a motion starts where the one before ended (its end in units,
    // carried along) unless it is a jump (Document::start_of). Kept records (parabolas, points beyond 32 bits)
    // are flattened from their record.
    for (; next_ < stop; ++next_) {
        const Motion& m = doc.motions[next_];
        const auto bit = static_cast<std::uint8_t>(kind_bit(m.kind));
        const bool kept = (m.flags & Motion::kFlagKept) != 0;
        bool start_in_units = !(m.flags & Motion::kFlagJump) && last_in_units_;
        UnitPoint su = last_end_;
        if (!start_in_units && !kept) start_in_units = doc.to_units(doc.start_of(next_), su);
        last_in_units_ = !kept;
        if (!kept) last_end_ = m.end_units;
        if (start_in_units && m.curve == CurveKind::Line) {
            add_cells(cells_of(su), cells_of(m.end_units), bit);
            continue;
        }
        if (start_in_units && m.curve == CurveKind::Arc && !kept) {
            put_arc(next_, su, tolerance_cells, bit);
            continue;
        }
        scratch_.clear();
        flatten(doc.record(next_), tolerance_cells * cell_, scratch_, true);
        for (std::size_t k = 1; k < scratch_.size(); ++k)
            add_cells(to_cells(scratch_[k - 1]), to_cells(scratch_[k]), bit);
    }
    if (next_ < doc.motions.size()) return false;
    scratch_ = std::vector<Point>();
    doc_ = nullptr;
    return true;
}

// A compact arc without its whole record: the sweep from the interpreter's formula on its integer points (as
// Document::record), chords at most `tolerance` cells from the circle (the angle a chord may span is at least
// 2 sqrt(2 t / r), a little less than flatten's 2 acos(1 - t / r): a chord or two more, no arccosine), their
// points by turning the radius vector a fixed angle each step (no sine and cosine a point).
void LodRaster::put_arc(std::size_t i, UnitPoint su, double tolerance, std::uint8_t bit) {
    const Document& doc = *doc_;
    const Motion& m = doc.motions[i];
    const UnitPoint cu = doc.arc_centres[doc.arc_rank.rank(i)];
    const MotionMeasure arc =
        measure_arc(su.x, su.y, m.end_units.x, m.end_units.y, cu.x, cu.y, (m.flags & Motion::kFlagCcw) != 0);
    const Point s = cells_of(su), e = cells_of(m.end_units), c = cells_of(cu);
    const double r0 = arc.r0 * units_to_cells_, r1 = arc.r1 * units_to_cells_;
    const double r = std::max(r0, r1), sweep = std::abs(arc.sweep);
    int segments = 1;
    if (r > tolerance) segments = static_cast<int>(std::ceil(sweep / (2 * std::sqrt(2 * tolerance / r))));
    segments = std::min(std::max(segments, sweep > kPi ? 4 : 2), kMaxFlattenSegments);
    const double step = arc.sweep / segments, cs = std::cos(step), sn = std::sin(step);
    double ux = r0 > 0 ? (s.x - c.x) / r0 : 1, uy = r0 > 0 ? (s.y - c.y) / r0 : 0;  // unit vector centre -> point
    Point prev = s;
    for (int k = 1; k < segments; ++k) {
        const double nx = ux * cs - uy * sn;
        uy = ux * sn + uy * cs;
        ux = nx;
        const double rk = r0 + (r1 - r0) * k / segments;
        const Point p{c.x + rk * ux, c.y + rk * uy};
        add_cells(prev, p, bit);
        prev = p;
    }
    add_cells(prev, e, bit);
}

float LodRaster::progress() const {
    if (doc_ == nullptr || doc_->motions.empty()) return 1.f;
    return static_cast<float>(next_) / static_cast<float>(doc_->motions.size());
}

void LodRaster::begin(const Box& bbox, Point origin, int cells) {
    *this = LodRaster{};
    if (bbox.empty) return;
    const double w = bbox.max_x - bbox.min_x, h = bbox.max_y - bbox.min_y;
    const double longer = std::max(w, h);
    if (!(longer > 0)) return;
    cells_ = std::clamp(cells, kMinCells, kMaxCells);
    cell_ = longer / (cells_ - 2);  // a cell of border on each side
    // The corner is kept as a float (the shader's): rounded down, so that the box's own edge stays out of the
    // border cell.
    const auto below = [](double v) {
        const float f = static_cast<float>(v);
        return f > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
    };
    min_x_ = below(bbox.min_x - origin.x - cell_);
    min_y_ = below(bbox.min_y - origin.y - cell_);
    int lw = std::clamp(static_cast<int>(std::ceil(w / cell_)) + 2, 1, cells_);
    int lh = std::clamp(static_cast<int>(std::ceil(h / cell_)) + 2, 1, cells_);
    width_ = lw;
    height_ = lh;
    for (;;) {
        sizes_.emplace_back(lw, lh);
        if (lw == 1 && lh == 1) break;
        lw = std::max(1, lw / 2);  // the sizes of a complete mipmap chain
        lh = std::max(1, lh / 2);
    }
    data_.clear();
    data_.push_back(blank(width_, height_));
    const int rows = rows_for(width_);
    rows_.resize(static_cast<std::size_t>(height_));
    for (int y = 0; y < height_; ++y)
        rows_[static_cast<std::size_t>(y)] = data_[0][static_cast<std::size_t>(y / rows)].data() +
                                             static_cast<std::size_t>(y % rows) * static_cast<std::size_t>(width_);
}

std::vector<std::vector<std::uint8_t>> LodRaster::blank(int w, int h) {
    std::vector<std::vector<std::uint8_t>> strips;
    const int rows = rows_for(w);
    strips.reserve(static_cast<std::size_t>((h + rows - 1) / rows));
    for (int y = 0; y < h; y += rows)
        strips.emplace_back(static_cast<std::size_t>(w) * static_cast<std::size_t>(std::min(rows, h - y)),
                            std::uint8_t{0});
    return strips;
}

std::uint8_t LodRaster::at(int k, int x, int y) const {
    if (k < 0 || k >= static_cast<int>(data_.size()) || x < 0 || y < 0 || x >= width(k) || y >= height(k)) return 0;
    const int w = width(k), rows = rows_for(w);
    return data_[static_cast<std::size_t>(k)][static_cast<std::size_t>(y / rows)]
                [static_cast<std::size_t>(y % rows) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)];
}

void LodRaster::add_cells(Point a, Point b, std::uint8_t bit) {
    // Within one row or one column (a nest's straight edges, and most short segments): the run of cells from one
    // end's to the other's, without stepping.
    const double row = std::floor(a.y), column = std::floor(a.x);
    const bool in_row = row == std::floor(b.y);
    if (in_row || column == std::floor(b.x)) {
        const double along0 = in_row ? std::floor(std::min(a.x, b.x)) : std::floor(std::min(a.y, b.y));
        const double along1 = in_row ? std::floor(std::max(a.x, b.x)) : std::floor(std::max(a.y, b.y));
        const double across = in_row ? row : column;
        const int length = in_row ? width_ : height_, breadth = in_row ? height_ : width_;
        if (!(across >= 0 && across < breadth && along1 >= 0 && along0 < length)) return;  // (NaN: nothing)
        const int k = static_cast<int>(across);
        const int first = static_cast<int>(std::max(along0, 0.0)),
                  last = static_cast<int>(std::min(along1, length - 1.0));
        if (in_row) {
            std::uint8_t* cells = rows_[static_cast<std::size_t>(k)];
            for (int x = first; x <= last; ++x) cells[x] |= bit;
        } else {
            for (int y = first; y <= last; ++y) rows_[static_cast<std::size_t>(y)][k] |= bit;
        }
        return;
    }
    // Samples at most a cell apart along the longer axis: every cell the segment crosses gets the bit
    // (8-connected, as a one-pixel line is drawn). Stepped in 32.32 fixed point. (This loop is most of the time of
    // a big tape's level of detail: about one sample a cell crossed, 25 a motion of the generated nest at 822
    // cells. Tiles of 8 x 8 cells instead of rows, and skipping the store where the bit is set, were no faster.)
    const double span = std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
    const int n = static_cast<int>(std::min(span, static_cast<double>(2 * cells_))) + 1;
    constexpr double kOne = 4294967296.0;  // 2^32
    constexpr double kFar = 1e9;           // cells: far outside, and within the fixed point's range
    std::int64_t fx = static_cast<std::int64_t>(std::clamp(a.x, -kFar, kFar) * kOne);
    std::int64_t fy = static_cast<std::int64_t>(std::clamp(a.y, -kFar, kFar) * kOne);
    const std::int64_t sx = static_cast<std::int64_t>(std::clamp((b.x - a.x) / n, -kFar, kFar) * kOne);
    const std::int64_t sy = static_cast<std::int64_t>(std::clamp((b.y - a.y) / n, -kFar, kFar) * kOne);
    const auto w = static_cast<std::uint32_t>(width_), h = static_cast<std::uint32_t>(height_);
    std::uint8_t* const* rows = rows_.data();
    for (int i = 0; i <= n; ++i, fx += sx, fy += sy) {
        const auto cx = static_cast<std::uint32_t>(fx >> 32), cy = static_cast<std::uint32_t>(fy >> 32);
        if (cx < w && cy < h) rows[cy][cx] |= bit;  // (a negative cell is a large unsigned one)
    }
}

void LodRaster::finish() {
    if (width_ == 0 || finished_ || data_.empty()) return;
    data_.resize(sizes_.size());
    for (std::size_t k = 1; k < sizes_.size(); ++k) {
        const auto [pw, ph] = sizes_[k - 1];
        const auto [w, h] = sizes_[k];
        data_[k] = blank(w, h);
        auto& src = data_[k - 1];
        auto& dst = data_[k];
        for (int y = 0; y < ph; ++y)
            for (int x = 0; x < pw; ++x)
                // (an odd last row or column goes into the last cell)
                cell(dst, w, std::min(x / 2, w - 1), std::min(y / 2, h - 1)) |= cell(src, pw, x, y);
    }
    finished_ = true;
}

void LodRaster::release() {
    rows_ = std::vector<std::uint8_t*>();
    data_.clear();
    data_.shrink_to_fit();
}

std::size_t LodRaster::memory_bytes() const {
    std::size_t n = 0;
    for (const auto& level : data_)
        for (const auto& strip : level) n += strip.capacity();
    return n;
}

}  // namespace essi::viewer
