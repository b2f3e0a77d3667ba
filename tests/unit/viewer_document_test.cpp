// The viewer's compact document (web/app/Document): what it rebuilds from 16 bytes a motion, the arc centres and
// the change lists is the interpreter's record to the last bit, and the blocks it reads again for a line are the
// blocks read_tape gives that line. Over every example, the real-tape corpus and a generated tape of many chunks.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../bench/nest_generator.hpp"
#include "app/Describe.hpp"
#include "app/Document.hpp"
#include "viewer_util.hpp"
#include "essi/interp.hpp"
#include "essi/read.hpp"
#include "essi/pipeline.hpp"
#include "paths.hpp"
#include "test_util.hpp"

using namespace essi;
using essi::viewer::Document;
using essi::viewer::DocumentLoader;
using essi::viewer::LineBlocks;
using essi_test::expect_same_record;
using essi_test::RecordMatch;
using essi_test::split_lines;
using essi_test::tricky_lines_text;

namespace {

std::unique_ptr<Document> load(const std::string& bytes, const Profile& p) {
    return essi_test::load_document(bytes, p);
}

void expect_same_records(const Document& doc, const std::vector<MotionRecord>& want, const std::string& what) {
    ASSERT_EQ(doc.motions.size(), want.size()) << what;
    for (std::size_t i = 0; i < want.size(); ++i) {
        const MotionRecord r = doc.record(i);
        const MotionRecord& w = want[i];
        const std::string at = what + " motion " + std::to_string(i) + " line " + std::to_string(w.line);
        expect_same_record(r, w, at, RecordMatch::ViewerDocument);  // exactly: the interpreter's doubles
        if (::testing::Test::HasFatalFailure()) return;
        ASSERT_EQ(doc.start_of(i), w.start) << at;
        ASSERT_EQ(doc.end_of(i), w.end) << at;
        if (w.curve == CurveKind::Arc) {
            ASSERT_EQ(doc.arc_centre(i), w.centre) << at;
        }
    }
}

void expect_same_blocks(const Document& doc, const Tape& want, const std::string& what) {
    ASSERT_EQ(doc.blocks, want.size()) << what;
    std::size_t b = 0;
    for (std::uint32_t line = 1; line <= doc.line_count() + 1; ++line) {
        const LineBlocks got = doc.blocks_of_line(line);
        const std::size_t first = b;
        while (b < want.size() && want.block(b).line == line) ++b;
        const std::string at = what + " line " + std::to_string(line);
        ASSERT_EQ(got.last - got.first, b - first) << at;
        for (std::size_t k = got.first; k < got.last; ++k) {
            const std::size_t t = got.tape_index(k);
            ASSERT_EQ(t, first + (k - got.first)) << at;
            const Block& g = got.chunk->block(k);
            const Block& w = want.block(t);
            ASSERT_EQ(g.offset, w.offset) << at;
            ASSERT_EQ(g.kind, w.kind) << at;
            ASSERT_EQ(g.code, w.code) << at;
            ASSERT_EQ(g.packed, w.packed) << at;
            const auto gw = got.chunk->words(k), ww = want.words(t);
            ASSERT_TRUE(std::equal(gw.begin(), gw.end(), ww.begin(), ww.end())) << at;
        }
    }
    ASSERT_EQ(b, want.size()) << what;
}

void check_tape(const std::string& bytes, const Profile& p, const std::string& what) {
    const auto doc = load(bytes, p);
    const Tape tape = read_tape(bytes, p);
    essi_test::RecordingSink sink;
    std::vector<Diagnostic> diagnostics;
    interpret(tape, bytes, p, sink, diagnostics);
    expect_same_records(*doc, sink.motions, what);
    expect_same_blocks(*doc, tape, what);
    for (std::size_t i = 0; i < doc->motions.size(); ++i) {
        const std::size_t block = doc->block_of(i);
        ASSERT_EQ(tape.block(block).line, doc->motions[i].line) << what << " motion " << i;
    }
}

std::vector<std::filesystem::path> tapes_in(const std::string& dir) {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file() && e.path().extension() != ".json" && e.path().extension() != ".trace")
            out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(ViewerDocument, ExamplesRebuildTheInterpretersRecordsAndBlocks) {
    std::size_t tapes = 0;
    for (const auto& path : tapes_in(examples_dir())) {
        if (path.extension() != ".esi") continue;
        ++tapes;
        const std::string name = path.filename().string();
        std::filesystem::path expected = path;
        expected.replace_extension(".expected.json");
        const bool woyda =
            std::filesystem::exists(expected) && read_file(expected.string()).find("\"woyda\"") != std::string::npos;
        const Profile p = *builtin_profile(woyda ? "woyda" : "iso6582");
        check_tape(read_file(path.string()), p, name);
    }
    EXPECT_GE(tapes, 10u);
}

TEST(ViewerDocument, CorpusRebuildsTheInterpretersRecordsAndBlocks) {
    const auto dir = corpus_dir();
    if (!dir) GTEST_SKIP() << "no corpus";
    for (const auto& path : tapes_in(*dir))
        check_tape(read_file(path.string()), *builtin_profile("iso6582"), path.string());
}

TEST(ViewerDocument, GeneratedTapeOfManyChunks) {
    const std::string bytes = bench::generate_nest_tape(1 << 20, 7);
    const auto doc = load(bytes, *builtin_profile("iso6582"));
    EXPECT_GT(doc->chunks.size(), 3u);
    EXPECT_TRUE(doc->kept.empty());  // every point in whole units: nothing kept whole
    check_tape(bytes, *builtin_profile("iso6582"), "generated");
}

// The source lines, split one byte at a time: a line ends at CR, LF, CR LF or LF CR.
TEST(ViewerDocument, LinesAreTheTapesLines) {
    // The document's lines are the line index's, built over the load's frames (essi/lines.hpp has the rule).
    const std::string text = tricky_lines_text();
    for (const std::string& t : {text, text + "\n", bench::generate_nest_tape(100000, 2)}) {
        const auto doc = load(t, *builtin_profile("iso6582"));
        const auto want = split_lines(t);
        ASSERT_EQ(doc->line_count(), want.size());
        for (std::size_t n = 1; n <= want.size(); ++n) ASSERT_EQ(doc->line(n), want[n - 1]) << "line " << n;
        EXPECT_EQ(doc->line(want.size() + 1), "");
    }
}

TEST(ViewerDocument, PlacementGivesTheSameRecords) {
    // The motion stream is in program coordinates: a zero offset and a turned plate change no record.
    Profile p = *builtin_profile("iso6582");
    p.zero_offsets["G54"] = {-12.5, 40};
    p.plate_rotation_deg = 2;
    check_tape(bench::generate_nest_tape(200000, 5), p, "generated, placed on the machine");
}

TEST(ViewerDocument, PointsBeyondThirtyTwoBitsKeepTheirRecord) {
    // 30 x 99 999 999 units is past int32: those motions keep their full record (and the first one back, which
    // starts out there).
    std::string bytes = "81\n";
    for (int k = 0; k < 30; ++k) bytes += "+99999999+0\n";
    for (int k = 0; k < 30; ++k) bytes += "-99999999+0\n";
    bytes += "+10+0\n+0+0+0+10+\n63\n";
    const auto doc = load(bytes, *builtin_profile("iso6582"));
    EXPECT_GE(doc->kept.size(), 10u);
    EXPECT_LT(doc->kept.size(), 40u);
    check_tape(bytes, *builtin_profile("iso6582"), "far");
}

TEST(ViewerDocument, MemoryPerMotionIsCompact) {
    const std::string bytes = bench::generate_nest_tape(1 << 20, 3);
    const auto doc = load(bytes, *builtin_profile("iso6582"));
    // The viewer's memory budget: 2 x the bytes + what the core's Tape of the tape holds.
    EXPECT_LT(doc->memory_bytes(), 2 * bytes.size() + doc->core_tape_bytes());
}

TEST(ViewerDocument, MotionBlocksAreDescribedByTheirWordNames) {
    const std::string text = "+100-1673\n+0+1778+948+889-\n+800+400+200+400+-\n19\n2+30+40\n63\n";
    const Profile p = *builtin_profile("iso6582");
    const Tape tape = read_tape(text, p);
    ASSERT_GE(tape.size(), 5u);
    EXPECT_EQ(viewer::describe_block(tape, 0, p), "motion block, 2 words: DX +100, DY -1673 (unit increments)");
    EXPECT_EQ(viewer::describe_block(tape, 1, p),
              "motion block, 5 words: DX +0, DY +1778, XC +948, YC +889, TC - (clockwise) (unit increments)");
    EXPECT_EQ(viewer::describe_block(tape, 2, p),
              "motion block, 6 words: DX +800, DY +400, XP +200, YP +400, TC + (counter-clockwise), TP - (axis "
              "parallel to X) (unit increments)");
    EXPECT_EQ(viewer::describe_block(tape, 4, p), "motion block, 2 words: DX +30, DY +40 (unit increments); head 2");
}
