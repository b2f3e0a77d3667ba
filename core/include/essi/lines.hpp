// Lines of a tape: the line-end rule (docs/semantics.md §1) and an index from line numbers to bytes. The reader
// counts lines with the same rule, so a diagnostic's line is the line the index finds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "essi/wire.hpp"

namespace essi {

// A line ends at CR, LF, CR LF or LF CR: the other of CR and LF right after a line end belongs to it.
// (is_not_line_end: the rule as two compares, the form the ESSI reader's hot loop runs fastest.)
[[nodiscard]] constexpr bool is_not_line_end(unsigned char c) { return c != '\n' && c != '\r'; }
[[nodiscard]] constexpr bool is_line_end(unsigned char c) { return !is_not_line_end(c); }
[[nodiscard]] constexpr bool is_line_end(char c) { return is_line_end(static_cast<unsigned char>(c)); }
// Whether `next`, right after the line end `end` (a CR or LF), belongs to it (CR ^ LF: no branch).
[[nodiscard]] constexpr bool is_line_end_pair(char end, char next) { return (next ^ end) == ('\r' ^ '\n'); }
// The start of the next line after the line end at `end`, when the byte after it is there to read.
// (The reader's hot loop: the bytes as unsigned, the test as is_line_end_pair's.)
[[nodiscard]] inline const unsigned char* past_line_end(const unsigned char* end) {
    return end + 1 + ((end[1] ^ end[0]) == ('\r' ^ '\n'));
}
// The same as a position, for a line end at `end` < size that may be the last byte.
[[nodiscard]] inline std::uint32_t past_line_end(const unsigned char* data, std::uint32_t end, std::uint32_t size) {
    return end + 1 < size ? static_cast<std::uint32_t>(past_line_end(data + end) - data) : end + 1;
}

// The first line end (CR or LF) at or after `pos`, or bytes.size() when the line runs to the end of the bytes.
[[nodiscard]] std::size_t find_line_end(std::string_view bytes, std::size_t pos);
// The start of the line holding `pos` (<= bytes.size()): the byte after the line end before it, or 0.
[[nodiscard]] constexpr std::size_t find_line_start(std::string_view bytes, std::size_t pos) {
    while (pos > 0 && !is_line_end(bytes[pos - 1])) --pos;
    return pos;
}

// A line without the blanks (spaces and tabs) around it: how every reader and scan of a tape sees a line's text.
[[nodiscard]] constexpr std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}
// 1-based column of a byte offset (counts bytes from the start of its line).
[[nodiscard]] std::uint32_t column_of(std::string_view bytes, std::uint32_t offset);
// The source text of the line holding `offset`, without its line end.
[[nodiscard]] std::string_view line_text(std::string_view bytes, std::uint32_t offset);

// Where each line of a tape starts, kept sparsely (one offset per kStride lines: 4 bytes per 64 lines), built
// a slice at a time so that a caller with a frame budget can spread it over frames. A line end at the very end
// of the bytes starts no line; empty bytes have no line.
class LineIndex {
public:
    static constexpr std::size_t kStride = 64;

    // Indexes up to `max_bytes` more of `bytes` (the same bytes on every call). Returns true when all are done.
    bool build(std::string_view bytes, std::size_t max_bytes = static_cast<std::size_t>(-1));
    [[nodiscard]] bool done(std::string_view bytes) const { return started_ && pos_ >= bytes.size(); }
    // Bytes indexed so far.
    [[nodiscard]] std::size_t position() const { return pos_; }

    [[nodiscard]] std::size_t line_count() const { return lines_; }
    // Lines that start with a sign ('+' or '-'): the motion blocks of a tape, near enough (a reservation hint).
    [[nodiscard]] std::size_t signed_lines() const { return signed_lines_; }
    // Line `n` (1-based) without its line end; empty when there is no such line.
    [[nodiscard]] std::string_view line(std::string_view bytes, std::size_t n) const;
    [[nodiscard]] std::size_t memory_bytes() const { return starts_.capacity() * sizeof(std::uint32_t); }
    void shrink_to_fit() { starts_.shrink_to_fit(); }
    // The index as bytes, and read back (false when the bytes are not one): what the viewer's worker hands its page.
    void save(WireWriter& out) const;
    [[nodiscard]] bool restore(WireReader& in);

private:
    std::vector<std::uint32_t> starts_;  // byte offset of line 1 + k * kStride
    std::size_t lines_ = 0;
    std::size_t signed_lines_ = 0;
    std::size_t pos_ = 0;
    bool started_ = false;
};

}  // namespace essi
