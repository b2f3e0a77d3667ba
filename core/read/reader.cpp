// Phase 1, read: bytes -> blocks (ESSI-SEMANTICS §1-2). One pass over the bytes, no allocation per block
// beyond the two growing arrays. The reader knows characters and word counts, not what a function does,
// except for the three things that change how the following bytes are read: 3/4 ignore sections, the
// end of the program, and the % mark.
#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>

#include "essi/read.hpp"

namespace essi {
namespace {

constexpr std::size_t kMaxReadErrors = 100;    // then E115: reading stops (a binary file, most likely)
constexpr int kMaxWordDigits = 9;              // significant digits of a dimension word or value
constexpr int kMaxFunctionDigits = 3;          // ISO 6582 3.4.1
constexpr int kIgnoreOnCode = 3;
constexpr int kIgnoreOffCode = 4;

enum CharClass : std::uint8_t { kOther, kDigit, kPlus, kMinus, kSpace, kLineEnd, kPercent, kSlash, kEquals, kHigh };

constexpr std::array<std::uint8_t, 256> make_classes() {
    std::array<std::uint8_t, 256> t{};
    for (int c = 0; c < 256; ++c) t[c] = c >= 0x80 ? kHigh : kOther;
    for (int c = '0'; c <= '9'; ++c) t[c] = kDigit;
    t['+'] = kPlus;
    t['-'] = kMinus;
    t[' '] = kSpace;
    t['\t'] = kSpace;
    t['\r'] = kLineEnd;
    t['\n'] = kLineEnd;
    t['%'] = kPercent;
    t['/'] = kSlash;
    t['='] = kEquals;
    return t;
}
constexpr std::array<std::uint8_t, 256> kClass = make_classes();

std::string describe_byte(unsigned char c) {
    char buf[32];
    if (c >= 0x21 && c < 0x7F) std::snprintf(buf, sizeof buf, "'%c' (0x%02X)", c, c);
    else std::snprintf(buf, sizeof buf, "byte 0x%02X", c);
    return buf;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

}  // namespace

class Reader {
public:
    Reader(std::string_view bytes, const Profile& profile, Tape& tape)
        : src_(bytes), profile_(profile), tape_(tape) {}

    void run();

private:
    // One line's parse, before classification.
    struct LineParse {
        int lead_digits = 0;          // digits of the leading unsigned number as written
        long long lead_value = 0;
        int words = 0;
        std::uint8_t sign_flags = 0;  // Block::kTcNegative / kTpNegative
        bool failed = false;
        bool blank = true;
        int mark = 0;                 // '%', '/' or '=' when the block is that mark
    };

    void read_line(std::uint32_t begin, std::uint32_t end);
    void read_ignored_line(std::uint32_t begin, std::uint32_t end);
    void after_end_line(std::uint32_t begin, std::uint32_t end);
    bool parse_words(std::uint32_t begin, std::uint32_t end, LineParse& lp);
    void push_block(std::uint32_t offset, BlockKind kind, std::uint16_t code, std::uint8_t packed);
    void report(Severity sev, DiagCode code, std::uint32_t offset, std::string message);
    [[nodiscard]] bool is_end_function(long long code) const;
    [[nodiscard]] bool is_end_mark(char mark) const;
    [[nodiscard]] std::uint32_t column(std::uint32_t offset) const { return offset - line_begin_ + 1; }

    std::string_view src_;
    const Profile& profile_;
    Tape& tape_;
    std::uint32_t line_ = 1;
    std::uint32_t line_begin_ = 0;
    std::size_t errors_ = 0;
    bool stopped_ = false;          // too many errors: nothing more is read
    bool after_end_seen_ = false;   // content after the end was reported: nothing more is read
    bool in_ignore_ = false;
    std::uint32_t ignore_line_ = 0, ignore_column_ = 0;
    bool ended_ = false;
    bool program_started_ = false;  // a block other than % has been read
    // A % after the program has started is a rewind-stop mark when nothing follows it; it is reported
    // (W112) only when another block comes after it.
    std::uint32_t percent_line_ = 0, percent_column_ = 0;
    std::uint32_t last_line_ = 0;
};

void Reader::report(Severity sev, DiagCode code, std::uint32_t offset, std::string message) {
    if (stopped_) return;
    tape_.diagnostics_.push_back({sev, code, line_, column(offset), std::move(message)});
    if (sev == Severity::Error && ++errors_ >= kMaxReadErrors) {
        tape_.diagnostics_.push_back({Severity::Error, DiagCode::E115_TooManyErrors, line_, column(offset),
                                      "reading stopped after " + std::to_string(kMaxReadErrors) +
                                          " errors; this does not look like an ESSI tape (expected lines of + - 0-9)"});
        stopped_ = true;
    }
}

bool Reader::is_end_function(long long code) const {
    return std::any_of(profile_.end_codes.begin(), profile_.end_codes.end(),
                       [&](const EndCode& e) { return e.function >= 0 && e.function == code; });
}

bool Reader::is_end_mark(char mark) const {
    return std::any_of(profile_.end_codes.begin(), profile_.end_codes.end(),
                       [&](const EndCode& e) { return e.function < 0 && e.mark == mark; });
}

void Reader::push_block(std::uint32_t offset, BlockKind kind, std::uint16_t code, std::uint8_t packed) {
    if (percent_line_ != 0 && kind != BlockKind::Comment) {
        tape_.diagnostics_.push_back({Severity::Warning, DiagCode::W112_MisplacedPercent, percent_line_, percent_column_,
                                      "a % mark in the middle of the program is ignored; % belongs before the first "
                                      "block or after the end"});
        percent_line_ = 0;
    }
    if (tape_.blocks_.size() % Tape::kWordIndexStride == 0)
        tape_.word_index_.push_back(static_cast<std::uint32_t>(tape_.words_.size()) - (packed & Block::kWordCountMask));
    Block b;
    b.offset = offset;
    b.line = line_;
    b.code = code;
    b.kind = kind;
    b.packed = packed;
    tape_.blocks_.push_back(b);
    last_line_ = line_;
}

void Reader::run() {
    if (src_.size() > std::numeric_limits<std::uint32_t>::max()) {
        tape_.diagnostics_.push_back({Severity::Error, DiagCode::E117_TapeTooLarge, 0, 0,
                                      "the tape has " + std::to_string(src_.size()) +
                                          " bytes; essikit reads tapes of at most 4 GiB"});
        return;
    }
    // A rough reservation: one block per 10 bytes, two words per block.
    tape_.blocks_.reserve(src_.size() / 10 + 16);
    tape_.words_.reserve(src_.size() / 5 + 16);

    const char* data = src_.data();
    const auto size = static_cast<std::uint32_t>(src_.size());
    std::uint32_t pos = 0;
    std::uint32_t skip = 0;  // a UTF-8 byte order mark: reported, then the line is read without it
    if (src_.substr(0, 3) == "\xEF\xBB\xBF") {
        report(Severity::Error, DiagCode::E102_NonAsciiByte, 0,
               "the tape starts with a UTF-8 byte order mark (EF BB BF); ESSI tapes are plain ASCII: save the file "
               "without a BOM");
        skip = 3;
    }
    while (pos < size && !stopped_ && !after_end_seen_) {
        // Find the end of this line.
        std::uint32_t end = pos;
        while (end < size && data[end] != '\n' && data[end] != '\r') ++end;
        line_begin_ = pos;
        const std::uint32_t from = pos + skip;
        skip = 0;
        if (ended_) after_end_line(from, end);
        else if (in_ignore_) read_ignored_line(from, end);
        else read_line(from, end);
        if (end >= size) break;
        // One line end: CR, LF, CR LF or LF CR.
        const char c = data[end];
        pos = end + 1;
        if (pos < size && (data[pos] == '\n' || data[pos] == '\r') && data[pos] != c) ++pos;
        ++line_;
    }
    if (stopped_) {
        tape_.end_block_ = tape_.blocks_.size();
        return;
    }
    if (in_ignore_) {
        tape_.diagnostics_.push_back({Severity::Error, DiagCode::E107_UnclosedIgnore, ignore_line_, ignore_column_,
                                      "ignore ON (3) is never switched off: expected a block 4 (ignore OFF) "
                                      "after it; everything after line " + std::to_string(ignore_line_) +
                                          " is ignored"});
    }
    if (tape_.blocks_.empty()) {
        tape_.diagnostics_.push_back({Severity::Error, DiagCode::E113_EmptyTape, 1, 1,
                                      "the tape holds no block; expected ESSI blocks such as 7, +100+0, 63"});
    } else if (!ended_) {
        tape_.diagnostics_.push_back({Severity::Warning, DiagCode::W114_NoProgramEnd, last_line_, 1,
                                      "the tape ends without an end of program; expected 63, 64 or / as the last block"});
    }
    if (!ended_) tape_.end_block_ = tape_.blocks_.size();
    // The reservation above is generous; give back what the tape did not use.
    tape_.blocks_.shrink_to_fit();
    tape_.words_.shrink_to_fit();
}

void Reader::read_ignored_line(std::uint32_t begin, std::uint32_t end) {
    const std::string_view text = src_.substr(begin, end - begin);
    const std::string_view t = trim(text);
    if (t == "4") {
        in_ignore_ = false;
        push_block(begin + static_cast<std::uint32_t>(text.find('4')), BlockKind::Function, kIgnoreOffCode, 0);
        return;
    }
    if (!t.empty()) push_block(begin, BlockKind::Comment, Block::kNoCode, 0);
}

void Reader::after_end_line(std::uint32_t begin, std::uint32_t end) {
    const std::string_view t = trim(src_.substr(begin, end - begin));
    if (t.empty()) return;
    if (t == "%") {  // a rewind-stop mark after the program is accepted (kept, but not part of the program)
        push_block(begin + static_cast<std::uint32_t>(src_.substr(begin, end - begin).find('%')), BlockKind::Percent,
                   Block::kNoCode, 0);
        return;
    }
    std::uint32_t first = begin;
    while (src_[first] == ' ' || src_[first] == '\t') ++first;
    report(Severity::Warning, DiagCode::W110_ContentAfterEnd, first,
           "content after the end of the program (line " + std::to_string(tape_.blocks_.empty() ? 0 : tape_.blocks_[tape_.end_block_ - 1].line) +
               "); it is not executed");
    after_end_seen_ = true;  // one warning is enough: nothing after the end is read
}

// Parses the characters of a line into the leading number and words (appended to the tape's words).
// Returns false (with a diagnostic) when the line cannot be a block.
bool Reader::parse_words(std::uint32_t begin, std::uint32_t end, LineParse& lp) {
    const auto* data = reinterpret_cast<const unsigned char*>(src_.data());
    bool in_word = false;
    int word_digits = 0;           // significant digits of the current word
    long long word_value = 0;
    bool word_negative = false;
    std::uint32_t space_at = end;  // first skipped blank; warned about only if the line parses
    std::uint32_t word_start = begin;
    auto finish_word = [&]() -> bool {
        if (!in_word) return true;
        if (word_digits > kMaxWordDigits) {
            report(Severity::Error, DiagCode::E104_NumberTooLarge, word_start,
                   "the word starting here has " + std::to_string(word_digits) + " digits; expected at most " +
                       std::to_string(kMaxWordDigits));
            return false;
        }
        ++lp.words;
        if (lp.words == 5 && word_negative) lp.sign_flags |= Block::kTcNegative;
        if (lp.words == 6 && word_negative) lp.sign_flags |= Block::kTpNegative;
        tape_.words_.push_back(static_cast<std::int32_t>(word_negative ? -word_value : word_value));
        return true;
    };
    for (std::uint32_t i = begin; i < end; ++i) {
        const unsigned char c = data[i];
        switch (kClass[c]) {
            case kDigit:
                lp.blank = false;
                if (in_word) {
                    if (word_digits > 0 || c != '0') ++word_digits;
                    if (word_digits <= kMaxWordDigits) word_value = word_value * 10 + (c - '0');
                } else if (lp.words == 0) {
                    if (lp.mark) goto misplaced_mark;
                    ++lp.lead_digits;
                    if (lp.lead_digits <= kMaxWordDigits) lp.lead_value = lp.lead_value * 10 + (c - '0');
                }
                break;
            case kPlus:
            case kMinus:
                lp.blank = false;
                if (lp.mark) goto misplaced_mark;
                if (!finish_word()) return false;
                in_word = true;
                word_negative = kClass[c] == kMinus;
                word_digits = 0;
                word_value = 0;
                word_start = i;
                break;
            case kSpace:
                if (profile_.whitespace == WhitespacePolicy::Strict) {
                    // Trailing blanks after a complete block are as much whitespace as inner ones.
                    report(Severity::Error, DiagCode::E108_WhitespaceStrict, i,
                           std::string(c == '\t' ? "a tab" : "a space") +
                               " inside a block; the strict whitespace policy allows only + - 0-9 in a block");
                    return false;
                }
                if (space_at == end) space_at = i;
                break;
            case kPercent:
            case kSlash:
            case kEquals:
                if (!lp.blank || lp.mark) goto misplaced_mark;
                if (kClass[c] != kPercent && !is_end_mark(static_cast<char>(c))) goto invalid;
                lp.mark = c;
                lp.blank = false;
                break;
            case kHigh:
                report(Severity::Error, DiagCode::E102_NonAsciiByte, i,
                       describe_byte(c) + " is not ASCII" +
                           (c == 0xEF && i + 2 < end && data[i + 1] == 0xBB && data[i + 2] == 0xBF
                                ? " (a UTF-8 byte order mark)"
                                : "") +
                           "; text belongs inside a 3 ... 4 ignore section, blocks hold only + - 0-9");
                return false;
            default:
                goto invalid;
        }
    }
    if (!finish_word()) return false;
    if (space_at != end) {
        report(Severity::Warning, DiagCode::W109_WhitespaceSkipped, space_at,
               std::string(data[space_at] == '\t' ? "a tab" : "a space") +
                   " inside a block was skipped; ESSI blocks hold only + - 0-9");
    }
    return true;

invalid:
    for (std::uint32_t i = begin; i < end; ++i) {
        const unsigned char c = data[i];
        const auto k = kClass[c];
        if (k == kOther || k == kLineEnd || ((k == kSlash || k == kEquals) && !is_end_mark(static_cast<char>(c)))) {
            report(Severity::Error, DiagCode::E101_InvalidCharacter, i,
                   "unexpected " + describe_byte(c) + "; expected + - or a digit" +
                       (c == '#' || c == ';' || c == '(' ? " (comments belong inside a 3 ... 4 ignore section)" : ""));
            return false;
        }
    }
    return false;

misplaced_mark:
    for (std::uint32_t i = begin; i < end; ++i) {
        const auto k = kClass[data[i]];
        if (k == kPercent || k == kSlash || k == kEquals) {
            report(Severity::Error, DiagCode::E116_MisplacedMark, i,
                   std::string("'") + static_cast<char>(data[i]) +
                       "' must stand alone in its block; expected a block holding only that mark");
            return false;
        }
    }
    return false;
}

void Reader::read_line(std::uint32_t begin, std::uint32_t end) {
    if (begin == end) return;  // empty block
    const std::size_t words_before = tape_.words_.size();
    LineParse lp;
    if (!parse_words(begin, end, lp)) {
        tape_.words_.resize(words_before);
        push_block(begin, BlockKind::Invalid, Block::kNoCode, 0);
        program_started_ = true;
        return;
    }
    if (lp.blank) return;  // only blanks: an empty block
    std::uint32_t first = begin;
    while (src_[first] == ' ' || src_[first] == '\t') ++first;

    auto fail = [&](DiagCode code, std::string message) {
        report(Severity::Error, code, first, std::move(message));
        tape_.words_.resize(words_before);
        push_block(first, BlockKind::Invalid, Block::kNoCode, 0);
        program_started_ = true;
    };

    if (lp.mark == '%') {
        if (program_started_) {
            percent_line_ = line_;
            percent_column_ = column(first);
            return;
        }
        push_block(first, BlockKind::Percent, Block::kNoCode, 0);
        return;
    }
    program_started_ = true;
    if (lp.mark) {  // '/' or '=' configured as an end of program
        push_block(first, BlockKind::EndMark, Block::kNoCode, 0);
        ended_ = true;
        tape_.has_end_ = true;
        tape_.end_block_ = tape_.blocks_.size();
        return;
    }
    const auto word_count = static_cast<std::uint8_t>(lp.words);
    const bool motion_count = lp.words == 2 || lp.words == 5 || lp.words == 6;
    if (lp.lead_digits > 0) {
        if (lp.lead_digits > kMaxFunctionDigits) {
            fail(DiagCode::E103_FunctionCodeTooLong,
                 "machine function " + std::string(src_.substr(first, lp.lead_digits)) + " has " +
                     std::to_string(lp.lead_digits) + " digits; expected at most 3 (ISO 6582 3.4.1)");
            return;
        }
        const auto code = static_cast<std::uint16_t>(lp.lead_value);
        if (lp.words == 0) {
            push_block(first, BlockKind::Function, code, 0);
            if (code == kIgnoreOnCode) {
                in_ignore_ = true;
                ignore_line_ = line_;
                ignore_column_ = column(first);
            } else if (code == kIgnoreOffCode) {
                report(Severity::Warning, DiagCode::W111_StrayIgnoreOff, first,
                       "ignore OFF (4) without an ignore ON (3) before it; expected 3 to open the ignored section");
            } else if (is_end_function(code)) {
                ended_ = true;
                tape_.has_end_ = true;
                tape_.end_block_ = tape_.blocks_.size();
            }
            return;
        }
        if (lp.words == 1) {
            push_block(first, BlockKind::FunctionValue, code, word_count);
            return;
        }
        if (motion_count) {
            push_block(first, BlockKind::Motion, code, static_cast<std::uint8_t>(word_count | lp.sign_flags | Block::kHasAddress));
            return;
        }
        fail(DiagCode::E106_FunctionWordCount,
             "a leading number followed by " + std::to_string(lp.words) +
                 " signed words; expected 1 (function value) or 2, 5 or 6 (head address and motion)");
        return;
    }
    if (motion_count) {
        push_block(first, BlockKind::Motion, Block::kNoCode, static_cast<std::uint8_t>(word_count | lp.sign_flags));
        return;
    }
    fail(DiagCode::E105_WordCount, "found " + std::to_string(lp.words) + " signed word" + (lp.words == 1 ? "" : "s") +
                                       "; expected 2 (line DX DY), 5 (arc DX DY XC YC TC) or 6 (parabola DX DY XP YP TC TP)");
}

// ---- Tape ----

std::span<const std::int32_t> Tape::words(std::size_t i) const {
    const std::size_t group = i / kWordIndexStride;
    std::size_t w = word_index_[group];
    for (std::size_t k = group * kWordIndexStride; k < i; ++k) w += blocks_[k].word_count();
    return {words_.data() + w, static_cast<std::size_t>(blocks_[i].word_count())};
}

std::span<const std::int32_t> Tape::WordCursor::next(std::size_t i) {
    while (block_ < i) word_ += tape_->blocks_[block_++].word_count();
    return {tape_->words_.data() + word_, static_cast<std::size_t>(tape_->blocks_[i].word_count())};
}

bool Tape::has_errors() const {
    return std::any_of(diagnostics_.begin(), diagnostics_.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

std::size_t Tape::memory_bytes() const {
    return blocks_.capacity() * sizeof(Block) + words_.capacity() * sizeof(std::int32_t) +
           word_index_.capacity() * sizeof(std::uint32_t);
}

Tape read_tape(std::string_view bytes, const Profile& profile) {
    Tape tape;
    Reader reader(bytes, profile, tape);
    reader.run();
    return tape;
}

std::uint32_t column_of(std::string_view bytes, std::uint32_t offset) {
    std::uint32_t begin = offset;
    while (begin > 0 && bytes[begin - 1] != '\n' && bytes[begin - 1] != '\r') --begin;
    return offset - begin + 1;
}

std::string_view line_text(std::string_view bytes, std::uint32_t offset) {
    if (offset > bytes.size()) return {};
    std::size_t begin = offset;
    while (begin > 0 && bytes[begin - 1] != '\n' && bytes[begin - 1] != '\r') --begin;
    std::size_t end = offset;
    while (end < bytes.size() && bytes[end] != '\n' && bytes[end] != '\r') ++end;
    return bytes.substr(begin, end - begin);
}

}  // namespace essi
