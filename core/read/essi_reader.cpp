// Phase 1, read: bytes -> blocks (docs/semantics.md §1-2). One pass over the bytes, no allocation per block
// beyond the two growing arrays. The reader knows characters and word counts, not what a function does,
// except for the three things that change how the following bytes are read: 3/4 ignore sections, the
// end of the program, and the % mark.
#include <algorithm>
#include <array>
#include <cstring>

#include "essi/function_codes.hpp"
#include "essi/read.hpp"
#include "essi/text.hpp"
#include "reader_driver.hpp"

namespace essi {
namespace {

constexpr int kMaxWordDigits = 9;      // significant digits of a dimension word or value
constexpr int kMaxFunctionDigits = 3;  // ISO 6582 3.4.1
// Words of a line read by the fast path; a line with more goes the general way (it is an error anyway).
// The fast path makes room for this many words before it reads a line.
constexpr int kMaxPlainWords = 8;
constexpr std::size_t kMaxBlockWords = 6;  // a parabola's DX DY XP YP TC TP: the most a block holds

enum CharClass : std::uint8_t { kOther, kDigit, kPlus, kMinus, kSpace, kLineEnd, kPercent, kSlash, kEquals, kHigh };

constexpr std::array<std::uint8_t, 256> make_classes() {
    std::array<std::uint8_t, 256> t{};
    for (int c = 0; c < 256; ++c) t[c] = c >= 0x80 ? kHigh : kOther;
    for (int c = '0'; c <= '9'; ++c) t[c] = kDigit;
    t['+'] = kPlus;
    t['-'] = kMinus;
    t[' '] = kSpace;
    t['\t'] = kSpace;
    for (int c = 0; c < 256; ++c)
        if (is_line_end(static_cast<unsigned char>(c))) t[c] = kLineEnd;
    t['%'] = kPercent;
    t['/'] = kSlash;
    t['='] = kEquals;
    return t;
}
constexpr std::array<std::uint8_t, 256> kClass = make_classes();

// Line ends and signs of a whole tape, 8 bytes at a time (the reservation pass must cost little).
struct ByteCounts {
    std::size_t lf = 0, cr = 0, signs = 0;
};

constexpr std::uint64_t kOnes = 0x0101010101010101ULL;

// 1 in each byte lane of `w` that equals `c`, 0 elsewhere.
inline std::uint64_t lanes_equal(std::uint64_t w, unsigned char c) {
    constexpr std::uint64_t kLow7 = 0x7F7F7F7F7F7F7F7FULL;
    const std::uint64_t x = w ^ (kOnes * c);                  // zero bytes where equal
    const std::uint64_t nonzero = ((x & kLow7) + kLow7) | x;  // high bit set where not equal
    return (~nonzero & (kOnes << 7)) >> 7;
}

// Sum of the byte lanes of `v`.
inline std::size_t lane_sum(std::uint64_t v) {
    std::size_t sum = 0;
    for (int k = 0; k < 8; ++k) sum += (v >> (8 * k)) & 0xFF;
    return sum;
}

ByteCounts count_bytes(std::string_view s) {
    ByteCounts n;
    std::size_t i = 0;
    // Per-lane counters; each lane gains at most 1 (2 for signs) a word, so they are emptied every
    // kWordsPerFlush words, before a lane can pass 255.
    constexpr int kWordsPerFlush = 120;
    while (i + 8 <= s.size()) {
        std::uint64_t lf = 0, cr = 0, signs = 0;
        for (int k = 0; k < kWordsPerFlush && i + 8 <= s.size(); ++k, i += 8) {
            std::uint64_t w;
            std::memcpy(&w, s.data() + i, 8);
            lf += lanes_equal(w, '\n');
            cr += lanes_equal(w, '\r');
            signs += lanes_equal(w, '+') + lanes_equal(w, '-');
        }
        n.lf += lane_sum(lf);
        n.cr += lane_sum(cr);
        n.signs += lane_sum(signs);
    }
    for (; i < s.size(); ++i) {
        n.lf += s[i] == '\n';
        n.cr += s[i] == '\r';
        n.signs += static_cast<std::size_t>(s[i] == '+' || s[i] == '-');
    }
    return n;
}

// What the fast path read of one line of digits and signs.
struct PlainLine {
    int lead_digits = 0;                      // digits of the leading unsigned number (function code or head address)
    std::uint32_t lead = 0;                   // its value
    int words = 0;                            // signed words written
    std::uint32_t negative = 0;               // bit k: word k has a '-' sign
    const unsigned char* line_end = nullptr;  // the line's CR or LF, or the end of the bytes
};

// The Block sign flags of a line's words from its mask of negative words: words 5 (TC) and 6 (TP) have their
// flags at bits 4 and 5, where the mask has them.
constexpr std::uint8_t sign_flags_of(std::uint32_t negative) {
    static_assert(Block::kTcNegative == 1u << 4 && Block::kTpNegative == 1u << 5);
    return static_cast<std::uint8_t>(negative & (Block::kTcNegative | Block::kTpNegative));
}

// The bytes read_plain_line may look at from a line's start when it is not told where the bytes end: the
// leading number and kMaxPlainWords words of at most kMaxWordDigits + 1 digits each are read before it gives up.
constexpr std::uint32_t kPlainLineReach = (kMaxWordDigits + 2) * (kMaxPlainWords + 1);
// Lines read_plain_lines reads in one batch without the per-line tests for rare cases, and the bytes a batch
// may look at (each line within its reach, and the byte after the last line end).
constexpr std::size_t kBatchLines = 64;
constexpr std::uint32_t kBatchReach = kBatchLines * kPlainLineReach + 1;

// Reads the unsigned number at p a digit at a time, at most kMaxWordDigits + 1 digits (more is an error the
// general path reports): its value and the first byte after it. `bounded`: p may reach `stop`. Unrolled:
// no loop counter, one test a digit.
template <bool bounded>
[[gnu::always_inline]] inline const unsigned char* read_number(const unsigned char* p, const unsigned char* stop,
                                                               std::uint32_t& value) {
    static_assert(kMaxWordDigits == 9, "read_number reads up to 10 digits");
    std::uint32_t v = 0;
    int k = 0;
#define ESSI_READ_DIGIT                                                                    \
    if (bounded && p + k == stop) goto done;                                               \
    if (const unsigned d = static_cast<unsigned>(p[k]) - '0'; d <= 9) v = v * 10 + d, ++k; \
    else goto done;
    ESSI_READ_DIGIT ESSI_READ_DIGIT ESSI_READ_DIGIT ESSI_READ_DIGIT ESSI_READ_DIGIT ESSI_READ_DIGIT ESSI_READ_DIGIT
        ESSI_READ_DIGIT ESSI_READ_DIGIT ESSI_READ_DIGIT
#undef ESSI_READ_DIGIT
            done : value = v;
    return p + k;
}

// Reads a line made only of digits and signs: a leading number, then signed words, then a line end.
// Returns false (the general path reads the line) when it is anything else: blanks, other characters, a
// number of more than kMaxWordDigits digits (leading zeros included), more than kMaxPlainWords words, empty.
// `bounded`: the line may reach `stop` (the end of the bytes); else kPlainLineReach bytes are readable.
template <bool bounded>
[[gnu::always_inline]] inline bool read_plain_line(const unsigned char* first, const unsigned char* stop,
                                                   std::int32_t* words, PlainLine& out) {
    const unsigned char* p = first;
    std::uint32_t lead = 0;
    if (*p != '+' && *p != '-') p = read_number<bounded>(p, stop, lead);  // motions start with a sign
    const auto lead_digits = static_cast<int>(p - first);
    if (lead_digits > kMaxWordDigits) return false;
    int n = 0;
    std::uint32_t negative = 0;  // bit k: word k has a '-' sign
    while (!(bounded && p == stop)) {
        const unsigned char sign = *p;
        if (sign != '+' && sign != '-') break;
        if (n == kMaxPlainWords) return false;
        std::uint32_t v = 0;
        const unsigned char* const after = read_number<bounded>(p + 1, stop, v);
        if (after - (p + 1) > kMaxWordDigits) return false;
        const std::uint32_t minus = sign == '-';
        words[n] = static_cast<std::int32_t>((v ^ (0u - minus)) + minus);  // -v for '-', without a branch
        negative |= minus << n;
        ++n;
        p = after;
    }
    // Not a plain line?
    if (p == first || (!(bounded && p == stop) && is_not_line_end(*p))) return false;
    out.lead_digits = lead_digits;
    out.lead = lead;
    out.words = n;
    out.negative = negative;
    out.line_end = p;
    return true;
}

// The digits a message quotes of a number (essi::excerpt).
constexpr std::size_t kExcerptDigits = 12;

}  // namespace

class EssiReader final : public detail::ReaderDriver<EssiReader> {
public:
    EssiReader(std::string_view bytes, const Profile& profile) : ReaderDriver(bytes, profile, Msg::ReadTooManyErrors) {}

    // Reserves the exact room the whole tape needs in `tape` (one cheap counting pass).
    void reserve_whole(Tape& tape) const override;

private:
    friend class detail::ReaderDriver<EssiReader>;

    // One line's parse, before classification.
    struct LineParse {
        std::size_t lead_digits = 0;  // digits of the leading unsigned number as written (a line may hold 4 G)
        long long lead_value = 0;
        int words = 0;
        std::uint8_t sign_flags = 0;  // Block::kTcNegative / kTpNegative
        bool value_negative = false;  // the first signed word has a '-' (a function's value must have '+')
        bool blank = true;
        int mark = 0;  // '%', '/' or '=' when the block is that mark
    };

    // What the driver asks of a front end (reader_driver.hpp).
    void begin_tape();
    std::uint32_t read_run(std::uint32_t pos, std::uint32_t size, std::size_t max_blocks);
    bool read_line(std::uint32_t begin, std::uint32_t end, std::size_t max_blocks);
    void end_tape(Tape& chunk);
    void save_own(WireWriter& out) const { out.put_all(skip_, in_ignore_, ignore_line_, ignore_column_); }
    [[nodiscard]] bool restore_own(WireReader& in) {
        return in.get_all(skip_, in_ignore_, ignore_line_, ignore_column_);
    }

    std::uint32_t read_plain_lines(std::uint32_t pos, std::uint32_t size, std::size_t max_blocks);
    void read_block(std::uint32_t begin, std::uint32_t end);
    void classify(std::uint32_t first, const LineParse& lp, std::size_t words_before);
    void read_ignored_line(std::uint32_t begin, std::uint32_t end);
    void after_end_line(std::uint32_t begin, std::uint32_t end);
    bool parse_words(std::uint32_t begin, std::uint32_t end, LineParse& lp);

    std::uint32_t skip_ = 0;  // a UTF-8 byte order mark: reported, then the line is read without it
    bool in_ignore_ = false;  // inside a 3 ... 4 section
    std::uint32_t ignore_line_ = 0, ignore_column_ = 0;
};

void EssiReader::reserve_whole(Tape& tape) const {
    // A block per line, a word per sign (but at most kMaxBlockWords a block are kept), and the fast path's room
    // for the last line: no reallocation while reading, no slack to give back.
    const ByteCounts n = count_bytes(src_);
    const std::size_t blocks = std::max(n.lf, n.cr) + 1;
    blocks_of(tape).reserve(blocks);
    words_of(tape).reserve(std::min(n.signs, kMaxBlockWords * blocks) + kMaxPlainWords);
    word_index_of(tape).reserve(blocks_of(tape).capacity() / Tape::kWordIndexStride + 1);
}

void EssiReader::begin_tape() {
    if (src_.substr(0, 3) != "\xEF\xBB\xBF") return;
    report(Severity::Error, DiagCode::E102_NonAsciiByte, 0, Msg::ReadByteOrderMark);
    skip_ = 3;
}

// The common case first: a run of lines of digits and signs, read in one pass, unless the line at `pos` needs the
// general path's state (a byte order mark to skip, the end, an ignore section, a % to report).
std::uint32_t EssiReader::read_run(std::uint32_t pos, std::uint32_t size, std::size_t max_blocks) {
    if (skip_ != 0 || ended_ || in_ignore_ || percent_line_ != 0) return pos;
    return read_plain_lines(pos, size, max_blocks);
}

// A line the general way: after the end, in an ignore section, or a block. A line gives at most one block: none
// is read into a full chunk.
bool EssiReader::read_line(std::uint32_t begin, std::uint32_t end, std::size_t max_blocks) {
    if (chunk_blocks_ >= max_blocks) return false;
    const std::uint32_t from = begin + skip_;
    skip_ = 0;
    if (ended_) after_end_line(from, end);
    else if (in_ignore_) read_ignored_line(from, end);
    else read_block(from, end);
    return true;
}

void EssiReader::end_tape(Tape& chunk) {
    if (!in_ignore_) return;
    diagnostics_of(chunk).push_back(make_diagnostic(Severity::Error, DiagCode::E107_UnclosedIgnore, ignore_line_,
                                                    ignore_column_, Msg::ReadUnclosedIgnore, {ignore_line_}));
}

// Reads lines made only of digits and signs (almost every line of a real tape) from `pos` on, one pass
// a line, until a line needs the general path (blanks, marks, comments, errors), the reader's state
// changes (the end, an ignore section), the chunk is full or the bytes end. Returns the start of the
// first line it did not read (line_ is that line's number), or `size`. Locals only in the loop, so that
// the compiler keeps them in registers; a line's words are written straight into room made once a line.
std::uint32_t EssiReader::read_plain_lines(std::uint32_t pos, std::uint32_t size, std::size_t max_blocks) {
    const auto* const base = reinterpret_cast<const unsigned char*>(src_.data());
    const unsigned char* const stop = base + size;
    Tape& t = chunk();
    std::uint32_t line = line_;
    std::size_t blocks = chunk_blocks_;
    const std::size_t blocks_before = blocks;
    bool started = program_started_;
    // Blocks and words are written through local pointers (registers), checked against the room made and
    // committed when the loop ends or the general path needs the arrays. Room is made only when a block or a
    // line's words need it: an exact reservation (read_tape) stays exact.
    Block *bp = nullptr, *b_room_end = nullptr;
    std::int32_t *wp = nullptr, *w_room_end = nullptr;
    const auto take_pointers = [&] {
        bp = blocks_of(t).data() + blocks_of(t).size();
        b_room_end = blocks_of(t).end_of_room();
        wp = words_of(t).data() + words_of(t).size();
        w_room_end = words_of(t).end_of_room();
    };
    take_pointers();
    // The two common shapes go straight in as blocks; every other line is classified in full. A motion: two,
    // five or six words. A function without a value that changes no reading state (not 3/4, not an end code).
    const auto is_motion = [](const PlainLine& pl) {
        return pl.lead_digits == 0 && (pl.words == 2 || pl.words == 5 || pl.words == 6);
    };
    const auto is_function = [this](const PlainLine& pl) {
        return pl.words == 0 && pl.lead_digits <= kMaxFunctionDigits && pl.lead != fn::kIgnoreOn &&
               pl.lead != fn::kIgnoreOff && !end_function_[pl.lead];
    };
    // Writes the block of a common line (its words are already in place); the room has been made. One block
    // either way; only its last three fields differ (selected, not branched on).
    const auto put_block = [&](const PlainLine& pl, bool motion, std::uint32_t offset) {
        if (blocks % Tape::kWordIndexStride == 0)
            word_index_of(t).push_back(static_cast<std::uint32_t>(wp - words_of(t).data()));
        Block& b = *bp++;
        b.offset = offset;
        b.line = line;
        b.code = motion ? Block::kNoCode : static_cast<std::uint16_t>(pl.lead);
        b.kind = motion ? BlockKind::Motion : BlockKind::Function;
        b.packed = motion ? static_cast<std::uint8_t>(pl.words | sign_flags_of(pl.negative)) : std::uint8_t{0};
        ++blocks;
        wp += pl.words;
    };
    while (pos < size && blocks < max_blocks) {
        // A batch of common lines, with every per-line test that only guards a rare case hoisted out of it:
        // the lines cannot reach the end of the bytes, the room for their blocks and words is there, the
        // chunk has room for all of them and the program has started. The first line that is not a plain
        // motion or function ends the batch and is read again by the loop below.
        if (started && size - pos >= kBatchReach && max_blocks - blocks >= kBatchLines &&
            b_room_end - bp >= static_cast<std::ptrdiff_t>(kBatchLines) &&
            w_room_end - wp >= static_cast<std::ptrdiff_t>(kBatchLines * kMaxPlainWords)) {
            const unsigned char* p = base + pos;
            for (const std::size_t batch_end = blocks + kBatchLines; blocks != batch_end;) {
                PlainLine pl;
                if (!read_plain_line<false>(p, stop, wp, pl)) break;
                const bool motion = is_motion(pl);
                if (!motion && !is_function(pl)) break;
                put_block(pl, motion, static_cast<std::uint32_t>(p - base));
                ++line;
                p = past_line_end(pl.line_end);  // the byte after the line end is there (kBatchReach)
            }
            const auto batch_end = static_cast<std::uint32_t>(p - base);
            if (batch_end != pos) {
                pos = batch_end;
                continue;
            }
            // Its first line was not common: the loop below reads it.
        }
        if (w_room_end - wp < kMaxPlainWords) [[unlikely]] {
            words_of(t).commit_to(wp);
            wp = words_of(t).room(kMaxPlainWords);
            w_room_end = words_of(t).end_of_room();
        }
        const unsigned char* const first = base + pos;
        PlainLine pl;
        const bool plain = size - pos >= kPlainLineReach ? read_plain_line<false>(first, stop, wp, pl)
                                                         : read_plain_line<true>(first, stop, wp, pl);
        if (!plain) break;
        const int n = pl.words;
        const std::uint32_t lead = pl.lead;
        const auto offset = static_cast<std::uint32_t>(first - base);
        bool state_changed = false;
        const bool motion = is_motion(pl);
        if (started && (motion || is_function(pl))) {
            if (bp == b_room_end) [[unlikely]] {
                blocks_of(t).commit_to(bp);
                bp = blocks_of(t).room(1);
                b_room_end = blocks_of(t).end_of_room();
            }
            put_block(pl, motion, offset);
        } else {
            // Rare shapes (the first block, a function value, a head address, an end code, 3/4, wrong word
            // counts): classify() with the reader's state brought up to date; it may change that state.
            blocks_of(t).commit_to(bp);
            words_of(t).commit_to(wp + n);
            line_ = line;
            line_begin_ = offset;
            chunk_blocks_ = blocks;
            LineParse lp;
            lp.lead_digits = static_cast<std::size_t>(pl.lead_digits);
            lp.lead_value = lead;
            lp.words = n;
            lp.sign_flags = sign_flags_of(pl.negative);
            lp.value_negative = (pl.negative & 1) != 0;
            lp.blank = false;
            classify(offset, lp, words_of(t).size() - static_cast<std::size_t>(n));
            blocks = chunk_blocks_;
            started = program_started_;
            state_changed = ended_ || in_ignore_ || stopped_ || percent_line_ != 0;
            take_pointers();
        }
        pos = static_cast<std::uint32_t>(pl.line_end - base);
        if (pos >= size) {
            pos = size;
            break;
        }
        pos = past_line_end(base, pos, size);
        ++line;
        if (state_changed) break;
    }
    blocks_of(t).commit_to(bp);
    words_of(t).commit_to(wp);
    if (blocks != blocks_before) last_line_ = blocks_of(t).back().line;
    line_ = line;
    chunk_blocks_ = blocks;
    return pos;
}

void EssiReader::read_ignored_line(std::uint32_t begin, std::uint32_t end) {
    const std::string_view text = src_.substr(begin, end - begin);
    const std::string_view t = trim_blanks(text);
    if (t == "4") {
        in_ignore_ = false;
        push_block(begin + static_cast<std::uint32_t>(text.find('4')), BlockKind::Function, fn::kIgnoreOff, 0);
        return;
    }
    if (!t.empty()) push_block(begin, BlockKind::Comment, Block::kNoCode, 0);
}

void EssiReader::after_end_line(std::uint32_t begin, std::uint32_t end) {
    const std::string_view t = trim_blanks(src_.substr(begin, end - begin));
    if (t.empty()) return;
    if (t == "%") {  // a rewind-stop mark after the program is accepted (kept, but not part of the program)
        push_block(begin + static_cast<std::uint32_t>(src_.substr(begin, end - begin).find('%')), BlockKind::Percent,
                   Block::kNoCode, 0);
        return;
    }
    std::uint32_t first = begin;
    while (src_[first] == ' ' || src_[first] == '\t') ++first;
    report(Severity::Warning, DiagCode::W110_ContentAfterEnd, first, Msg::ReadContentAfterEnd, {end_line_});
    after_end_seen_ = true;  // one warning is enough: nothing after the end is read
}

// Parses the characters of a line into the leading number and words (appended to the tape's words).
// Returns false (with a diagnostic) when the line cannot be a block.
bool EssiReader::parse_words(std::uint32_t begin, std::uint32_t end, LineParse& lp) {
    const auto* data = reinterpret_cast<const unsigned char*>(src_.data());
    bool in_word = false;
    std::size_t word_digits = 0;  // significant digits of the current word (a line may hold 4 G)
    long long word_value = 0;
    bool word_negative = false;
    std::uint32_t space_at = end;  // first skipped blank; warned about only if the line parses
    std::uint32_t word_start = begin;
    auto finish_word = [&]() -> bool {
        if (!in_word) return true;
        if (word_digits > kMaxWordDigits) {
            report(Severity::Error, DiagCode::E104_NumberTooLarge, word_start, Msg::ReadWordTooLong,
                   {word_digits, kMaxWordDigits});
            return false;
        }
        ++lp.words;
        // A block holds at most kMaxBlockWords words: the ones after them are only counted (for the error), so
        // that a line of a billion '+' costs no memory per '+'.
        if (static_cast<std::size_t>(lp.words) > kMaxBlockWords) return true;
        if (lp.words == 1 && word_negative) lp.value_negative = true;
        if (lp.words == 5 && word_negative) lp.sign_flags |= Block::kTcNegative;
        if (lp.words == 6 && word_negative) lp.sign_flags |= Block::kTpNegative;
        words_of(chunk()).push_back(static_cast<std::int32_t>(word_negative ? -word_value : word_value));
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
                    report(Severity::Error, DiagCode::E108_WhitespaceStrict, i, Msg::ReadWhitespaceStrict,
                           {c == '\t' ? Msg::WordATab : Msg::WordASpace});
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
                report(Severity::Error, DiagCode::E102_NonAsciiByte, i, Msg::ReadNonAscii,
                       {detail::hex_byte(c), c == 0xEF && i + 2 < end && data[i + 1] == 0xBB && data[i + 2] == 0xBF
                                                 ? MessageArgs::Arg(Msg::ReadBomHint)
                                                 : MessageArgs::Arg("")});
                return false;
            default: goto invalid;
        }
    }
    if (!finish_word()) return false;
    if (space_at != end) {
        report(Severity::Warning, DiagCode::W109_WhitespaceSkipped, space_at, Msg::ReadWhitespaceSkipped,
               {data[space_at] == '\t' ? Msg::WordATab : Msg::WordASpace});
    }
    return true;

invalid:
    for (std::uint32_t i = begin; i < end; ++i) {
        const unsigned char c = data[i];
        const auto k = kClass[c];
        if (k == kOther || k == kLineEnd || ((k == kSlash || k == kEquals) && !is_end_mark(static_cast<char>(c)))) {
            const MessageArgs::Arg hint =
                c == '#' || c == ';' || c == '(' ? MessageArgs::Arg(Msg::ReadCommentHint) : MessageArgs::Arg("");
            if (c >= 0x21 && c < 0x7F)
                report(Severity::Error, DiagCode::E101_InvalidCharacter, i, Msg::ReadUnexpectedChar,
                       {std::string_view(reinterpret_cast<const char*>(data + i), 1), detail::hex_byte(c), hint});
            else
                report(Severity::Error, DiagCode::E101_InvalidCharacter, i, Msg::ReadUnexpectedByte,
                       {detail::hex_byte(c), hint});
            return false;
        }
    }
    return false;

misplaced_mark:
    for (std::uint32_t i = begin; i < end; ++i) {
        const auto k = kClass[data[i]];
        if (k == kPercent || k == kSlash || k == kEquals) {
            report(Severity::Error, DiagCode::E116_MisplacedMark, i, Msg::ReadMisplacedMark,
                   {std::string_view(reinterpret_cast<const char*>(data + i), 1)});
            return false;
        }
    }
    return false;
}

void EssiReader::read_block(std::uint32_t begin, std::uint32_t end) {
    if (begin == end) return;  // empty block
    const std::size_t words_before = words_of(chunk()).size();
    LineParse lp;
    if (!parse_words(begin, end, lp)) {
        words_of(chunk()).truncate(words_before);
        push_block(begin, BlockKind::Invalid, Block::kNoCode, 0);
        return;
    }
    if (lp.blank) return;  // only blanks: an empty block
    std::uint32_t first = begin;
    while (src_[first] == ' ' || src_[first] == '\t') ++first;
    classify(first, lp, words_before);
}

// Turns a parsed line into a block: its kind by the leading number and the count of signed words.
void EssiReader::classify(std::uint32_t first, const LineParse& lp, std::size_t words_before) {
    auto fail = [&](DiagCode code, Msg msg, MessageArgs args) {
        report(Severity::Error, code, first, msg, std::move(args));
        words_of(chunk()).truncate(words_before);
        push_block(first, BlockKind::Invalid, Block::kNoCode, 0);
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
    if (lp.mark) {  // '/' or '=' configured as an end of program
        push_block(first, BlockKind::EndMark, Block::kNoCode, 0);
        mark_program_end();
        return;
    }
    const auto word_count = static_cast<std::uint8_t>(lp.words);
    const bool motion_count = lp.words == 2 || lp.words == 5 || lp.words == 6;
    if (lp.lead_digits > 0) {
        if (lp.lead_digits > kMaxFunctionDigits) {
            fail(DiagCode::E103_FunctionCodeTooLong, Msg::ReadFunctionTooLong,
                 {excerpt(src_.substr(first, lp.lead_digits), kExcerptDigits), lp.lead_digits});
            return;
        }
        const auto code = static_cast<std::uint16_t>(lp.lead_value);
        if (lp.words == 0) {
            push_block(first, BlockKind::Function, code, 0);
            if (code == fn::kIgnoreOn) {
                in_ignore_ = true;
                ignore_line_ = line_;
                ignore_column_ = column(first);
            } else if (code == fn::kIgnoreOff) {
                report(Severity::Warning, DiagCode::W111_StrayIgnoreOff, first, Msg::ReadStrayIgnoreOff);
            } else if (is_end_function(code)) {
                mark_program_end();
            }
            return;
        }
        if (lp.words == 1) {
            if (lp.value_negative) {
                fail(DiagCode::E118_FunctionValueSign, Msg::ReadFunctionValueSign, {code});
                return;
            }
            push_block(first, BlockKind::FunctionValue, code, word_count);
            return;
        }
        if (motion_count) {
            push_block(first, BlockKind::Motion, code,
                       static_cast<std::uint8_t>(word_count | lp.sign_flags | Block::kHasAddress));
            return;
        }
        fail(DiagCode::E106_FunctionWordCount, Msg::ReadFunctionWordCount, {lp.words});
        return;
    }
    if (motion_count) {
        push_block(first, BlockKind::Motion, Block::kNoCode, static_cast<std::uint8_t>(word_count | lp.sign_flags));
        return;
    }
    fail(DiagCode::E105_WordCount, Msg::ReadWordCount, {lp.words});
}

std::unique_ptr<BlockReader> make_essi_reader(std::string_view bytes, const Profile& profile) {
    return std::make_unique<EssiReader>(bytes, profile);
}

}  // namespace essi
