// The reading worker's work on one tape, and what it says to the page. Portable: web/worker/ runs it in a Web
// Worker, the page's WorkerLoader (WorkerLoader.hpp) reads its messages, and the unit tests run both in place.
//   page -> worker: the request's header (encode_reading_request: name, setup) and the tape's bytes beside it;
//   worker -> page: messages, each a kind byte and its body, in this order:
//     Progress     (float share 0..1, Msg stage) every kProgressMs while reading and checking;
//     Document     encode_document (DocumentWire.hpp): the document, its cut plan not analysed yet;
//   page -> worker: analyse the plan now (ReadingWorker::analyse_plan: once the page has drawn the document, where
//     it would analyse the plan itself; so the worker does not take a core from the page's drawing meanwhile);
//   worker -> page:
//     Progress     (the plan's share, Msg::UiStagePlan) every kProgressMs while the plan is analysed;
//     Diagnostics  encode_diagnostics: all of them, the plan's findings among them (the last message);
//     Failed       the request could not be read (WireError::message()): the last message.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "app/DocumentLoader.hpp"
#include "app/DocumentWire.hpp"
#include "essi/i18n.hpp"

namespace essi::viewer {

enum class ReadingMessage : char { Progress = 'p', Document = 'd', Diagnostics = 'f', Failed = 'e' };

struct ReadingProgress {
    float share = 0;
    Msg stage = Msg::None;
};

inline constexpr double kProgressMs = 50;  // the worker's slices between two progress messages

[[nodiscard]] std::string encode_reading_request(std::string_view name, const TapeSetup& setup);

// Each message to the page: its kind, then its body, as soon as it is made.
using PostReadingMessage = std::function<void(ReadingMessage kind, std::string_view body)>;

// One job in the worker, in its two halves.
class ReadingJob {
public:
    // Reads and checks the tape `bytes` as the request `header` says, up to the Document message (or Failed: false).
    bool read(std::string_view header, std::string bytes, const PostReadingMessage& post);
    // The same once the request is read.
    void read(std::string name, std::string bytes, TapeSetup setup, const PostReadingMessage& post);
    // After read(), once the page asks: the cut plan's plates for about budget_ms (then Progress); true when they are
    // all done and the Diagnostics message is sent.
    bool analyse_plan(double budget_ms, const PostReadingMessage& post);

private:
    std::unique_ptr<DocumentLoader> loader_;
    std::unique_ptr<Document> doc_;
};

// A whole job at once, both halves (the unit tests, and the worker's warm-up: read_for_page).
void run_reading_job(std::string_view header, std::string bytes, const PostReadingMessage& post);
void read_for_page(std::string name, std::string bytes, TapeSetup setup, const PostReadingMessage& post);

[[nodiscard]] std::string encode_progress(ReadingProgress p);
[[nodiscard]] bool decode_progress(std::string_view body, ReadingProgress& p);

}  // namespace essi::viewer
