// Tape::append: a tape read a chunk at a time (TapeReader) and appended chunk by chunk equals the tape
// read at once (read_tape): blocks, words (through the sparse index and the cursor), diagnostics, end.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "../bench/nest_generator.hpp"
#include "essi/read.hpp"
#include "paths.hpp"
#include "test_util.hpp"

using namespace essi;

namespace {

Tape read_appended(std::string_view bytes, const Profile& p, std::size_t chunk_blocks, bool reserve = false) {
    Tape whole;
    if (reserve) whole.reserve(1000, 2000);
    TapeReader reader(bytes, p);
    Tape chunk;
    while (reader.read_chunk(chunk, chunk_blocks)) whole.append(chunk);
    whole.shrink_to_fit();
    return whole;
}

// Program blocks counted the plain way: blocks before the end that are not comment lines.
std::size_t count_program_blocks(const Tape& t) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < t.end_block(); ++i) n += t.block(i).kind != BlockKind::Comment;
    return n;
}

void expect_same(const Tape& a, const Tape& b, const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    EXPECT_EQ(a.program_blocks(), count_program_blocks(a)) << what;
    EXPECT_EQ(b.program_blocks(), count_program_blocks(b)) << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Block& x = a.block(i);
        const Block& y = b.block(i);
        ASSERT_TRUE(x.offset == y.offset && x.line == y.line && x.code == y.code && x.kind == y.kind &&
                    x.packed == y.packed)
            << what << ": block " << i;
        const auto wa = a.words(i), wb = b.words(i);
        ASSERT_TRUE(std::equal(wa.begin(), wa.end(), wb.begin(), wb.end())) << what << ": words of block " << i;
    }
    const auto all_a = a.all_words(), all_b = b.all_words();
    EXPECT_TRUE(std::equal(all_a.begin(), all_a.end(), all_b.begin(), all_b.end()))
        << what;  // (Emscripten's libc++ has no ranges::equal)
    Tape::WordCursor ca(a), cb(b);
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto wa = ca.next(i), wb = cb.next(i);
        ASSERT_TRUE(std::equal(wa.begin(), wa.end(), wb.begin(), wb.end())) << what << ": cursor at block " << i;
    }
    EXPECT_EQ(a.end_block(), b.end_block()) << what;
    EXPECT_EQ(a.has_program_end(), b.has_program_end()) << what;
    EXPECT_EQ(a.first_block(), b.first_block()) << what;
    ASSERT_EQ(a.diagnostics().size(), b.diagnostics().size()) << what << "\n" << essi_test::dump(a.diagnostics());
    for (std::size_t i = 0; i < a.diagnostics().size(); ++i) {
        EXPECT_EQ(a.diagnostics()[i].code, b.diagnostics()[i].code) << what;
        EXPECT_EQ(a.diagnostics()[i].line, b.diagnostics()[i].line) << what;
        EXPECT_EQ(a.diagnostics()[i].column, b.diagnostics()[i].column) << what;
    }
}

}  // namespace

TEST(TapeAppend, EmptyTapeStaysEmpty) {
    const Profile p;
    const Tape t = read_appended("", p, 8);
    const Tape w = read_tape("", p);
    expect_same(t, w, "empty");
    EXPECT_EQ(t.size(), 0u);
}

TEST(TapeAppend, SmallTapeAnyChunkSize) {
    const Profile p;
    const std::string text =
        "3\r\nheader\r\n4\r\n39+1000\r\n5\r\n+100+0\r\n6\r\n29\r\n7\r\n+100+0\r\n+0+100-50+0+\r\n"
        "8\r\n38\r\n64\r\n+1+1\r\n";
    const Tape whole = read_tape(text, p);
    ASSERT_TRUE(whole.has_program_end());
    ASSERT_LT(whole.end_block(), whole.size() + 1);
    for (std::size_t n : {1u, 2u, 3u, 5u, 64u, 1000u})
        expect_same(read_appended(text, p, n), whole, "chunk " + std::to_string(n));
}

TEST(TapeAppend, TapeWithoutEndAndWithErrors) {
    const Profile p;
    const std::string text = "7\n+100+0\nX12\n+1+2+3\n8\n+5+5\n";
    const Tape whole = read_tape(text, p);
    EXPECT_FALSE(whole.has_program_end());
    EXPECT_FALSE(whole.diagnostics().empty());
    for (std::size_t n : {1u, 2u, 4u}) expect_same(read_appended(text, p, n), whole, "chunk " + std::to_string(n));
}

TEST(TapeAppend, GeneratedNestTapeAcrossManyIndexStrides) {
    const Profile p;
    const std::string text = essi::bench::generate_nest_tape(300'000, 5);
    const Tape whole = read_tape(text, p);
    ASSERT_GT(whole.size(), 10 * Tape::kWordIndexStride);
    // Chunk sizes that are and are not multiples of the word index stride.
    for (std::size_t n : {63u, 64u, 100u, 8192u})
        expect_same(read_appended(text, p, n), whole, "chunk " + std::to_string(n));
    expect_same(read_appended(text, p, 100, true), whole, "reserved first");
}

TEST(TapeAppend, EveryExampleTape) {
    namespace fs = std::filesystem;
    const Profile p;
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(examples_dir())) {
        if (e.path().extension() != ".esi") continue;
        const std::string text = read_file(e.path().string());
        const Tape whole = read_tape(text, p);
        for (std::size_t c : {1u, 7u, 4096u})
            expect_same(read_appended(text, p, c), whole, e.path().filename().string());
        ++n;
    }
    EXPECT_GT(n, 3u);
}

namespace {

TEST(TapeReader, ACopyGoesOnFromWhereTheOriginalIs) {
    // The viewer keeps a copy of the reader before each chunk to read that chunk again: the copy (BlockReader's
    // clone) must read exactly what the original reads from there on.
    const std::string bytes = essi::bench::generate_nest_tape(60000, 4) + "\n3\nNOTE\n4\n+1+1\n63\n%\n";
    const Profile p = *builtin_profile("iso6582");
    TapeReader reader(bytes, p);
    Tape chunk;
    ASSERT_TRUE(reader.read_chunk(chunk, 500));
    ASSERT_TRUE(reader.read_chunk(chunk, 500));
    TapeReader copy = reader;
    EXPECT_EQ(copy.state_bytes(), reader.state_bytes());
    EXPECT_GT(reader.state_bytes(), sizeof(TapeReader));
    Tape from_original, from_copy;
    while (reader.read_chunk(chunk, 700)) from_original.append(chunk);
    while (copy.read_chunk(chunk, 300)) from_copy.append(chunk);
    ASSERT_GT(from_original.size(), 1000u);
    expect_same(from_original, from_copy, "after two chunks");
}

TEST(TapeReader, TheEssiFrontEndIsTheDefault) {
    const std::string bytes = "%\n7\n+100+0\n+0+100+0+50-\n8\n63\n";
    const Profile p = *builtin_profile("iso6582");
    expect_same(read_tape(bytes, p, InputFormat::Essi), read_tape(bytes, p), "whole");
    Tape chunk, appended;
    const auto front_end = make_block_reader(InputFormat::Essi, bytes, p);
    while (front_end->read_chunk(chunk, 2)) appended.append(chunk);
    expect_same(appended, read_tape(bytes, p), "chunks of 2");
}

}  // namespace
