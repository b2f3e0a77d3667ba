// What every front end of core/read/ shares (internal): the reader's position, line and counts, what a block, an
// error and the program's end do to them, and the chunk loop that drives a front end over the lines of a tape.
// A front end (EssiReader, EiaReader) derives from ReaderDriver<itself> and supplies only how its lines become
// blocks; the driver calls it without a virtual call, so the line loop compiles as one piece.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "essi/function_codes.hpp"
#include "essi/lines.hpp"
#include "essi/read.hpp"

namespace essi::detail {

// Reading stops after this many errors (E115): the bytes are most likely not a tape.
constexpr std::size_t kMaxReadErrors = 100;

// A byte as two hex digits ("C3"), as the messages quote it.
[[nodiscard]] std::string hex_byte(unsigned char c);

// The state every front end keeps, and what reading a block, an error and the program's end does to it.
class ReaderState : public BlockReader {
protected:
    // `too_many_errors`: the front end's message for E115 (what the tape was expected to look like).
    ReaderState(std::string_view bytes, const Profile& profile, Msg too_many_errors);

    // A diagnostic at `offset` of the current line; E115 and nothing more once kMaxReadErrors errors are reached.
    void report(Severity sev, DiagCode code, std::uint32_t offset, Msg msg, MessageArgs args = {});
    // Appends a block on the current line; its words (`packed`'s count) have been appended before it. A block
    // other than % or a comment starts the program, and reports a % that came in the program before it (W112).
    void push_block(std::uint32_t offset, BlockKind kind, std::uint16_t code, std::uint8_t packed);
    // The block just pushed ends the program.
    void mark_program_end();
    // Whether the profile ends the program with function `code`, or with the mark '/' or '='.
    [[nodiscard]] bool is_end_function(long long code) const {
        return code >= 0 && code < fn::kCodeCount && end_function_[static_cast<std::size_t>(code)];
    }
    [[nodiscard]] bool is_end_mark(char mark) const;
    // 1-based column of `offset` on the current line.
    [[nodiscard]] std::uint32_t column(std::uint32_t offset) const { return offset - line_begin_ + 1; }
    [[nodiscard]] Tape& chunk() { return *chunk_; }
    // The bytes a reader reads: positions are 32-bit (a larger tape is E117).
    [[nodiscard]] std::uint32_t readable_size() const {
        return static_cast<std::uint32_t>(
            std::min<std::size_t>(src_.size(), std::numeric_limits<std::uint32_t>::max()));
    }

    // The chunk keeping of the driver: begin_chunk empties `chunk` for the next blocks and says whether this is
    // the tape's first chunk and it can be read (else E117: the bytes are too large for 32-bit positions);
    // finish_chunk ends it with the bytes read up to `pos`, and says whether the tape's closing diagnostics are
    // due (all of it is read, and reading was not stopped); report_tape_end gives those every front end gives.
    bool begin_chunk(Tape& chunk);
    bool finish_chunk(Tape& chunk, std::uint32_t pos);
    void report_tape_end(Tape& chunk);
    // BlockReader::save and restore of what every front end keeps (between chunks: the chunk's own counts are
    // not kept); the format's own state follows it (ReaderDriver).
    void save_state(WireWriter& out) const;
    [[nodiscard]] bool restore_state(WireReader& in);

    std::string_view src_;
    const Profile& profile_;
    Tape* chunk_ = nullptr;         // the chunk being filled
    std::uint32_t pos_ = 0;         // the next byte to read
    std::uint32_t line_ = 1;        // the current line (every CR, LF, CR LF or LF CR counts one)
    std::uint32_t line_begin_ = 0;  // its first byte (columns count from it)
    std::uint32_t last_line_ = 0;   // the line of the last block
    std::uint32_t end_line_ = 0;    // the line of the block that ended the program
    // A % after the program has started is a rewind-stop mark when nothing follows it; it is reported (W112)
    // only when another block comes after it.
    std::uint32_t percent_line_ = 0, percent_column_ = 0;
    std::size_t total_blocks_ = 0;    // blocks of all earlier chunks
    std::size_t chunk_blocks_ = 0;    // blocks in the chunk being filled
    std::size_t chunk_comments_ = 0;  // comment blocks among them
    std::size_t errors_ = 0;
    bool started_ = false;          // the first chunk has begun
    bool finished_ = false;         // the closing diagnostics have been given
    bool stopped_ = false;          // too many errors, or too many bytes: nothing more is read
    bool after_end_seen_ = false;   // content after the end was reported: nothing more is read
    bool ended_ = false;            // the program has ended
    bool program_started_ = false;  // a block other than % (and comments) has been read
    Msg too_many_errors_;
    std::array<bool, fn::kCodeCount> end_function_{};  // the profile's end codes, by function code
};

inline void ReaderState::push_block(std::uint32_t offset, BlockKind kind, std::uint16_t code, std::uint8_t packed) {
    Tape& t = *chunk_;
    if (percent_line_ != 0 && kind != BlockKind::Comment) [[unlikely]] {
        diagnostics_of(t).push_back(make_diagnostic(Severity::Warning, DiagCode::W112_MisplacedPercent, percent_line_,
                                                    percent_column_, Msg::ReadMisplacedPercent));
        percent_line_ = 0;
    }
    if (kind == BlockKind::Comment) ++chunk_comments_;
    else if (kind != BlockKind::Percent) program_started_ = true;
    if (chunk_blocks_ % Tape::kWordIndexStride == 0)
        word_index_of(t).push_back(static_cast<std::uint32_t>(words_of(t).size()) - (packed & Block::kWordCountMask));
    blocks_of(t).push_back(Block{offset, line_, code, kind, packed});
    ++chunk_blocks_;
    last_line_ = line_;
}

// The chunk loop of a front end `Format` (which derives from ReaderDriver<Format>): begin a chunk, read lines until
// the chunk has its blocks or the tape ends, finish the chunk, and give the closing diagnostics after the last line.
// `Format` supplies
//   bool read_line(std::uint32_t begin, std::uint32_t end, std::size_t max_blocks)
//       the line from `begin` to its line end `end` (line_ and line_begin_ are set): its blocks and diagnostics;
//       false when it is left unread (its blocks do not fit in the chunk, or nothing more is to be read);
// and may replace the driver's
//   void begin_tape()             before the first line of the tape;
//   std::uint32_t read_run(std::uint32_t pos, std::uint32_t size, std::size_t max_blocks)
//       lines read its quick way from `pos` (keeping line_ up to date): the first line it did not read, or `size`;
//   void end_tape(Tape& chunk)    its own closing diagnostics, before the shared ones;
//   void save_own(WireWriter&) const, bool restore_own(WireReader&)
//                                 the state it keeps from one chunk to the next (its modes), for save/restore.
template <class Format>
class ReaderDriver : public ReaderState {
public:
    bool read_chunk(Tape& chunk, std::size_t max_blocks) final;
    [[nodiscard]] std::unique_ptr<BlockReader> clone() const final {
        return std::make_unique<Format>(static_cast<const Format&>(*this));
    }
    [[nodiscard]] std::size_t state_bytes() const final { return sizeof(Format); }
    void save(WireWriter& out) const final {
        save_state(out);
        static_cast<const Format&>(*this).save_own(out);
    }
    [[nodiscard]] bool restore(WireReader& in) final { return restore_state(in) && format().restore_own(in); }

protected:
    using ReaderState::ReaderState;

    void begin_tape() {}
    // The format's own state between chunks (none by default).
    void save_own(WireWriter& /*out*/) const {}
    [[nodiscard]] bool restore_own(WireReader& /*in*/) { return true; }
    std::uint32_t read_run(std::uint32_t pos, std::uint32_t /*size*/, std::size_t /*max_blocks*/) { return pos; }
    void end_tape(Tape& /*chunk*/) {}

private:
    Format& format() { return static_cast<Format&>(*this); }
};

template <class Format>
bool ReaderDriver<Format>::read_chunk(Tape& chunk, std::size_t max_blocks) {
    if (finished_) return false;
    if (begin_chunk(chunk)) format().begin_tape();
    const std::uint32_t size = readable_size();
    std::uint32_t pos = pos_;
    while (pos < size && !stopped_ && !after_end_seen_) {
        pos = format().read_run(pos, size, max_blocks);
        if (pos >= size || stopped_) break;
        const auto end = static_cast<std::uint32_t>(find_line_end({src_.data(), size}, pos));
        line_begin_ = pos;
        if (!format().read_line(pos, end, max_blocks)) break;
        if (end >= size) {
            pos = size;
            break;
        }
        pos = past_line_end(reinterpret_cast<const unsigned char*>(src_.data()), end, size);
        ++line_;
    }
    if (finish_chunk(chunk, pos)) {
        format().end_tape(chunk);
        report_tape_end(chunk);
    }
    return true;
}

}  // namespace essi::detail
