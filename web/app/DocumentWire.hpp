// A Document as bytes and back: what the reading worker (ReadingJob.hpp) hands the page. Everything but the tape's
// bytes, which the page has: the tables as they lie in memory (both sides are one build), the diagnostics and
// statistics through the core's save/restore, the reader before each chunk as its checkpoint
// (TapeReader::checkpoint), the setup's profile as its JSON. A decode that fails says where and what it expected.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/Document.hpp"

namespace essi::viewer {

// What a decode that failed says: the part it was reading and the byte it stopped at.
struct WireError {
    std::string what;
    std::size_t at = 0;
    [[nodiscard]] std::string message() const;  // "the reading worker's message is cut short or wrong at byte ..."
};

[[nodiscard]] std::string encode_setup(const TapeSetup& setup);
// False (with `error`) when `wire` is not a setup encode_setup made.
[[nodiscard]] bool decode_setup(std::string_view wire, TapeSetup& setup, WireError& error);

// The document without its bytes.
[[nodiscard]] std::string encode_document(const Document& doc);
// The document `wire` holds, with `bytes` (the tape it was read from, moved into it); null (with `error`, and
// the bytes left in `bytes`) when it is not one.
[[nodiscard]] std::unique_ptr<Document> decode_document(std::string_view wire, std::string& bytes, WireError& error);

[[nodiscard]] std::string encode_diagnostics(const std::vector<Diagnostic>& diagnostics);
[[nodiscard]] bool decode_diagnostics(std::string_view wire, std::vector<Diagnostic>& diagnostics, WireError& error);

}  // namespace essi::viewer
