// A tape checked on two threads (essi::PipelinedCheck, essi/pipelined_check.hpp) and the viewer's document read so
// (web/app/DocumentLoader): the result of the check on one thread to the bit, in one run or in slices, the readers kept
// before each chunk those of a reader in place, the document the same to the byte, and a loader dropped mid-way stops
// its reading thread. The threads exist natively (and in the reading worker built with pthreads); under node the
// loader checks on one thread, and the tests of PipelinedCheck itself skip.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "../bench/nest_generator.hpp"
#include "app/DocumentLoader.hpp"
#include "app/DocumentWire.hpp"
#include "essi/dialect.hpp"
#include "essi/pipelined_check.hpp"
#include "essi/report_json.hpp"
#include "essi/threads.hpp"
#include "paths.hpp"

using namespace essi;
using essi::viewer::Document;
using essi::viewer::DocumentLoader;

namespace {

constexpr std::size_t kNeverTwo = std::numeric_limits<std::size_t>::max();

std::string diagnostics_json(const CheckResult& r) { return diagnostics_to_json(r.diagnostics).dump(); }

// The document of `bytes` on two threads from `two_threads_min_bytes` (0: always, where there are threads), in slices
// of `slice_ms`, its plan's findings in; `two_threads`: whether it was.
std::unique_ptr<Document> load(const std::string& bytes, std::size_t two_threads_min_bytes, bool plan_later,
                               bool& two_threads) {
    DocumentLoader loader("tape", bytes, setup_tape(bytes, std::nullopt, std::nullopt), plan_later,
                          two_threads_min_bytes);
    while (!loader.step(2)) {  // (short slices: the check is taken up again between them)
    }
    two_threads = loader.two_threads();
    std::unique_ptr<Document> doc = loader.take();
    while (!loader.step_plan(*doc, 2)) {
    }
    return doc;
}

}  // namespace

// Run in one go and in slices of one chunk, the check on two threads is check_tape's; the readers it keeps before each
// chunk go on as a reader in place does from there.
TEST(PipelinedCheck, GivesTheCheckOfOneThreadInOneRunOrInSlices) {
    if (!kHaveThreads) GTEST_SKIP() << "no threads in this build";
    const std::string bytes = bench::generate_nest_tape(std::size_t(1) << 20, 9);
    const Profile profile = *builtin_profile("iso6582");
    const CheckResult want = check_tape(bytes, profile);
    ASSERT_GT(want.stats.motions, 10000u);
    for (const bool slices : {false, true}) {
        SCOPED_TRACE(slices ? "in slices" : "in one run");
        TapeChecker checker(bytes, profile);
        std::vector<std::string> checkpoints;
        std::size_t runs = 0;
        {
            PipelinedCheck::Hooks hooks;
            hooks.keep_readers = true;
            hooks.chunk_read = [&](const Tape&, std::optional<TapeReader>& before) {
                checkpoints.push_back(before.has_value() ? before->checkpoint() : "");
            };
            PipelinedCheck pipeline(checker, TapeReader(bytes, profile), std::move(hooks), 4096);
            for (++runs; !pipeline.run([slices] { return !slices; });) ++runs;
        }
        const CheckResult got = checker.finish();
        EXPECT_EQ(stats_to_json(got.stats).dump(), stats_to_json(want.stats).dump());
        EXPECT_EQ(diagnostics_json(got), diagnostics_json(want));
        EXPECT_EQ(runs, slices ? checkpoints.size() + 1 : 1u);  // (one slice a chunk, and the last to see the end)
        TapeReader here(bytes, profile);
        Tape chunk;
        for (std::size_t k = 0; k < checkpoints.size(); ++k) {
            ASSERT_EQ(checkpoints[k], here.checkpoint()) << "chunk " << k;
            ASSERT_TRUE(here.read_chunk(chunk, 4096));
        }
        EXPECT_FALSE(here.read_chunk(chunk, 4096));
    }
}

// Dropped before its end, the check stops its reading thread where it is: before any chunk, after one, after a few.
TEST(PipelinedCheck, StopsWhereItIsWhenDropped) {
    if (!kHaveThreads) GTEST_SKIP() << "no threads in this build";
    const std::string bytes = bench::generate_nest_tape(std::size_t(1) << 20, 5);
    const Profile profile = *builtin_profile("iso6582");
    for (const int slices : {0, 1, 3}) {
        SCOPED_TRACE(slices);
        TapeChecker checker(bytes, profile);
        PipelinedCheck pipeline(checker, TapeReader(bytes, profile), {}, 1024);
        for (int k = 0; k < slices; ++k) EXPECT_FALSE(pipeline.run([] { return false; }));
    }
}

// The viewer's document checked on two threads is the one checked on one, to the byte (its chunks' readers among
// it), for a tape of many chunks and for examples with findings, arcs, parabolas and kerf; with the cut plan in the
// check and analysed after the reading (the viewer's way).
TEST(ViewerTwoThreads, TheDocumentIsTheOneCheckedOnOneThread) {
    std::vector<std::pair<std::string, std::string>> tapes{
        {"nest", bench::generate_nest_tape(std::size_t(1) << 20, 11)}};
    for (const char* name :
         {"plate_holes.esi", "bad_character.esi", "din66025_plate.eia", "parabola.esi", "bad_kerf_gouge.esi"})
        tapes.emplace_back(name, read_file(examples_dir() + "/" + name));
    for (const auto& [name, bytes] : tapes) {
        for (const bool plan_later : {false, true}) {
            SCOPED_TRACE(name + (plan_later ? ", plan later" : ""));
            bool two = false, one = true;
            const auto on_two = load(bytes, 0, plan_later, two);
            const auto on_one = load(bytes, kNeverTwo, plan_later, one);
            EXPECT_EQ(two, kHaveThreads);
            EXPECT_FALSE(one);
            EXPECT_TRUE(essi::viewer::encode_document(*on_two) == essi::viewer::encode_document(*on_one));
            EXPECT_EQ(essi::viewer::encode_diagnostics(on_two->diagnostics),
                      essi::viewer::encode_diagnostics(on_one->diagnostics));
            EXPECT_EQ(on_two->chunks.size(), on_one->chunks.size());
            EXPECT_EQ(on_two->motions.size(), on_one->motions.size());
        }
    }
}

// A tape of kPipelineMinBytes or more is checked on two threads by default, a smaller one on one.
TEST(ViewerTwoThreads, OnlyTapesOfAMegabyteOrMoreAreCheckedOnTwo) {
    const std::string big = bench::generate_nest_tape(kPipelineMinBytes, 5);
    const std::string small = read_file(examples_dir() + "/plate_holes.esi");
    ASSERT_GE(big.size(), kPipelineMinBytes);
    bool two = false;
    load(big, kPipelineMinBytes, false, two);
    EXPECT_EQ(two, kHaveThreads);
    load(small, kPipelineMinBytes, false, two);
    EXPECT_FALSE(two);
}

// A loader dropped mid-way (a new tape dropped meanwhile) takes its reading thread with it.
TEST(ViewerTwoThreads, ALoaderDroppedMidwayStopsItsReadingThread) {
    const std::string bytes = bench::generate_nest_tape(std::size_t(1) << 20, 5);
    for (const int slices : {0, 1, 3}) {
        SCOPED_TRACE(slices);
        DocumentLoader loader("tape", bytes, setup_tape(bytes, std::nullopt, std::nullopt), true, 0);
        for (int k = 0; k < slices; ++k) EXPECT_FALSE(loader.step(0));
    }
}
