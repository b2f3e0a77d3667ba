#include "app/DocumentLoader.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>

#include "app/DocumentSink.hpp"
#include "essi/plan.hpp"
#include "essi/threads.hpp"

namespace essi::viewer {

namespace {

double now_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Grows `v` ahead of need to the size projected from the share of the tape read so far (no doubling: a
// 10 M motion stream must not cost twice its size).
template <class T>
void grow(std::vector<T>& v, std::size_t more, std::size_t read, std::size_t total) {
    if (v.size() + more <= v.capacity()) return;
    const double share = read > 0 ? static_cast<double>(read) / static_cast<double>(total) : 0.0;
    std::size_t want = v.size() + more;
    if (share > 0.01)
        want = std::max(want, static_cast<std::size_t>(static_cast<double>(v.size()) / share * 1.05) + 1024);
    else want = std::max(want, v.capacity() * 2);
    v.reserve(want);
}

// Gives back the room reserved ahead when it is more than an eighth (a copy: the WASM heap's peak grows by it).
template <class T>
void shrink_if_loose(std::vector<T>& v) {
    if (v.capacity() > v.size() + v.size() / 8 + 4096) v.shrink_to_fit();
}

// The document's tables without the room reserved ahead of the reading.
void shrink_tables(Document& d) {
    shrink_if_loose(d.motions);
    shrink_if_loose(d.arc_centres);
    shrink_if_loose(d.jumps);
    shrink_if_loose(d.kerfs);
    shrink_if_loose(d.feeds);
    shrink_if_loose(d.pierces);
    d.chunks.shrink_to_fit();
}

}  // namespace

// The document's motions as the cut plan reads them back (Document::record: the interpreter's own numbers).
class DocumentLoader::Motions final : public MotionStore {
public:
    explicit Motions(const Document& doc) : doc_(doc) {}
    [[nodiscard]] MotionRecord motion(std::size_t index) const override { return doc_.record(index); }

private:
    const Document& doc_;
};

DocumentLoader::DocumentLoader(std::string name, std::string bytes, TapeSetup setup, bool plan_later,
                               std::size_t two_threads_min_bytes)
    : doc_(std::make_unique<Document>()), plan_later_(plan_later), two_threads_min_bytes_(two_threads_min_bytes) {
    doc_->name = std::move(name);
    doc_->bytes = std::move(bytes);
    doc_->profile = setup.profile;
    doc_->setup = std::move(setup);
}

// (the reading thread first: it uses the checker, the sink and the document)
DocumentLoader::~DocumentLoader() { pipeline_.reset(); }

bool DocumentLoader::step(double budget_ms) {
    const double until = now_ms() + budget_ms;
    if (stage_ == Stage::IndexLines) {
        if (!index_lines(until)) return false;
        start_reading();
        if (now_ms() > until) return false;
    }
    if (stage_ == Stage::ReadAndCheck && !read_and_check(until)) return false;
    if (stage_ == Stage::Finish) finish();
    return true;
}

// The sparse line index, 2 MB at a time until the slice's time is up.
bool DocumentLoader::index_lines(double until) {
    Document& d = *doc_;
    constexpr std::size_t kIndexBytesPerTry = std::size_t(2) << 20;
    while (!d.line_index.build(d.bytes, kIndexBytesPerTry))
        if (now_ms() > until) return false;
    return true;
}

// The reader, the checker and the document's sink; room for the motion stream at once (lines that start with a
// sign are motions, near enough): no late reserve has to copy hundreds of MB in one slice. grow() covers the few
// motions this misses.
void DocumentLoader::start_reading() {
    Document& d = *doc_;
    stage_ = Stage::ReadAndCheck;
    const std::size_t motion_lines = d.line_index.signed_lines();  // the motion stream's size, near enough
    d.motions.reserve(motion_lines + motion_lines / kMotionReserveSlack + 16);
    d.arc_rank.reserve(d.motions.capacity());
    sink_ = std::make_unique<DocumentSink>(d);
    TapeReader reader(d.bytes, d.profile, d.setup.format);
    checker_ = std::make_unique<TapeChecker>(d.bytes, d.profile, sink_.get());
    if (plan_later_) {
        motions_ = std::make_unique<Motions>(d);
        checker_->defer_plan(motions_.get());
    }
    two_threads_ = kHaveThreads && d.bytes.size() >= two_threads_min_bytes_;
    if (!two_threads_) {
        reader_ = std::make_unique<TapeReader>(std::move(reader));
        chunk_.reserve(Document::kReadChunkBlocks, 2 * Document::kReadChunkBlocks);  // (no doubling steps)
        return;
    }
    // The reading thread reads the chunks and feeds their streams to the document (the checker's `also`) and the
    // plan, making room for their motions first; this one notes each chunk and interprets it.
    PipelinedCheck::Hooks hooks;
    hooks.keep_readers = true;
    hooks.chunk_read = [this](const Tape& chunk, std::optional<TapeReader>& before) {
        read_chunk_done(std::move(*before), chunk);
    };
    hooks.before_feed = [this](const MotionBuffer& stream) { make_room(stream.size()); };
    pipeline_ =
        std::make_unique<PipelinedCheck>(*checker_, std::move(reader), std::move(hooks), Document::kReadChunkBlocks);
}

// Read and check, a chunk at a time, until the slice's time is up or the tape's end (the stage is Finish then).
bool DocumentLoader::read_and_check(double until) {
    if (pipeline_) return check_on_two_threads(until);
    for (;;) {
        TapeReader before = *reader_;  // kept with the chunk: the inspector reads it again from there
        if (!reader_->read_chunk(chunk_, Document::kReadChunkBlocks)) {
            stage_ = Stage::Finish;
            return true;
        }
        read_chunk_done(std::move(before), chunk_);
        // Room for the chunk's motions (a motion block makes at most one): counting the chunk's blocks instead made
        // the last chunks re-reserve the whole stream that was reserved for every motion line at once (a copy of it,
        // and a hole the size of it in the heap, at 150 000 motions a quarter of the budget).
        std::size_t motion_blocks = 0;
        for (std::size_t b = 0; b < chunk_.size(); ++b) motion_blocks += chunk_.block(b).kind == BlockKind::Motion;
        make_room(motion_blocks);
        checker_->check_chunk(chunk_);
        if (now_ms() > until) return false;
    }
}

// The same on two threads (PipelinedCheck): chunks until the slice's time is up (waiting for the reading thread
// when it is behind).
bool DocumentLoader::check_on_two_threads(double until) {
    if (!pipeline_->run([until] { return now_ms() <= until; })) return false;
    stage_ = Stage::Finish;
    return true;
}

// A chunk read (`before`: the reader before it): the document's note of it, how far the reader is, what it counts.
void DocumentLoader::read_chunk_done(TapeReader before, const Tape& chunk) {
    Document& d = *doc_;
    if (chunk.size() == 0) return;
    d.chunks.push_back({std::move(before), static_cast<std::uint32_t>(chunk.first_block()), chunk.block(0).line});
    read_pos_.store(chunk.block(chunk.size() - 1).offset, std::memory_order_relaxed);
    d.blocks += chunk.size();
    d.block_words += chunk.all_words().size();
}

// Room for `motions` more motions in the document's tables (on the thread that writes them).
void DocumentLoader::make_room(std::size_t motions) {
    Document& d = *doc_;
    const std::size_t read = read_pos_.load(std::memory_order_relaxed);
    grow(d.motions, motions, read, d.bytes.size());
    grow(d.arc_centres, motions, read, d.bytes.size());
}

// The check's result, the tables without their spare room, the origin, the diagnostics' marks.
void DocumentLoader::finish() {
    pipeline_.reset();  // (its reading thread is done)
    Document& d = *doc_;
    CheckResult r = plan_later_ ? checker_->finish_before_plan() : checker_->finish();
    record_setup(r, d.setup);  // (the note N403 among the diagnostics, as `essi check` has it)
    d.stats = r.stats;
    d.diagnostics = std::move(r.diagnostics);
    d.bbox = d.stats.motion_bbox;
    if (!plan_later_) {
        checker_.reset();
        sink_.reset();
    }
    reader_.reset();
    chunk_ = Tape{};
    shrink_tables(d);
    if (!d.bbox.empty)
        d.origin = {std::round((d.bbox.min_x + d.bbox.max_x) / 2), std::round((d.bbox.min_y + d.bbox.max_y) / 2)};
    d.place_diagnostics();  // (after the check: a few marks, not a pass over the motions)
    stage_ = Stage::Done;
}

bool DocumentLoader::step_plan(Document& doc, double budget_ms) {
    if (!checker_) return true;
    const double until = now_ms() + budget_ms;
    while (checker_->analyse_plan_plate())
        if (now_ms() > until) return false;
    std::vector<Diagnostic> found = checker_->plan_findings();
    doc.diagnostics.insert(doc.diagnostics.end(), std::make_move_iterator(found.begin()),
                           std::make_move_iterator(found.end()));
    sort_diagnostics(doc.diagnostics);  // (as TapeChecker::finish orders them: the same list as essi check's)
    doc.place_diagnostics();
    checker_.reset();
    sink_.reset();
    motions_.reset();
    return true;
}

float DocumentLoader::plan_progress() const {
    if (!checker_ || checker_->plan_plates() == 0) return 1.f;
    return 1.f - static_cast<float>(checker_->plan_plates_left()) / static_cast<float>(checker_->plan_plates());
}

float DocumentLoader::progress() const {
    const double n = static_cast<double>(std::max<std::size_t>(doc_ ? doc_->bytes.size() : 1, 1));
    switch (stage_) {
        case Stage::IndexLines:
            return static_cast<float>(0.1 * static_cast<double>(doc_ ? doc_->line_index.position() : 0) / n);
        case Stage::ReadAndCheck:
            return static_cast<float>(0.1 + 0.6 * static_cast<double>(read_pos_.load(std::memory_order_relaxed)) / n);
        default: return 0.7f;
    }
}

Msg DocumentLoader::stage() const {
    switch (stage_) {
        case Stage::IndexLines: return Msg::UiStageIndexing;
        case Stage::ReadAndCheck: return Msg::UiStageReading;
        default: return Msg::UiStageBuilding;
    }
}

}  // namespace essi::viewer
