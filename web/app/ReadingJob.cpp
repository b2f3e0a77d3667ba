#include "app/ReadingJob.hpp"

#include "essi/wire.hpp"

namespace essi::viewer {

std::string encode_reading_request(std::string_view name, const TapeSetup& setup) {
    WireWriter out;
    out.put_string(name);
    out.put_string(encode_setup(setup));
    return out.take();
}

std::string encode_progress(ReadingProgress p) {
    WireWriter out;
    out.put(p.share);
    out.put(p.stage);
    return out.take();
}

bool decode_progress(std::string_view body, ReadingProgress& p) {
    WireReader in(body);
    return in.get(p.share) && in.get(p.stage) && in.at_end();
}

bool ReadingJob::read(std::string_view header, std::string bytes, const PostReadingMessage& post) {
    WireReader in(header);
    std::string name, setup_wire;
    if (!in.get_string(name) || !in.get_string(setup_wire) || !in.at_end()) {
        post(ReadingMessage::Failed, WireError{"request", in.position()}.message());
        return false;
    }
    TapeSetup setup;
    if (WireError error; !decode_setup(setup_wire, setup, error)) {
        post(ReadingMessage::Failed, error.message());
        return false;
    }
    read(std::move(name), std::move(bytes), std::move(setup), post);
    return true;
}

void ReadingJob::read(std::string name, std::string bytes, TapeSetup setup, const PostReadingMessage& post) {
    // The plan's plates are analysed after the document is handed over: the page draws it meanwhile.
    loader_ = std::make_unique<DocumentLoader>(std::move(name), std::move(bytes), std::move(setup), true);
    while (!loader_->step(kProgressMs))
        post(ReadingMessage::Progress, encode_progress({loader_->progress(), loader_->stage()}));
    doc_ = loader_->take();
    post(ReadingMessage::Document, encode_document(*doc_));
}

bool ReadingJob::analyse_plan(double budget_ms, const PostReadingMessage& post) {
    if (!loader_) return true;
    if (!loader_->step_plan(*doc_, budget_ms)) {
        post(ReadingMessage::Progress, encode_progress({loader_->plan_progress(), Msg::UiStagePlan}));
        return false;
    }
    post(ReadingMessage::Diagnostics, encode_diagnostics(doc_->diagnostics));
    loader_.reset();
    doc_.reset();
    return true;
}

void run_reading_job(std::string_view header, std::string bytes, const PostReadingMessage& post) {
    ReadingJob job;
    if (!job.read(header, std::move(bytes), post)) return;
    while (!job.analyse_plan(kProgressMs, post)) {
    }
}

void read_for_page(std::string name, std::string bytes, TapeSetup setup, const PostReadingMessage& post) {
    ReadingJob job;
    job.read(std::move(name), std::move(bytes), std::move(setup), post);
    while (!job.analyse_plan(kProgressMs, post)) {
    }
}

}  // namespace essi::viewer
