// The reading worker's work on one tape, and what it says to the page. Portable: web/worker/ runs it in a Web
// Worker, the page's WorkerLoader (WorkerLoader.hpp) reads its messages, and the unit tests run both in place.
//   page -> worker: the request's header (encode_reading_request: name, setup) and the tape's bytes beside it;
//   worker -> page: messages, each a kind byte and its body, in this order:
//     Progress     (float share 0..1, Msg stage) every kProgressMs while reading and checking;
//     Document     encode_document (DocumentWire.hpp): the document, its cut plan still being analysed;
//     Progress     (the plan's share, Msg::UiStagePlan) every kProgressMs while the plan is analysed;
//     Diagnostics  encode_diagnostics: all of them, the plan's findings among them (the last message);
//     Failed       the request could not be read (WireError::message()): the last message.
#pragma once

#include <functional>
#include <string>
#include <string_view>

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

// Reads and checks the tape `bytes` as the request `header` says, giving each message to `post` (its kind, then
// its body) as soon as it is made.
using PostReadingMessage = std::function<void(ReadingMessage kind, std::string_view body)>;
void run_reading_job(std::string_view header, std::string bytes, const PostReadingMessage& post);
// The job once its request is read (what the worker's warm-up runs too).
void read_for_page(std::string name, std::string bytes, TapeSetup setup, const PostReadingMessage& post);

[[nodiscard]] std::string encode_progress(ReadingProgress p);
[[nodiscard]] bool decode_progress(std::string_view body, ReadingProgress& p);

}  // namespace essi::viewer
