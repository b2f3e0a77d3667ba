// Loads a document in steps that each take about `budget_ms` (so the page keeps drawing): the line index,
// then TapeReader chunks through essi::TapeChecker (the statistics and diagnostics of `essi check`), the
// viewer's compact stream taken on the way (DocumentSink, TapeChecker's `also` sink), the blocks appended to the
// Tape. Where the build has threads, a tape of `two_threads_min_bytes` or more is checked on two
// (essi::PipelinedCheck): a thread of its own reads it and feeds the cut plan and the document, this one interprets.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>

#include "app/Document.hpp"
#include "app/DocumentSource.hpp"
#include "essi/i18n.hpp"
#include "essi/pipeline.hpp"
#include "essi/pipelined_check.hpp"

namespace essi::viewer {

class DocumentSink;

class DocumentLoader final : public DocumentSource {
public:
    // `plan_later`: the cut plan's plates are kept while the tape is read and analysed after it (step_plan), from
    // the document's motions (TapeChecker::defer_plan): the document is drawn first, its plan's findings follow.
    DocumentLoader(std::string name, std::string bytes, TapeSetup setup, bool plan_later = false,
                   std::size_t two_threads_min_bytes = kPipelineMinBytes);
    ~DocumentLoader() override;
    // Runs for about budget_ms; returns true when the document is complete (but for the plan's findings when
    // plan_later: plan_pending()).
    bool step(double budget_ms) override;
    [[nodiscard]] float progress() const override;
    [[nodiscard]] Msg stage() const override;
    [[nodiscard]] std::unique_ptr<Document> take() override { return std::move(doc_); }
    // After step() returned true and take(): the cut plan's plates still to analyse.
    [[nodiscard]] bool plan_pending() const override { return checker_ != nullptr; }
    // Analyses plates for about budget_ms; when the last is done, its findings join `doc`'s diagnostics (sorted,
    // their marks placed) and true is returned. `doc` is the document this loader made.
    bool step_plan(Document& doc, double budget_ms) override;
    [[nodiscard]] float plan_progress() const override;
    // Whether the tape is checked on two threads (known once the reading began).
    [[nodiscard]] bool two_threads() const { return two_threads_; }

private:
    class Motions;
    // The stages; each returns false when the slice's time (`until`, now_ms) ran out before it was done.
    bool index_lines(double until);
    void start_reading();
    bool read_and_check(double until);
    bool check_on_two_threads(double until);
    void read_chunk_done(TapeReader before, const Tape& chunk);
    void make_room(std::size_t motions);
    void finish();

    std::unique_ptr<Document> doc_;
    std::unique_ptr<DocumentSink> sink_;
    std::unique_ptr<Motions> motions_;  // the document's motions, read back by the kept plates (plan_later)
    bool plan_later_ = false;
    std::unique_ptr<TapeReader> reader_;
    std::size_t two_threads_min_bytes_;
    std::unique_ptr<PipelinedCheck> pipeline_;  // instead of reader_, from two_threads_min_bytes_
    bool two_threads_ = false;
    std::unique_ptr<TapeChecker> checker_;
    Tape chunk_;
    enum class Stage { IndexLines, ReadAndCheck, Finish, Done };
    Stage stage_ = Stage::IndexLines;
    static constexpr std::size_t kMotionReserveSlack = 64;  // 1/64 more for addressed motions ("1+100+0")
    // The byte offset reached by the reader (atomic: with two threads, read by the one that makes room for motions).
    std::atomic<std::size_t> read_pos_{0};
};

}  // namespace essi::viewer
