// The viewer's kerf layers (web/render/PathBuffers.cpp) and the inspector's second position
// (Document::torch_path_of_line): the compensated path the core makes (essi::KerfPath), as segments of their own
// kinds beside the motions', and nothing of it for a tape without compensation.
#include <gtest/gtest.h>

#include <string>

#include "app/Document.hpp"
#include "viewer_util.hpp"
#include "app/Layers.hpp"
#include "essi/trace.hpp"
#include "paths.hpp"
#include "render/PathBuffers.hpp"
#include "test_util.hpp"

using namespace essi;
using essi::viewer::Document;
using essi::viewer::DocumentLoader;
using essi::viewer::PathBuffers;

namespace {

std::unique_ptr<Document> load_example(const std::string& name) {
    return essi_test::load_document(read_file(examples_dir() + "/" + name));
}

struct Counts {
    std::size_t kerf = 0, band = 0;
};
Counts build(const Document& doc, PathBuffers& b) {
    b.begin(doc, 0.01);
    while (!b.step(1000)) {
    }
    Counts c;
    for (std::uint8_t k : b.staged_kinds) {
        c.kerf += k == viewer::kKerfPathKind;
        c.band += k >= viewer::kKerfBandKind;
    }
    return c;
}

TEST(ViewerKerf, CompensatedTapeGetsTheTorchPathAndTheBand) {
    const auto doc = load_example("kerf_parts.esi");
    PathBuffers b;
    const Counts c = build(*doc, b);
    EXPECT_GT(c.kerf, 20u);
    EXPECT_GT(c.band, 20u);
    EXPECT_EQ(c.kerf + c.band, b.kerf_segments);
    ASSERT_EQ(b.kerf_width_count, 1u);
    EXPECT_FLOAT_EQ(b.kerf_widths[0], 3.0f);  // 29+30: 3 mm
    // The kerf path's segments end where essi trace --kerf's pieces do: the first cut piece's end is among them.
    std::string trace;
    (void)trace_tape(
        doc->bytes, doc->profile, [&](std::string_view s) { trace += s; }, InputFormat::Essi, 3,
        TraceView{true, false});
    EXPECT_NE(trace.find("->(198.500,210.000)"), std::string::npos) << trace;  // the entry's trimmed end
    bool found = false;
    for (std::size_t s = 0; s < b.staged_kinds.size() && !found; ++s) {
        if (b.staged_kinds[s] != viewer::kKerfPathKind) continue;
        const float x = b.staged_ends[4 * s + 2] + static_cast<float>(doc->origin.x);
        const float y = b.staged_ends[4 * s + 3] + static_cast<float>(doc->origin.y);
        found = std::abs(x - 198.5f) < 1e-3f && std::abs(y - 210.f) < 1e-3f;
    }
    EXPECT_TRUE(found) << "no kerf segment ends at the entry's trimmed end (198.5, 210)";
}

TEST(ViewerKerf, NoCompensationNoKerfSegments) {
    const auto doc = load_example("arcs_both_senses.esi");
    PathBuffers b;
    const Counts c = build(*doc, b);
    EXPECT_EQ(c.kerf + c.band, 0u);
    EXPECT_EQ(b.kerf_segments, 0u);
    EXPECT_TRUE(doc->torch_path_of_line(5).empty());
}

TEST(ViewerKerf, InspectorHasTheTorchsPositionOfALine) {
    const auto doc = load_example("kerf_parts.esi");
    // line 15: +0+800, the left side of part A (kerf left, 1.5 mm): the torch runs 1.5 mm further left
    const auto torch = doc->torch_path_of_line(15);
    ASSERT_FALSE(torch.empty());
    EXPECT_NEAR(torch.front().start.x, 198.5, 1e-9);
    EXPECT_NEAR(torch.front().end.x, 198.5, 1e-9);
    EXPECT_NEAR(torch.front().end.y, 290.0, 1e-9);
    // a line before any compensation: none
    EXPECT_TRUE(doc->torch_path_of_line(10).empty());
}

TEST(ViewerKerf, LayersMaskHasTheKerfBits) {
    viewer::Layers l;
    EXPECT_EQ(l.kind_mask(), viewer::kAllPathMask);
    l.kerf = false;
    EXPECT_EQ(l.kind_mask() & viewer::kKerfPathBit, 0);
    EXPECT_NE(l.kind_mask() & viewer::kKerfBandBit, 0);
}

}  // namespace
