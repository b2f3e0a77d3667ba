// The cut plan fed a chunk's stream at a time from MotionBuffers, later than the chunks are interpreted
// (TapeChecker::check_chunk with a buffer, then feed_plan: the pipelined check's way, here on one thread): the same
// result as check_tape, to the bit.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "essi/motion.hpp"
#include "essi/pipeline.hpp"
#include "essi/report_json.hpp"
#include "../bench/nest_generator.hpp"
#include "test_util.hpp"

namespace {

using essi::CheckResult;
using essi::MotionBuffer;

// What a sink was fed, one line of text an item: the kind and a few fields that tell the items apart.
class Transcript final : public essi::MotionSink {
public:
    void on_motion(const essi::MotionRecord& m) override {
        items.push_back("motion " + std::to_string(m.line) + " " + std::to_string(m.end.x));
    }
    void on_event(const essi::MachineEvent& e) override {
        items.push_back("event " + std::to_string(e.line) + " " + std::to_string(e.code));
    }
    void on_line(const essi::UnitLine& l) override {
        items.push_back("line " + std::to_string(l.line) + " " + std::to_string(l.end_x));
    }
    std::vector<std::string> items;
};

// The nest with every 29 and 30 swapped: a finding of the cut plan on every part and hole (E602), plates.
std::string swapped_nest() {
    const std::string nest = essi::bench::generate_nest_tape(200000, 3);
    std::string out;
    std::size_t at = 0;
    while (at < nest.size()) {
        std::size_t end = nest.find('\n', at);
        end = end == std::string::npos ? nest.size() : end + 1;
        const std::string_view line(nest.data() + at, end - at);
        const std::string_view code = line.substr(0, 2);
        const bool swap = (code == "29" || code == "30") &&
                          (line.size() == 2 || std::string_view("+-\r\n").find(line[2]) != std::string_view::npos);
        out += swap ? std::string_view(code == "29" ? "30" : "29") : code;
        out += line.substr(code.size());
        at = end;
    }
    return out;
}

// Checks `tape` in chunks of `chunk_blocks`, each chunk's stream for the plan kept in one of `ring` buffers and fed
// to the plan `lag` chunks later (the pipelined check's reading thread feeds it when it has time).
CheckResult check_with_plan_fed_late(std::string_view tape, const essi::Profile& profile, std::size_t chunk_blocks,
                                     std::size_t ring, std::size_t lag, bool parts = false) {
    essi::TapeChecker checker(tape, profile);
    if (parts) checker.find_parts();
    essi::TapeReader reader(tape, profile);
    essi::Tape chunk;
    std::vector<MotionBuffer> buffers(ring);
    std::size_t checked = 0, fed = 0;
    while (reader.read_chunk(chunk, chunk_blocks)) {
        if (checked - fed == ring) checker.feed_plan(buffers[fed++ % ring]);  // (the ring is full: room first)
        checker.check_chunk(chunk, {}, buffers[checked++ % ring]);
        while (checked - fed > lag) checker.feed_plan(buffers[fed++ % ring]);
    }
    while (fed < checked) checker.feed_plan(buffers[fed++ % ring]);
    return checker.finish();
}

std::string parts_json(const CheckResult& r) {
    std::string out;
    if (r.parts) essi::write_parts_member_json(*r.parts, "parts", 1, 0, [&](std::string_view s) { out += s; });
    return out;
}

}  // namespace

TEST(MotionBuffer, ReplaysWhatItKeptInOrder) {
    MotionBuffer buffer;
    EXPECT_TRUE(buffer.empty());
    essi::UnitLine l1, l2;
    l1.line = 3;
    l1.end_x = 100;
    l2.line = 6;
    l2.end_x = -7;
    essi::MotionRecord m;
    m.line = 4;
    m.end = {12.5, 0};
    essi::MachineEvent e;
    e.line = 5;
    e.code = 7;
    buffer.on_line(l1);
    buffer.on_motion(m);
    buffer.on_event(e);
    buffer.on_line(l2);
    EXPECT_EQ(buffer.size(), 4u);
    EXPECT_GE(buffer.memory_bytes(), 2 * sizeof(essi::UnitLine) + sizeof(essi::MotionRecord));
    Transcript got;
    buffer.replay(got);
    EXPECT_EQ(got.items, (std::vector<std::string>{"line 3 100", "motion 4 12.500000", "event 5 7", "line 6 -7"}));
    buffer.replay(got);  // (replaying keeps what it holds)
    EXPECT_EQ(got.items.size(), 8u);
    buffer.clear();
    EXPECT_TRUE(buffer.empty());
    EXPECT_EQ(buffer.size(), 0u);
    Transcript none;
    buffer.replay(none);
    EXPECT_TRUE(none.items.empty());
}

TEST(TapeCheckerPlanFeed, PlanFedChunksLaterGivesTheCheck) {
    const essi::Profile profile;
    const std::string tape = swapped_nest();
    const CheckResult direct = essi::check_tape(tape, profile);
    std::size_t plan_findings = 0;
    for (const essi::Diagnostic& d : direct.diagnostics)
        plan_findings += d.code == essi::DiagCode::E602_KerfIntoPart ? 1 : 0;
    ASSERT_GE(plan_findings, 50u);  // (a tape whose plan has something to compare)
    // (small chunks: plates and cuts end in a chunk whose stream the plan gets later)
    for (const auto& [blocks, ring, lag] :
         {std::tuple{64u, 3u, 2u}, std::tuple{97u, 4u, 0u}, std::tuple{16384u, 4u, 3u}})
        essi_test::expect_same_result(
            check_with_plan_fed_late(tape, profile, blocks, ring, lag), direct,
            "chunks of " + std::to_string(blocks) + ", fed " + std::to_string(lag) + " chunks later");
}

TEST(TapeCheckerPlanFeed, PartsFromAPlanFedLaterAreThePartsOfTheCheck) {
    const essi::Profile profile;
    const std::string tape = essi::bench::generate_nest_tape(100000, 5);
    const CheckResult direct = essi::check_tape(tape, profile, essi::InputFormat::Essi, static_cast<std::size_t>(-1),
                                                /*parts*/ true);
    ASSERT_TRUE(direct.parts.has_value());
    EXPECT_GE(direct.parts->parts.size(), 10u);
    const CheckResult later = check_with_plan_fed_late(tape, profile, 64, 3, 2, /*parts*/ true);
    essi_test::expect_same_result(later, direct, "parts, chunks of 64");
    EXPECT_EQ(parts_json(later), parts_json(direct));
}
