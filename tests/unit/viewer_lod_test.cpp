// The viewer's level-of-detail raster (web/render/LodRaster): its size follows the tape (fewer cells for fewer
// motions, within the memory it may take), and every motion of a generated nest is in it: the cells of its end
// points have its kind's bit at the finest level and at every coarser level (each ORs 2 x 2 cells), pierces
// have theirs, and a cell far from every motion stays empty.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../bench/nest_generator.hpp"
#include "app/Document.hpp"
#include "viewer_util.hpp"
#include "essi/geom.hpp"
#include "essi/profile.hpp"
#include "render/LodRaster.hpp"

using namespace essi;
using essi::viewer::Document;
using essi::viewer::DocumentLoader;
using essi::viewer::LodRaster;

namespace {

std::unique_ptr<Document> load(const std::string& bytes) { return essi_test::load_document(bytes); }

// The cell of machine point p at level k (each level halves the cell index; an odd last row or column of the
// level below goes into the last cell).
std::pair<int, int> cell_of(const LodRaster& lod, const Document& d, Point p, int k) {
    const double fx = (p.x - d.origin.x - lod.min_x()) / lod.cell_mm(),
                 fy = (p.y - d.origin.y - lod.min_y()) / lod.cell_mm();
    int x = static_cast<int>(std::floor(fx)), y = static_cast<int>(std::floor(fy));
    for (int j = 1; j <= k; ++j) {
        x = std::min(x / 2, lod.width(j) - 1);
        y = std::min(y / 2, lod.height(j) - 1);
    }
    return {x, y};
}

}  // namespace

TEST(ViewerLod, CellsFollowTheMotionsWithinTheirShare) {
    // A square tape: cells^2 <= kCellsPerMotion x motions, between kMinCells and kMaxCells.
    EXPECT_EQ(LodRaster::cells_for(1000, 1000, 100000),
              static_cast<int>(std::sqrt(LodRaster::kCellsPerMotion * 100000)));
    EXPECT_EQ(LodRaster::cells_for(1000, 1000, 10000000), LodRaster::kMaxCells);
    EXPECT_EQ(LodRaster::cells_for(1000, 1000, 100), LodRaster::kMinCells);
    // A 2:1 plate of 150 000 motions: twice the cells on the longer side for the same bytes.
    const int c = LodRaster::cells_for(3000, 1500, 150000);
    EXPECT_EQ(c, static_cast<int>(std::sqrt(LodRaster::kCellsPerMotion * 150000 * 2)));
    EXPECT_LE(static_cast<double>(c) * (c / 2), LodRaster::kCellsPerMotion * 150000);
}

TEST(ViewerLod, EveryMotionIsInEveryLevel) {
    const auto doc = load(bench::generate_nest_tape(2u << 20, 5));
    const Document& d = *doc;
    ASSERT_GT(d.motions.size(), 100000u);
    LodRaster lod;
    lod.begin(d);
    ASSERT_TRUE(lod.active());
    const int cells = LodRaster::cells_for(d.bbox.max_x - d.bbox.min_x, d.bbox.max_y - d.bbox.min_y, d.motions.size());
    EXPECT_EQ(std::max(lod.width(), lod.height()), cells);
    // (plus the border: a cell on each side)
    EXPECT_LE(static_cast<double>(lod.width()) * lod.height(),
              LodRaster::kCellsPerMotion * static_cast<double>(d.motions.size()) + 2.0 * (lod.width() + lod.height()));
    EXPECT_LT(cells, LodRaster::kMaxCells);
    std::size_t steps = 0;
    while (!lod.step(4096)) ++steps;
    EXPECT_GT(steps, 10u);
    lod.finish();
    ASSERT_GT(lod.levels(), 8);
    EXPECT_GT(lod.strips(0).size(), 4u);  // held in strips, not one block
    std::size_t bytes = 0;
    for (int k = 0; k < lod.levels(); ++k) {
        std::size_t n = 0;
        for (const auto& s : lod.strips(k)) n += s.size();
        EXPECT_EQ(n, static_cast<std::size_t>(lod.width(k)) * static_cast<std::size_t>(lod.height(k))) << "level " << k;
        bytes += n;
    }
    EXPECT_EQ(lod.memory_bytes(), bytes);
    for (std::size_t i = 0; i < d.motions.size(); i += 7) {
        const auto bit = static_cast<std::uint8_t>(1u << static_cast<int>(d.motions[i].kind));
        for (int k = 0; k < lod.levels(); ++k) {
            for (const Point p : {d.start_of(i), d.end_of(i)}) {
                const auto [x, y] = cell_of(lod, d, p, k);
                ASSERT_TRUE(lod.at(k, x, y) & bit) << "motion " << i << " level " << k << " cell " << x << "," << y;
            }
        }
    }
    // Along every arc (drawn from chords a quarter cell from it): its points at a quarter, half and three quarters
    // of the way are in or next to a cell with the bit, at the finest level.
    std::size_t arcs = 0;
    for (std::size_t i = 0; i < d.motions.size(); ++i) {
        if (d.motions[i].curve != CurveKind::Arc) continue;
        ++arcs;
        const MotionRecord r = d.record(i);
        const auto bit = static_cast<std::uint8_t>(1u << static_cast<int>(r.kind));
        for (const double f : {0.25, 0.5, 0.75}) {
            const auto [x, y] = cell_of(lod, d, point_at(r, f), 0);
            bool near = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) near = near || (lod.at(0, x + dx, y + dy) & bit) != 0;
            ASSERT_TRUE(near) << "arc " << i << " at " << f << ": cell " << x << "," << y;
        }
    }
    EXPECT_GT(arcs, 10000u);
    for (const std::uint32_t i : d.pierces) {
        const auto [x, y] = cell_of(lod, d, d.start_of(i), 0);
        ASSERT_TRUE(lod.at(0, x, y) & LodRaster::kPierceBit) << "pierce at motion " << i;
    }
    // The border cells (one on each side, outside the motions' box) are empty.
    EXPECT_EQ(lod.at(0, 0, 0), 0);
    EXPECT_EQ(lod.at(0, lod.width() - 1, lod.height() - 1), 0);
    lod.release();
    EXPECT_EQ(lod.memory_bytes(), 0u);
}
