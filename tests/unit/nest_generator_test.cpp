// The benchmark's nesting-tape generator (tests/bench/nest_generator.hpp) must produce valid tapes:
// the benchmarks measure a tape that checks with no error, natively and under WASM.
#include <gtest/gtest.h>

#include <string>

#include "../bench/nest_generator.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"

namespace {

using essi::bench::generate_nest_tape;
using essi::bench::LineEnding;

std::string first_errors(const essi::CheckResult& r, std::size_t max = 5) {
    std::string s;
    for (const auto& d : r.diagnostics) {
        if (d.severity != essi::Severity::Error) continue;
        s += essi::code_name(d.code) + " line " + std::to_string(d.line) + ":" + std::to_string(d.column) + " " +
             essi::diagnostic_message(d, essi::Lang::En) + "\n";
        if (--max == 0) break;
    }
    return s;
}

TEST(NestGenerator, IsDeterministicAndReachesItsSize) {
    const std::string a = generate_nest_tape(50'000, 7);
    const std::string b = generate_nest_tape(50'000, 7);
    EXPECT_EQ(a, b);
    EXPECT_GE(a.size(), 50'000u);
    EXPECT_LT(a.size(), 51'000u);
    EXPECT_NE(a, generate_nest_tape(50'000, 8));
}

TEST(NestGenerator, LineEndings) {
    const std::string crlf = generate_nest_tape(20'000, 3, LineEnding::CrLf);
    const std::string lf = generate_nest_tape(20'000, 3, LineEnding::Lf);
    EXPECT_NE(crlf.find("\r\n"), std::string::npos);
    EXPECT_EQ(lf.find('\r'), std::string::npos);
    // The same blocks: dropping the CRs of the CR LF tape gives a prefix-compatible LF tape.
    std::string stripped;
    for (char c : crlf)
        if (c != '\r') stripped += c;
    EXPECT_EQ(stripped.substr(0, 5000), lf.substr(0, 5000));
}

class NestGeneratorCheck : public ::testing::TestWithParam<LineEnding> {};

TEST_P(NestGeneratorCheck, ChecksWithNoError) {
    const std::string tape = generate_nest_tape(200'000, 1, GetParam());
    const essi::Profile profile;  // default (iso6582)
    const essi::CheckResult r = essi::check_tape(tape, profile);
    EXPECT_EQ(r.count(essi::Severity::Error), 0u) << first_errors(r);
    EXPECT_TRUE(r.ok());
    EXPECT_GT(r.stats.cut_length_mm, 0.0);
    EXPECT_GT(r.stats.pierces, 100u);
    EXPECT_GT(r.stats.rapid_length_mm, 0.0);
    EXPECT_GT(r.stats.blocks, 10'000u);
    EXPECT_FALSE(r.stats.cut_bbox.empty);
}

INSTANTIATE_TEST_SUITE_P(LineEndings, NestGeneratorCheck, ::testing::Values(LineEnding::CrLf, LineEnding::Lf),
                         [](const auto& info) { return info.param == LineEnding::CrLf ? "CrLf" : "Lf"; });

}  // namespace
