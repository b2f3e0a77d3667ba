// A document read by the reading worker (ReadingWorker.hpp, ReadingJob.hpp): the page hands the tape over and
// only picks up the worker's messages (progress, the document, then its cut plan's findings), so reading and
// checking take none of its thread. When the worker fails (its Failed message, a message the page cannot read),
// the tape is read on the page instead (DocumentLoader) and failure() says why: nothing of the tape is lost.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "app/DocumentLoader.hpp"
#include "app/DocumentSource.hpp"
#include "app/ReadingJob.hpp"
#include "app/ReadingWorker.hpp"

namespace essi::viewer {

class WorkerLoader final : public DocumentSource {
public:
    WorkerLoader(ReadingWorker& worker, std::string name, std::string bytes, TapeSetup setup);
    ~WorkerLoader() override;
    WorkerLoader(const WorkerLoader&) = delete;
    WorkerLoader& operator=(const WorkerLoader&) = delete;

    bool step(double budget_ms) override;
    [[nodiscard]] std::unique_ptr<Document> take() override { return local_ ? local_->take() : std::move(doc_); }
    [[nodiscard]] bool plan_pending() const override;
    bool step_plan(Document& doc, double budget_ms) override;
    [[nodiscard]] float progress() const override {
        return local_ ? local_->progress() : doc_received_ ? 1.f : progress_.share;
    }
    [[nodiscard]] Msg stage() const override;
    [[nodiscard]] float plan_progress() const override {
        return local_ ? local_->plan_progress() : doc_received_ ? progress_.share : 0.f;
    }
    [[nodiscard]] bool works_on_page() const override { return local_ != nullptr || !failure_.empty(); }
    [[nodiscard]] std::string_view failure() const override { return failure_; }

private:
    void receive();
    // The worker failed: the page reads the tape itself (before the document came: all of it, from bytes_;
    // after: again, from the document's bytes, for the cut plan's findings only).
    void fail(std::string why);
    bool step_plan_on_page(Document& doc, double budget_ms);

    ReadingWorker& worker_;
    std::uint32_t job_ = 0;
    bool job_open_ = true;  // the worker may still send messages of the job
    std::string name_, bytes_;
    TapeSetup setup_;
    std::unique_ptr<Document> doc_;
    bool doc_received_ = false;
    std::string diagnostics_;  // the Diagnostics message's body, when it came
    bool diagnostics_received_ = false;
    bool plan_asked_ = false;  // the worker was told to analyse the plan
    bool plan_done_ = false;   // step_plan put all the diagnostics into the document
    ReadingProgress progress_;
    std::unique_ptr<DocumentLoader> local_;       // reading on the page, when the worker failed before the document
    std::unique_ptr<DocumentLoader> local_plan_;  // ... after it: the page's own check gives the plan's findings
    std::string failure_;
};

}  // namespace essi::viewer
