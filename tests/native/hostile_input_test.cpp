// Hostile input that only a native test can afford: inputs of gigabytes (the WASM build has no room for them).
// Each case fails on the code before its fix.
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "../unit/test_util.hpp"
#include "essi/pipeline.hpp"
#include "file_io.hpp"
#include "temp_dir.hpp"

#include <filesystem>
#include <fstream>

namespace {

using essi::DiagCode;
using essi_test::count_code;

// More digits than an int counts: 2^31 + 3. The digit counters of the reader overflowed (UBSan: signed integer
// overflow), and the word then read as its first nine digits: a tape that was "ok" with a wrong coordinate.
constexpr std::size_t kGiantDigits = (std::size_t(1) << 31) + 3;

TEST(HostileInput, AWordOfTwoBillionDigitsIsE104NotAWrongCoordinate) {
    std::string tape = "+";
    tape.append(kGiantDigits, '7');
    tape += "+0\n64\n";
    const essi::CheckResult r = essi::check_tape(tape, *essi::builtin_profile("iso6582"));
    EXPECT_EQ(count_code(r.diagnostics, DiagCode::E104_NumberTooLarge), 1u);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.stats.motions, 0u);
    for (const essi::Diagnostic& d : r.diagnostics)
        EXPECT_LT(essi::diagnostic_message(d, essi::Lang::En).size(), 300u)
            << essi::diagnostic_message(d, essi::Lang::En).substr(0, 300);

    // The same digits as a leading number: a function code of more than 3 digits (E103, was E105), and its
    // message quotes the start of the number, not 2 GB of it.
    tape[0] = '1';
    const essi::CheckResult f = essi::check_tape(tape, *essi::builtin_profile("iso6582"));
    EXPECT_EQ(count_code(f.diagnostics, DiagCode::E103_FunctionCodeTooLong), 1u);
    EXPECT_EQ(count_code(f.diagnostics, DiagCode::E105_WordCount), 0u);
    for (const essi::Diagnostic& d : f.diagnostics)
        EXPECT_LT(essi::diagnostic_message(d, essi::Lang::En).size(), 300u)
            << essi::diagnostic_message(d, essi::Lang::En).substr(0, 300);
}

// A tape truncated while it is checked: a reader that mapped the file would touch pages that no longer exist and
// die of SIGBUS (rc 135, no message, the batch lost). The file is read, not mapped: the bytes read stay the bytes
// checked. Both buffers: the heap's for a small file, a mapping of huge pages from kHugePageBufferBytes (4 MB) on.
TEST(HostileInput, ATapeTruncatedWhileItIsCheckedIsCheckedAsItWasRead) {
    const std::filesystem::path dir = temp_dir("truncated");
    const std::filesystem::path file = dir / "t.esi";
    for (const std::size_t motions : {200000u, 1000000u}) {
        SCOPED_TRACE(std::to_string(motions) + " motions");
        std::string tape;
        for (std::size_t i = 0; i < motions; ++i) tape += "+10+0\n";
        tape += "64\n";
        std::ofstream(file) << tape;
        const essi::native::ReadResult r = essi::native::read_whole_file(file.string());
        ASSERT_TRUE(r.ok) << r.error;
        std::filesystem::resize_file(file, 0);
        EXPECT_TRUE(r.bytes == tape);
        const essi::CheckResult c = essi::check_tape(r.bytes, *essi::builtin_profile("iso6582"));
        EXPECT_TRUE(c.ok());
        EXPECT_EQ(c.stats.motions, motions);
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
