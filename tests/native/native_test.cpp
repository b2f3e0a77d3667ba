// Unit tests of the native-only parts of the CLI (native/: batch, formats, SHA-256, share store, thread pool).
// Built natively only (essi_native_tests); the formats are also checked end to end against their real consumers
// by tests/formats (node: ajv + the SARIF schema, junit2json, xml2js, Chromium).
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "batch.hpp"
#include "../bench/nest_generator.hpp"
#include "../unit/test_util.hpp"
#include "essi/diagnostics.hpp"
#include "essi/sha256.hpp"
#include "essi/share_link.hpp"
#include "essi/pipeline.hpp"
#include "formats.hpp"
#include "pipelined_check.hpp"
#include "plate_runner.hpp"
#include "share_store.hpp"
#include "temp_dir.hpp"
#include "thread_pool.hpp"

namespace fs = std::filesystem;
using namespace essi::native;

namespace {

void write(const fs::path& p, const std::string& s) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << s;
}

essi::Diagnostic diag(essi::Severity s, essi::DiagCode c, std::uint32_t line, std::uint32_t col, std::string msg) {
    essi::Diagnostic d;
    d.severity = s;
    d.code = c;
    d.line = line;
    d.column = col;
    d.set_text(std::move(msg));
    return d;
}

}  // namespace

// FIPS 180-4 / NIST CSRC example vectors for SHA-256.
TEST(Expand, ExtensionsSniffingAndOrder) {
    const fs::path d = temp_dir("expand");
    write(d / "b.esi", "+1+1\n63\n");
    write(d / "a.NC", "+1+1\n63\n");
    write(d / "sub/c.txt", "+1+1\n63\n");
    write(d / "sub/PART7", "3\nPART 7\n4\n+100+0\n63\n");  // no extension, ESSI content
    write(d / "sub/notes", "just some notes\n");           // no extension, not ESSI
    write(d / "sub/x.json", "{}\n");
    std::vector<std::string> errors;
    auto files = expand_paths({d.string()}, ExpandOptions{}, errors);
    ASSERT_TRUE(errors.empty());
    std::vector<std::string> rel;
    for (auto& f : files) rel.push_back(fs::relative(f, d).generic_string());
    EXPECT_EQ(rel, (std::vector<std::string>{"a.NC", "b.esi", "sub/PART7", "sub/c.txt"}));

    ExpandOptions only_esi;
    only_esi.extensions = parse_extension_list("esi");
    only_esi.sniff = false;
    files = expand_paths({d.string(), "-", "missing.esi"}, only_esi, errors);
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(fs::path(files[0]).filename(), "b.esi");
    EXPECT_EQ(files[1], "-");
    EXPECT_EQ(files[2], "missing.esi");  // reported when it is read
    fs::remove_all(d);
}

TEST(Expand, ParseExtensionList) {
    EXPECT_EQ(parse_extension_list("esi,.NC  txt;;"), (std::vector<std::string>{".esi", ".nc", ".txt"}));
    EXPECT_TRUE(parse_extension_list(" , ").empty());
}

// Each plate is analysed once, by whichever thread asks: queued up to the bound, at once beyond it, the rest by
// wait().
TEST(SharedPlateRunner, EveryPlateRunsOnceWhicheverThreadRunsIt) {
    essi::native::SharedPlateRunner plates(2);
    std::atomic<int> ran{0};
    const auto job = [&] { ++ran; };
    for (int k = 0; k < 5; ++k) plates.run(job, 10);
    EXPECT_EQ(ran.load(), 3);  // (two queued, three run by run() itself)
    EXPECT_TRUE(plates.run_one());
    EXPECT_EQ(ran.load(), 4);
    std::thread reader([&] { EXPECT_TRUE(plates.run_one()); });
    reader.join();
    EXPECT_EQ(ran.load(), 5);
    EXPECT_FALSE(plates.run_one());
    plates.run(job, 10);
    plates.run(job, 10);
    plates.wait();
    EXPECT_EQ(ran.load(), 7);
    EXPECT_FALSE(plates.run_one());
}

// Plates wait only while their motions together stay within kMaxWaitingMotions: large plates do not pile up.
TEST(SharedPlateRunner, LargePlatesDoNotPileUp) {
    essi::native::SharedPlateRunner plates(8);
    std::atomic<int> ran{0};
    const auto job = [&] { ++ran; };
    const std::size_t half = essi::native::SharedPlateRunner::kMaxWaitingMotions / 2;
    plates.run(job, half);
    plates.run(job, half);
    EXPECT_EQ(ran.load(), 0);  // (both wait: together exactly the bound)
    plates.run(job, 1);
    EXPECT_EQ(ran.load(), 1);  // (over the bound: run at once)
    EXPECT_TRUE(plates.run_one());
    plates.run(job, 1);
    EXPECT_EQ(ran.load(), 2);  // (room again: it waits)
    plates.wait();
    EXPECT_EQ(ran.load(), 4);
}

TEST(ThreadPool, EmitsInOrderWithManyWorkers) {
    for (unsigned jobs : {1u, 2u, 7u}) {
        const std::size_t n = 500;
        std::vector<int> results(n, -1);
        std::vector<std::size_t> order;
        std::atomic<int> running{0}, max_running{0};
        for_each_ordered(
            n, jobs,
            [&](std::size_t i) {
                const int now = ++running;
                int m = max_running.load();
                while (now > m && !max_running.compare_exchange_weak(m, now)) {
                }
                if (i % 7 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
                results[i] = static_cast<int>(i * 3);
                --running;
            },
            [&](std::size_t i) {
                EXPECT_EQ(results[i], static_cast<int>(i * 3));
                order.push_back(i);
            },
            16);
        ASSERT_EQ(order.size(), n);
        for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(order[i], i);
        EXPECT_LE(max_running.load(), static_cast<int>(jobs));
    }
}

TEST(Batch, SameResultsForAnyJobCountAndLimit) {
    const fs::path d = temp_dir("batch");
    for (int i = 0; i < 20; ++i)
        write(d / ("t" + std::to_string(100 + i) + ".esi"), i % 3 ? "+100+0\n63\n" : "+1x\n+5\n");
    std::vector<std::string> errors;
    const auto files = expand_paths({d.string()}, ExpandOptions{}, errors);
    ASSERT_EQ(files.size(), 20u);
    std::vector<std::string> seen1, seen2;
    const TapeRequest iso_request{std::nullopt, essi::builtin_profile("iso6582"), "iso6582", std::nullopt};
    BatchOptions o;
    o.jobs = 1;
    check_batch(files, iso_request, o,
                [&](BatchItem&& it) { seen1.push_back(it.report.path + ":" + std::to_string(it.report.errors())); });
    o.jobs = 4;
    o.max_diagnostics = 1;
    check_batch(files, iso_request, o, [&](BatchItem&& it) {
        EXPECT_LE(it.report.result.diagnostics.size(), 1u);
        seen2.push_back(it.report.path + ":" + std::to_string(it.report.errors()));
    });
    EXPECT_EQ(seen1, seen2);  // same order, same counts (omitted diagnostics still count)
    fs::remove_all(d);
}

TEST(Formats, GithubCommands) {
    EXPECT_EQ(github_escape_data("a%b\r\nc"), "a%25b%0D%0Ac");
    EXPECT_EQ(github_escape_property("dir,x:y.esi"), "dir%2Cx%3Ay.esi");
    BatchItem it;
    it.read_ok = true;
    it.report.path = "a b.esi";
    it.report.result.diagnostics = {
        diag(essi::Severity::Error, essi::DiagCode::E301_ArcEndNotOnCircle, 12, 3, "off 50%"),
        diag(essi::Severity::Warning, essi::DiagCode::W114_NoProgramEnd, 0, 0, "no end")};
    EXPECT_EQ(github_file_block(it),
              "::error file=a b.esi,line=12,col=3,title=E301::off 50%25\n"
              "::warning file=a b.esi,title=W114::no end\n");
}

TEST(Formats, UrisAndXml) {
    EXPECT_EQ(path_to_uri("./dir/a b#1.esi"), "dir/a%20b%231.esi");
    EXPECT_EQ(path_to_uri("/abs/x.esi"), "file:///abs/x.esi");
    // A backslash is a character of a Linux file name, not a separator: percent-encoded like any other byte.
    EXPECT_EQ(path_to_uri("dir\\x.esi"), "dir%5Cx.esi");
    EXPECT_EQ(path_to_uri("bad\xFF.esi"), "bad%FF.esi");
    EXPECT_EQ(essi::xml_escape("<a href=\"x\">'&'\x01</a>"),
              "&lt;a href=&quot;x&quot;&gt;&apos;&amp;&apos;?&lt;/a&gt;");
}

TEST(Formats, SarifHasOneRulePerCode) {
    const auto rules = sarif_rules("https://example.org/docs");
    ASSERT_EQ(rules.size(), essi::all_codes().size());
    EXPECT_EQ(rules[0]["id"], "E101");
    EXPECT_EQ(rules[0]["helpUri"], "https://example.org/docs/diagnostics.md#e101");
    EXPECT_EQ(rules[0]["defaultConfiguration"]["level"], "error");
    for (const auto& r : rules) EXPECT_FALSE(r["shortDescription"]["text"].get<std::string>().empty());
}

TEST(ShareStore, ContentAddressedAndPersistent) {
    const fs::path d = temp_dir("store");
    std::string error;
    {
        auto store = ShareStore::open((d / "data").string(), error);
        ASSERT_TRUE(store) << error;
        const auto a = store->put("+100+0\n63\n");
        ASSERT_TRUE(a.ok) << a.error;
        EXPECT_TRUE(a.created);
        EXPECT_EQ(a.id, essi::sha256_hex("+100+0\n63\n"));
        const auto b = store->put("+100+0\n63\n");
        EXPECT_TRUE(b.ok);
        EXPECT_FALSE(b.created);
        EXPECT_EQ(b.id, a.id);
        EXPECT_FALSE(store->get(essi::sha256_hex("other")));
    }
    auto again = ShareStore::open((d / "data").string(), error);
    ASSERT_TRUE(again);
    auto tape = again->get(essi::sha256_hex("+100+0\n63\n"));
    ASSERT_TRUE(tape);
    EXPECT_EQ(*tape, "+100+0\n63\n");
    const std::string binary("\0\xff\r\n", 4);  // blobs, not text
    const auto c = again->put(binary);
    EXPECT_EQ(*again->get(c.id), binary);
    fs::remove_all(d);
}

// `essi check` on two threads (native/pipelined_check.cpp) gives check_tape's result to the bit: the
// statistics (doubles compared bit for bit) and every diagnostic, on a tape of many chunks. Whether a chunk's arcs
// are measured by the reading thread or by the interpreter depends on which thread is ahead at that moment,
// so each tape is checked several times. One tape is valid; in the other, errors and warnings are spread
// over the chunks (a bad character, an unassigned function, a function with a value it does not take).
TEST(PipelinedCheck, SameResultAsOneThread) {
    const essi::Profile profile;
    const std::string valid = essi::bench::generate_nest_tape(3 * kPipelineMinBytes, 11);
    std::string flawed;  // (the generator's lines end in CR LF)
    std::size_t line = 0;
    for (std::size_t at = 0; at < valid.size();) {
        const std::size_t end = valid.find('\n', at);
        const std::size_t next = end == std::string::npos ? valid.size() : end + 1;
        flawed.append(valid, at, next - at);
        at = next;
        if (++line % 40'009 == 0)
            flawed += (line / 40'009) % 3 == 0 ? "+1x2\r\n" : (line / 40'009) % 3 == 1 ? "117\r\n" : "7+5\r\n";
    }
    ASSERT_GT(valid.size(), kPipelineMinBytes * 2);
    for (const std::string* tape :
         {static_cast<const std::string*>(&valid), static_cast<const std::string*>(&flawed)}) {
        SCOPED_TRACE(tape == &valid ? "valid tape" : "tape with errors and warnings");
        const essi::CheckResult one = essi::check_tape(*tape, profile);
        EXPECT_GT(one.stats.motions, 100'000u);
        if (tape == &valid) EXPECT_TRUE(one.diagnostics.empty());
        else EXPECT_GE(one.diagnostics.size(), 6u);
        for (int run = 0; run < 3; ++run)
            essi_test::expect_same_result(check_tape_pipelined(*tape, profile), one, "run " + std::to_string(run));
    }
    // The cut plan's plates analysed by the reading thread or at the end (SharedPlateRunner): the same findings in
    // the same order.
    // A kerf 40 mm wide makes the nest's parts (35 mm apart) collide on every plate.
    essi::Profile wide;
    wide.kerf_units = 400;
    const essi::CheckResult one = essi::check_tape(valid, wide);
    EXPECT_GT(one.count(essi::Severity::Error), 100u);
    for (int run = 0; run < 3; ++run)
        essi_test::expect_same_result(check_tape_pipelined(valid, wide), one, "wide kerf, run " + std::to_string(run));
}
