// Core throughput benchmarks (Google Benchmark), natively and under WASM.
//
//   read/<eol>     essi::read_tape               bytes -> blocks
//   interp/<eol>   essi::interpret               blocks -> motion stream (a counting sink), tape read once
//   check/<eol>    essi::check_tape              the whole pipeline on bytes (what `essi check` runs)
//   check_every_rule/crlf   the same with the cut plan's optional rules on (lead_in_required, a table: W610, W611)
//   check_without_plan/crlf the pipeline without the cut plan (reader, interpreter, statistics): check / this is
//                  what the cut plan costs (docs/performance.md: the viewer's load may grow by at most 20 %)
//   read_eia       essi::read_tape of the EIA form of the tape (tests/bench/eia_generator.hpp, Woyda table, LF)
//   check_eia      essi::check_tape of it
//   wc_l/<eol>     `wc -l` on the same tape as a file: the floor (native only; a child process, timed
//                  with std::chrono around std::system, reported as manual time)
//
// <eol> is crlf or lf: the same generated nesting tape (tests/bench/nest_generator.hpp) with either line end.
// Tape size: 100 MB natively, 20 MB under WASM; override with --essi_tape_mb=N.
// Throughput: `bytes_per_second` (Google Benchmark, MiB/s) and `MB/s` (10^6 bytes/s, the unit of
// docs/performance.md and scripts/bench_compare). Counters: `blocks`, `bytes_per_block`
// (Tape::memory_bytes() / blocks), `errors` (must be 0: the generated tape is valid).
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#ifndef __EMSCRIPTEN__
#include <unistd.h>  // getpid
#endif

#include "essi/interp.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/pipeline.hpp"
#include "eia_generator.hpp"
#include "nest_generator.hpp"

namespace {

using essi::bench::LineEnding;

#ifdef __EMSCRIPTEN__
double g_tape_mb = 20;
#else
double g_tape_mb = 100;
#endif
constexpr unsigned kSeed = 1;

const essi::Profile& profile() {
    static const essi::Profile p;  // the default (iso6582) profile
    return p;
}

int index_of(LineEnding eol) { return eol == LineEnding::CrLf ? 0 : 1; }
const char* name_of(LineEnding eol) { return eol == LineEnding::CrLf ? "crlf" : "lf"; }

// The generated tape, once per line ending (generated on first use, kept for the whole run).
const std::string& tape_bytes(LineEnding eol) {
    static std::array<std::unique_ptr<std::string>, 2> cache;
    auto& slot = cache[index_of(eol)];
    if (!slot) {
        slot = std::make_unique<std::string>(
            essi::bench::generate_nest_tape(static_cast<std::size_t>(g_tape_mb * 1e6), kSeed, eol));
    }
    return *slot;
}

// The tape read once (for the interp benchmark).
const essi::Tape& read_once(LineEnding eol) {
    static std::array<std::unique_ptr<essi::Tape>, 2> cache;
    auto& slot = cache[index_of(eol)];
    if (!slot) slot = std::make_unique<essi::Tape>(essi::read_tape(tape_bytes(eol), profile()));
    return *slot;
}

// The EIA tape (generated on first use) and the profile that reads it.
const std::string& eia_bytes() {
    static const std::string bytes =
        essi::bench::generate_eia_nest_tape(static_cast<std::size_t>(g_tape_mb * 1e6), kSeed);
    return bytes;
}
const essi::Profile& woyda() {
    static const essi::Profile p = *essi::builtin_profile("woyda");
    return p;
}

void set_throughput(benchmark::State& state, std::size_t bytes) {
    const auto total = static_cast<double>(bytes) * static_cast<double>(state.iterations());
    state.SetBytesProcessed(static_cast<std::int64_t>(total));
    state.counters["MB/s"] = benchmark::Counter(total / 1e6, benchmark::Counter::kIsRate);
    state.counters["tape_MB"] = static_cast<double>(bytes) / 1e6;
}

void tape_counters(benchmark::State& state, const essi::Tape& tape) {
    const double blocks = static_cast<double>(tape.size());
    state.counters["blocks"] = blocks;
    state.counters["bytes_per_block"] = blocks > 0 ? static_cast<double>(tape.memory_bytes()) / blocks : 0;
}

class CountingSink final : public essi::MotionSink {
public:
    void on_motion(const essi::MotionRecord& m) override {
        ++motions;
        length_mm += m.length_mm;
    }
    void on_event(const essi::MachineEvent&) override { ++events; }
    std::uint64_t motions = 0;
    std::uint64_t events = 0;
    double length_mm = 0;
};

void bm_read(benchmark::State& state, LineEnding eol) {
    const std::string& bytes = tape_bytes(eol);
    std::size_t blocks = 0;
    for (auto _ : state) {
        essi::Tape tape = essi::read_tape(bytes, profile());
        blocks = tape.size();
        benchmark::DoNotOptimize(blocks);
    }
    set_throughput(state, bytes.size());
    const essi::Tape& tape = read_once(eol);
    tape_counters(state, tape);
    state.counters["errors"] = static_cast<double>(tape.has_errors() ? 1 : 0);
}

void bm_read_eia(benchmark::State& state) {
    const std::string& bytes = eia_bytes();
    for (auto _ : state) {
        essi::Tape tape = essi::read_tape(bytes, woyda(), essi::InputFormat::Eia);
        benchmark::DoNotOptimize(tape.size());
    }
    set_throughput(state, bytes.size());
    const essi::Tape tape = essi::read_tape(bytes, woyda(), essi::InputFormat::Eia);
    tape_counters(state, tape);
    state.counters["errors"] = static_cast<double>(tape.has_errors() ? 1 : 0);
}

void bm_check_eia(benchmark::State& state) {
    const std::string& bytes = eia_bytes();
    std::size_t errors = 0;
    for (auto _ : state) {
        const essi::CheckResult r = essi::check_tape(bytes, woyda(), essi::InputFormat::Eia);
        errors = r.count(essi::Severity::Error) + r.count(essi::Severity::Warning);
        benchmark::DoNotOptimize(errors);
    }
    set_throughput(state, bytes.size());
    state.counters["errors"] = static_cast<double>(errors);
}

void bm_interp(benchmark::State& state, LineEnding eol) {
    const std::string& bytes = tape_bytes(eol);
    const essi::Tape& tape = read_once(eol);
    std::uint64_t motions = 0;
    std::size_t errors = 0;
    for (auto _ : state) {
        CountingSink sink;
        std::vector<essi::Diagnostic> diagnostics;
        essi::interpret(tape, bytes, profile(), sink, diagnostics);
        motions = sink.motions;
        errors = 0;
        for (const auto& d : diagnostics) errors += d.severity == essi::Severity::Error ? 1 : 0;
        benchmark::DoNotOptimize(sink.length_mm);
    }
    set_throughput(state, bytes.size());
    tape_counters(state, tape);
    state.counters["motions"] = static_cast<double>(motions);
    state.counters["errors"] = static_cast<double>(errors);
}

void bm_check(benchmark::State& state, LineEnding eol) {
    const std::string& bytes = tape_bytes(eol);
    std::size_t errors = 0;
    double cut_m = 0;
    for (auto _ : state) {
        essi::CheckResult result = essi::check_tape(bytes, profile());
        errors = result.count(essi::Severity::Error);
        cut_m = result.stats.cut_length_mm / 1000.0;
        benchmark::DoNotOptimize(cut_m);
    }
    set_throughput(state, bytes.size());
    tape_counters(state, read_once(eol));
    state.counters["errors"] = static_cast<double>(errors);
    state.counters["cut_m"] = cut_m;
}

// Every rule of the cut plan on: a lead-in asked for, a table as large as the generated plates.
const essi::Profile& every_rule_profile() {
    static const essi::Profile p = [] {
        essi::Profile q;
        q.lead_in_required = true;
        q.table = essi::TableLimits{-10, -10, 3010, 1510};
        return q;
    }();
    return p;
}

void bm_check_every_rule(benchmark::State& state, LineEnding eol) {
    const std::string& bytes = tape_bytes(eol);
    std::size_t problems = 0;
    for (auto _ : state) {
        const essi::CheckResult result = essi::check_tape(bytes, every_rule_profile());
        problems = result.diagnostics.size();
        benchmark::DoNotOptimize(problems);
    }
    set_throughput(state, bytes.size());
    state.counters["errors"] = static_cast<double>(problems);  // (any diagnostic: the nest is clean)
}

// What check_tape did before the cut plan: the chunks read and interpreted into the statistics only.
void bm_check_without_plan(benchmark::State& state, LineEnding eol) {
    const std::string& bytes = tape_bytes(eol);
    std::size_t errors = 0;
    for (auto _ : state) {
        std::vector<essi::Diagnostic> diagnostics;
        essi::StatsSink stats(profile());
        essi::Interpreter interpreter(bytes, profile(), stats, nullptr, diagnostics);
        essi::TapeReader reader(bytes, profile());
        essi::Tape chunk;
        while (reader.read_chunk(chunk, essi::kCheckChunkBlocks)) interpreter.run(chunk);
        interpreter.finish();
        stats.finish();
        errors = diagnostics.size();
        benchmark::DoNotOptimize(errors);
    }
    set_throughput(state, bytes.size());
    state.counters["errors"] = static_cast<double>(errors);
}

#ifndef __EMSCRIPTEN__
// The tape as a file in the temp folder (written once per line ending, removed at exit).
const std::string& tape_file(LineEnding eol) {
    static std::array<std::string, 2> paths;
    static struct Cleanup {
        ~Cleanup() {
            for (const auto& p : paths)
                if (!p.empty()) std::remove(p.c_str());
        }
    } cleanup;
    std::string& path = paths[index_of(eol)];
    if (path.empty()) {
        path = (std::filesystem::temp_directory_path() /
                ("essi_bench_nest_" + std::to_string(::getpid()) + "_" + name_of(eol) + ".esi"))
                   .string();
        const std::string& bytes = tape_bytes(eol);
        std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    return path;
}

void bm_wc_l(benchmark::State& state, LineEnding eol) {
    const std::string& path = tape_file(eol);
    const std::string cmd = "wc -l '" + path + "' >/dev/null";
    if (std::system(cmd.c_str()) != 0) {  // also warms the page cache
        state.SkipWithError("wc -l failed");
        return;
    }
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const int rc = std::system(cmd.c_str());
        const auto t1 = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(rc);
        state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
    }
    set_throughput(state, tape_bytes(eol).size());
}
#endif

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    // Our own flag: --essi_tape_mb=N (the tape size in 10^6 bytes).
    int out = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        constexpr std::string_view flag = "--essi_tape_mb=";
        if (a.substr(0, flag.size()) == flag) {
            g_tape_mb = std::strtod(argv[i] + flag.size(), nullptr);
            if (!(g_tape_mb > 0)) {
                std::fprintf(stderr, "essi_bench: --essi_tape_mb needs a positive number\n");
                return 2;
            }
        } else {
            argv[out++] = argv[i];
        }
    }
    argc = out;
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

    benchmark::AddCustomContext(
        "essi_tape", "generated nest tape, seed " + std::to_string(kSeed) + ", " + std::to_string(g_tape_mb) + " MB");
    for (LineEnding eol : {LineEnding::CrLf, LineEnding::Lf}) {
        const std::string suffix = std::string("/") + name_of(eol);
        benchmark::RegisterBenchmark(("read" + suffix).c_str(), bm_read, eol)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("interp" + suffix).c_str(), bm_interp, eol)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("check" + suffix).c_str(), bm_check, eol)->Unit(benchmark::kMillisecond);
#ifndef __EMSCRIPTEN__
        benchmark::RegisterBenchmark(("wc_l" + suffix).c_str(), bm_wc_l, eol)
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
#endif
    }
    benchmark::RegisterBenchmark("check_every_rule/crlf", bm_check_every_rule, LineEnding::CrLf)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("check_without_plan/crlf", bm_check_without_plan, LineEnding::CrLf)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("read_eia", bm_read_eia)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("check_eia", bm_check_eia)->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
