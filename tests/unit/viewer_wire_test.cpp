// The document as the reading worker hands it to the page (web/app/DocumentWire, ReadingJob, WorkerLoader): what
// the page decodes is the document the worker read, to the last byte (encoded again, the same bytes), its blocks
// read again from the resumed readers are read_tape's, and a message cut short or wrong says where and what, and
// makes the page read the tape itself. Over every example and a generated tape of many chunks.
#include <gtest/gtest.h>

#include <deque>
#include <filesystem>
#include <string>
#include <vector>

#include "../bench/nest_generator.hpp"
#include "app/DocumentLoader.hpp"
#include "app/DocumentWire.hpp"
#include "app/ReadingJob.hpp"
#include "app/WorkerLoader.hpp"
#include "essi/dialect.hpp"
#include "essi/read.hpp"
#include "essi/report_json.hpp"
#include "paths.hpp"

using namespace essi;
using essi::viewer::Document;
using essi::viewer::DocumentLoader;
using essi::viewer::ReadingMessage;
using essi::viewer::WireError;

namespace {

// Where two encodings first differ ("" when they are the same bytes): what a failure prints instead of both.
std::string difference(const std::string& a, const std::string& b) {
    if (a == b) return "";
    std::size_t i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
    return "differ at byte " + std::to_string(i) + " of " + std::to_string(a.size()) + " and " +
           std::to_string(b.size());
}

// The document DocumentLoader reads from `bytes` (its format and profile from the content, as the page's "auto").
std::unique_ptr<Document> read_here(const std::string& bytes, bool plan_later = false) {
    DocumentLoader loader("tape", bytes, setup_tape(bytes, std::nullopt, std::nullopt), plan_later);
    while (!loader.step(1e9)) {
    }
    return loader.take();
}

std::vector<std::string> diagnostic_texts(const Document& d) {
    std::vector<std::string> out;
    for (const Diagnostic& x : d.diagnostics)
        out.push_back(std::to_string(x.line) + ":" + std::to_string(x.column) + " " + code_name(x.code) + " " +
                      diagnostic_message(x, Lang::En));
    return out;
}

// Every line's blocks, read again by the decoded document's resumed readers, are those of the document read here.
void expect_same_blocks(const Document& got, const Document& want) {
    ASSERT_EQ(got.chunks.size(), want.chunks.size());
    for (std::uint32_t line = 1; line <= want.line_count(); ++line) {
        const auto g = got.blocks_of_line(line);
        std::vector<Block> wb;
        std::vector<std::vector<std::int32_t>> ww;
        {
            const auto w = want.blocks_of_line(line);
            for (std::size_t k = w.first; k < w.last; ++k) {
                wb.push_back(w.chunk->block(k));
                const auto words = w.chunk->words(k);
                ww.emplace_back(words.begin(), words.end());
            }
        }
        ASSERT_EQ(g.last - g.first, wb.size()) << "line " << line;
        for (std::size_t k = 0; k < wb.size(); ++k) {
            const Block& b = g.chunk->block(g.first + k);
            ASSERT_EQ(b.offset, wb[k].offset) << "line " << line;
            ASSERT_EQ(b.kind, wb[k].kind) << "line " << line;
            ASSERT_EQ(b.code, wb[k].code) << "line " << line;
            const auto words = g.chunk->words(g.first + k);
            ASSERT_EQ(std::vector<std::int32_t>(words.begin(), words.end()), ww[k]) << "line " << line;
        }
    }
}

void expect_comes_back_whole(const std::string& bytes) {
    const auto doc = read_here(bytes);
    const std::string wire = essi::viewer::encode_document(*doc);
    std::string given = bytes;
    WireError error;
    const auto back = essi::viewer::decode_document(wire, given, error);
    ASSERT_NE(back, nullptr) << error.message();
    EXPECT_TRUE(given.empty());  // (moved into the document)
    EXPECT_EQ(back->bytes, bytes);
    EXPECT_EQ(difference(essi::viewer::encode_document(*back), wire), "");  // every part, to the byte
    EXPECT_EQ(diagnostic_texts(*back), diagnostic_texts(*doc));
    EXPECT_EQ(profile_to_json(back->profile), profile_to_json(doc->profile));
    // Every field of the statistics, through the report (a field that save_stats leaves out differs here).
    EXPECT_EQ(stats_to_json(back->stats).dump(), stats_to_json(doc->stats).dump());
    EXPECT_EQ(statistics_time_s(back->stats), statistics_time_s(doc->stats));
    ASSERT_EQ(back->motions.size(), doc->motions.size());
    for (std::size_t i = 0; i < doc->motions.size(); ++i) {
        ASSERT_EQ(back->end_of(i), doc->end_of(i)) << "motion " << i;
        ASSERT_EQ(back->start_of(i), doc->start_of(i)) << "motion " << i;
    }
    expect_same_blocks(*back, *doc);
}

std::vector<std::filesystem::path> example_tapes() {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::directory_iterator(examples_dir()))
        if (e.path().extension() == ".esi" || e.path().extension() == ".eia") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(ViewerWire, ExamplesComeBackWhole) {
    const auto tapes = example_tapes();
    ASSERT_GT(tapes.size(), 20u);
    for (const auto& path : tapes) {
        SCOPED_TRACE(path.filename().string());
        expect_comes_back_whole(read_file(path.string()));
    }
}

TEST(ViewerWire, GeneratedTapeOfManyChunksComesBackWhole) {
    const std::string bytes = bench::generate_nest_tape(1 << 20, 7);
    EXPECT_GT(read_here(bytes)->chunks.size(), 3u);
    expect_comes_back_whole(bytes);
}

// A reader resumed from its checkpoint before any chunk reads the rest as the reader that went on, diagnostics
// included; a checkpoint of another format or another size of tape is refused.
TEST(ViewerWire, ReadersResumeFromTheirCheckpoints) {
    for (const char* name : {"plate_holes.esi", "bad_character.esi", "din66025_plate.eia", "bad_eia_order.eia"}) {
        SCOPED_TRACE(name);
        const std::string bytes = read_file(examples_dir() + "/" + name);
        const TapeSetup setup = setup_tape(bytes, std::nullopt, std::nullopt);
        TapeReader reader(bytes, setup.profile, setup.format);
        Tape chunk, again;
        for (int k = 0;; ++k) {
            const std::string checkpoint = reader.checkpoint();
            std::optional<TapeReader> resumed = TapeReader::resume(bytes, setup.profile, setup.format, checkpoint);
            ASSERT_TRUE(resumed.has_value()) << "chunk " << k;
            const bool more = reader.read_chunk(chunk, 5);
            ASSERT_EQ(resumed->read_chunk(again, 5), more) << "chunk " << k;
            if (!more) break;
            ASSERT_EQ(again.size(), chunk.size()) << "chunk " << k;
            for (std::size_t b = 0; b < chunk.size(); ++b) {
                ASSERT_EQ(again.block(b).offset, chunk.block(b).offset) << "chunk " << k;
                ASSERT_EQ(again.block(b).line, chunk.block(b).line) << "chunk " << k;
                ASSERT_EQ(again.block(b).kind, chunk.block(b).kind) << "chunk " << k;
            }
            ASSERT_EQ(again.diagnostics().size(), chunk.diagnostics().size()) << "chunk " << k;
            EXPECT_EQ(resumed->checkpoint(), reader.checkpoint()) << "chunk " << k;
        }
        const std::string end = reader.checkpoint();
        const InputFormat other = setup.format == InputFormat::Essi ? InputFormat::Eia : InputFormat::Essi;
        EXPECT_FALSE(TapeReader::resume(bytes, setup.profile, other, end).has_value());
        EXPECT_FALSE(TapeReader::resume(bytes + "\n", setup.profile, setup.format, end).has_value());
        EXPECT_FALSE(TapeReader::resume(bytes, setup.profile, setup.format, end.substr(0, end.size() - 1)));
    }
}

// Cut anywhere, the document is refused with the part it was in and a byte no later than the cut, and the
// tape's bytes are given back; bytes after its end are refused too.
TEST(ViewerWire, ACutShortDocumentSaysWhereAndGivesTheBytesBack) {
    const std::string bytes = read_file(examples_dir() + "/plan_collision.esi");
    const std::string wire = essi::viewer::encode_document(*read_here(bytes));
    std::vector<std::string> parts;
    for (std::size_t cut = 0; cut < wire.size(); ++cut) {
        std::string given = bytes;
        WireError error;
        EXPECT_EQ(essi::viewer::decode_document(wire.substr(0, cut), given, error), nullptr) << "cut at " << cut;
        EXPECT_EQ(given, bytes) << "cut at " << cut;
        EXPECT_LE(error.at, cut) << "cut at " << cut;
        ASSERT_FALSE(error.what.empty()) << "cut at " << cut;
        if (parts.empty() || parts.back() != error.what) parts.push_back(error.what);
    }
    const std::vector<std::string> want = {"name",
                                           "setup",
                                           "diagnostics",
                                           "statistics",
                                           "motions",
                                           "arc centres",
                                           "arc index",
                                           "kept motions",
                                           "jumps",
                                           "kerfs",
                                           "feeds",
                                           "pierces",
                                           "line index",
                                           "diagnostic marks",
                                           "concerned motions",
                                           "reader checkpoints",
                                           "counts"};
    EXPECT_EQ(parts, want);  // (each part in its turn)
    std::string given = bytes;
    WireError error;
    EXPECT_EQ(essi::viewer::decode_document(wire + "x", given, error), nullptr);
    EXPECT_EQ(error.what, "end (bytes after the last part)");
    EXPECT_EQ(error.at, wire.size());
    EXPECT_EQ(error.message(), "the reading worker's message is cut short or wrong at byte " +
                                   std::to_string(wire.size()) + ", in its end (bytes after the last part)");
}

namespace {

// The worker's messages of one job, run in place.
std::vector<std::string> run_job(const std::string& header, const std::string& bytes) {
    std::vector<std::string> out;
    essi::viewer::run_reading_job(header, bytes, [&](ReadingMessage kind, std::string_view body) {
        out.push_back(static_cast<char>(kind) + std::string(body));
    });
    return out;
}

// A reading worker that runs each job in place: up to its document when it is posted, its plan when the page asks
// (or, `spoil`ed, changes its messages first: all of them, when the page asks for the plan).
class InPlaceWorker final : public essi::viewer::ReadingWorker {
public:
    std::function<void(std::vector<std::string>&)> spoil;
    bool hold_last = false;  // the job's last message never comes (it is still running)
    std::vector<std::uint32_t> cancelled;
    int posted = 0;
    std::vector<std::uint32_t> plans_asked;

    void prepare() override {}
    void post(std::uint32_t job, std::string_view header, std::string_view bytes) override {
        ++posted;
        if (spoil || hold_last) {  // (the whole job at once, then changed)
            std::vector<std::string> messages = run_job(std::string(header), std::string(bytes));
            if (spoil) spoil(messages);
            if (hold_last) messages.pop_back();
            for (std::string& m : messages) queue_.emplace_back(job, std::move(m));
            return;
        }
        job_.read(header, std::string(bytes), to_queue(job));
    }
    void analyse_plan(std::uint32_t job) override {
        plans_asked.push_back(job);
        if (spoil || hold_last) return;
        while (!job_.analyse_plan(1e9, to_queue(job))) {
        }
    }
    std::optional<std::string> receive(std::uint32_t job) override {
        while (!queue_.empty()) {
            auto [from, m] = std::move(queue_.front());
            queue_.pop_front();
            if (from == job) return m;
        }
        return std::nullopt;
    }
    void cancel(std::uint32_t job) override { cancelled.push_back(job); }

private:
    essi::viewer::PostReadingMessage to_queue(std::uint32_t job) {
        return [this, job](ReadingMessage kind, std::string_view body) {
            queue_.emplace_back(job, static_cast<char>(kind) + std::string(body));
        };
    }
    std::deque<std::pair<std::uint32_t, std::string>> queue_;
    essi::viewer::ReadingJob job_;
};

// What the page holds once a WorkerLoader's document and plan are in.
std::unique_ptr<Document> load_through(InPlaceWorker& worker, const std::string& bytes, std::string& failure) {
    essi::viewer::WorkerLoader loader(worker, "tape", bytes, setup_tape(bytes, std::nullopt, std::nullopt));
    while (!loader.step(1e9)) {
    }
    auto doc = loader.take();
    EXPECT_TRUE(loader.plan_pending());
    EXPECT_TRUE(worker.plans_asked.empty());  // (the worker analyses the plan only once the page asks)
    while (!loader.step_plan(*doc, 1e9)) {
    }
    failure = std::string(loader.failure());
    return doc;
}

}  // namespace

// The job's messages: progress, the document (the plan's findings not yet in it), progress, all the diagnostics.
TEST(ViewerWire, TheJobGivesTheDocumentThenAllItsDiagnostics) {
    const std::string bytes = bench::generate_nest_tape(1 << 20, 3);
    const auto here = read_here(bytes);
    const std::vector<std::string> messages =
        run_job(essi::viewer::encode_reading_request("tape", setup_tape(bytes, std::nullopt, std::nullopt)), bytes);
    std::string kinds;
    for (const std::string& m : messages) kinds += m.front();
    const auto document = kinds.find('d');
    ASSERT_NE(document, std::string::npos) << kinds;
    EXPECT_EQ(kinds.back(), 'f') << kinds;
    EXPECT_EQ(kinds.find_first_not_of('p', document + 1), kinds.size() - 1) << kinds;
    EXPECT_EQ(kinds.find_first_not_of('p'), document) << kinds;
    for (const std::string& m : messages) {
        if (m.front() != 'p') continue;
        essi::viewer::ReadingProgress p;
        ASSERT_TRUE(essi::viewer::decode_progress(std::string_view(m).substr(1), p));
        EXPECT_GE(p.share, 0.f);
        EXPECT_LE(p.share, 1.f);
    }
    essi::viewer::ReadingProgress p;
    const std::string progress = essi::viewer::encode_progress({0.25f, Msg::UiStagePlan});
    ASSERT_TRUE(essi::viewer::decode_progress(progress, p));
    EXPECT_EQ(p.share, 0.25f);
    EXPECT_EQ(p.stage, Msg::UiStagePlan);
    EXPECT_FALSE(essi::viewer::decode_progress(progress.substr(1), p));

    std::vector<Diagnostic> all;
    WireError error;
    ASSERT_TRUE(essi::viewer::decode_diagnostics(std::string_view(messages.back()).substr(1), all, error));
    Document with_all;
    with_all.diagnostics = std::move(all);
    EXPECT_EQ(diagnostic_texts(with_all), diagnostic_texts(*here));

    const std::vector<std::string> bad = run_job("not a request", bytes);
    ASSERT_EQ(bad.size(), 1u);
    EXPECT_EQ(bad[0], "ethe reading worker's message is cut short or wrong at byte 8, in its request");
}

TEST(ViewerWire, TheWorkerLoaderGivesThePageTheDocumentReadHere) {
    for (const char* name : {"plan_collision.esi", "kerf_parts.esi", "woyda_eia.eia", "bad_character.esi"}) {
        SCOPED_TRACE(name);
        const std::string bytes = read_file(examples_dir() + "/" + name);
        InPlaceWorker worker;
        std::string failure;
        const auto doc = load_through(worker, bytes, failure);
        EXPECT_EQ(failure, "");
        EXPECT_EQ(worker.posted, 1);
        EXPECT_EQ(worker.plans_asked.size(), 1u);
        EXPECT_TRUE(worker.cancelled.empty());  // (the job ended by itself)
        const auto here = read_here(bytes);
        EXPECT_EQ(diagnostic_texts(*doc), diagnostic_texts(*here));
        EXPECT_EQ(doc->marks.size(), here->marks.size());
        EXPECT_EQ(difference(essi::viewer::encode_document(*doc), essi::viewer::encode_document(*here)), "");
    }
}

// A document the page cannot read, a Failed message, or diagnostics cut short: the page reads the tape itself,
// says why, and ends with the same document.
TEST(ViewerWire, AWorkerThatFailsLeavesTheReadingToThePage) {
    const std::string bytes = read_file(examples_dir() + "/plan_collision.esi");
    const std::string want = essi::viewer::encode_document(*read_here(bytes));
    const auto cut = [](char kind) {
        return [kind](std::vector<std::string>& messages) {
            for (std::string& m : messages)
                if (m.front() == kind) m.resize(m.size() / 2);
        };
    };
    struct Case {
        const char* what;
        std::function<void(std::vector<std::string>&)> spoil;
        const char* failure_starts;
    };
    const Case cases[] = {
        {"document cut short", cut('d'), "the reading worker's message is cut short or wrong at byte "},
        {"diagnostics cut short", cut('f'), "the reading worker's message is cut short or wrong at byte "},
        {"failed", [](std::vector<std::string>& m) { m = {"eno memory"}; }, "no memory"},
        {"unknown kind", [](std::vector<std::string>& m) { m = {"?"}; }, "a message of an unknown kind"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        InPlaceWorker worker;
        worker.spoil = c.spoil;
        std::string failure;
        const auto doc = load_through(worker, bytes, failure);
        EXPECT_EQ(failure.rfind(c.failure_starts, 0), 0u) << failure;
        EXPECT_EQ(difference(essi::viewer::encode_document(*doc), want), "");
    }
}

// A loader dropped before its job ends (a new tape) cancels the job.
TEST(ViewerWire, ALoaderDroppedBeforeTheEndCancelsItsJob) {
    const std::string bytes = read_file(examples_dir() + "/plate_holes.esi");
    InPlaceWorker worker;
    worker.hold_last = true;
    std::uint32_t job = 0;
    {
        essi::viewer::WorkerLoader loader(worker, "tape", bytes, setup_tape(bytes, std::nullopt, std::nullopt));
        EXPECT_TRUE(loader.step(0));
        job = worker.posted;
    }
    ASSERT_EQ(worker.cancelled.size(), 1u);
    EXPECT_GT(worker.cancelled[0], 0u);
    EXPECT_EQ(job, 1);
}
