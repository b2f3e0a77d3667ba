#include "app/ReadingJob.hpp"

#include "app/DocumentLoader.hpp"
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

void run_reading_job(std::string_view header, std::string bytes, const PostReadingMessage& post) {
    WireReader in(header);
    std::string name, setup_wire;
    if (!in.get_string(name) || !in.get_string(setup_wire) || !in.at_end()) {
        post(ReadingMessage::Failed, WireError{"request", in.position()}.message());
        return;
    }
    TapeSetup setup;
    if (WireError error; !decode_setup(setup_wire, setup, error)) {
        post(ReadingMessage::Failed, error.message());
        return;
    }
    read_for_page(std::move(name), std::move(bytes), std::move(setup), post);
}

void read_for_page(std::string name, std::string bytes, TapeSetup setup, const PostReadingMessage& post) {
    // The plan's plates are analysed after the document is handed over: the page draws it meanwhile.
    DocumentLoader loader(std::move(name), std::move(bytes), std::move(setup), true);
    while (!loader.step(kProgressMs))
        post(ReadingMessage::Progress, encode_progress({loader.progress(), loader.stage()}));
    const std::unique_ptr<Document> doc = loader.take();
    post(ReadingMessage::Document, encode_document(*doc));
    while (!loader.step_plan(*doc, kProgressMs))
        post(ReadingMessage::Progress, encode_progress({loader.plan_progress(), Msg::UiStagePlan}));
    post(ReadingMessage::Diagnostics, encode_diagnostics(doc->diagnostics));
}

}  // namespace essi::viewer
