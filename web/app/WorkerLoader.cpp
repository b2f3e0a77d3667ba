#include "app/WorkerLoader.hpp"

#include <utility>

namespace essi::viewer {

namespace {
std::uint32_t g_next_job = 1;
}

WorkerLoader::WorkerLoader(ReadingWorker& worker, std::string name, std::string bytes, TapeSetup setup)
    : worker_(worker), job_(g_next_job++), name_(std::move(name)), bytes_(std::move(bytes)), setup_(std::move(setup)) {
    worker_.post(job_, encode_reading_request(name_, setup_), bytes_);
}

WorkerLoader::~WorkerLoader() {
    if (job_open_) worker_.cancel(job_);
}

// The messages that came.
void WorkerLoader::receive() {
    while (job_open_) {
        std::optional<std::string> m = worker_.receive(job_);
        if (!m) return;
        if (m->empty()) return fail("an empty message");
        const std::string_view body = std::string_view(*m).substr(1);
        switch (static_cast<ReadingMessage>(m->front())) {
            case ReadingMessage::Progress:
                if (!decode_progress(body, progress_)) return fail("a progress message it cannot read");
                break;
            case ReadingMessage::Document: {
                WireError error;
                doc_ = decode_document(body, bytes_, error);
                if (!doc_) return fail(error.message());
                doc_received_ = true;
                break;
            }
            case ReadingMessage::Diagnostics:
                diagnostics_ = std::string(body);
                diagnostics_received_ = true;
                job_open_ = false;
                break;
            case ReadingMessage::Failed: return fail(std::string(body));
            default: return fail("a message of an unknown kind");
        }
    }
}

void WorkerLoader::fail(std::string why) {
    failure_ = std::move(why);
    if (job_open_) worker_.cancel(job_);
    job_open_ = false;
    diagnostics_received_ = false;
    if (!doc_received_) local_ = std::make_unique<DocumentLoader>(name_, std::move(bytes_), setup_, true);
}

bool WorkerLoader::step(double budget_ms) {
    if (!local_) receive();
    if (local_) return local_->step(budget_ms);
    return doc_received_;
}

bool WorkerLoader::plan_pending() const { return local_ ? local_->plan_pending() : !plan_done_; }

Msg WorkerLoader::stage() const {
    if (local_) return local_->stage();
    return progress_.stage == Msg::None ? Msg::UiStageReading : progress_.stage;
}

bool WorkerLoader::step_plan(Document& doc, double budget_ms) {
    if (local_) return local_->step_plan(doc, budget_ms);
    if (!failure_.empty()) return step_plan_on_page(doc, budget_ms);
    if (!plan_asked_ && job_open_) worker_.analyse_plan(job_);
    plan_asked_ = true;
    receive();
    if (!failure_.empty() || !diagnostics_received_) return false;
    WireError error;
    std::vector<Diagnostic> all;
    if (!decode_diagnostics(diagnostics_, all, error)) {
        fail(error.message());
        return false;
    }
    doc.diagnostics = std::move(all);
    doc.place_diagnostics();
    plan_done_ = true;
    return true;
}

// The tape read and checked again on the page (plan and all): its diagnostics are the document's.
bool WorkerLoader::step_plan_on_page(Document& doc, double budget_ms) {
    if (!local_plan_) local_plan_ = std::make_unique<DocumentLoader>(name_, doc.bytes, setup_, false);
    if (!local_plan_->step(budget_ms)) return false;
    doc.diagnostics = std::move(local_plan_->take()->diagnostics);
    doc.place_diagnostics();
    local_plan_.reset();
    plan_done_ = true;
    return true;
}

}  // namespace essi::viewer
