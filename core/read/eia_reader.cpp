// Phase 1, read, for EIA (RS-274) tapes (docs/semantics.md §10): bytes -> the same blocks an ESSI tape gives, so
// that the interpreter, the statistics and every report run them unchanged. An EIA block ("N10 G02 X50 Y0 I25 J0")
// becomes the ESSI blocks it stands for, by the profile's EIA table (Profile::eia): its G and M words the machine
// functions they map to (M70 -> 7, G91 -> 81), F a feed (39+v), G04 a dwell (41+v), its X Y I J one motion block
// in unit increments. What the reader keeps of the machine is only what EIA leaves out and ESSI needs spelled out:
// the modal arc direction (G02/G03), the rapid mode of G00, absolute mode and the programmed position (a missing X
// or Y in absolute mode stays where it is; I/J are relative to the block's start in both modes).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>

#include "essi/function_codes.hpp"
#include "essi/read.hpp"
#include "essi/text.hpp"
#include "reader_driver.hpp"

namespace essi {
namespace {

constexpr int kMaxNumberDigits = 12;       // digits of a number (before and after the point together)
constexpr long long kMaxCodeNumber = 999;  // G and M numbers have at most 3 digits
constexpr std::size_t kExcerptChars = 16;  // what a message quotes of a word
constexpr double kMmPerInch = 25.4;
constexpr double kOnGrid = 1e-6;  // a value this close to a whole unit increment is on the grid

enum class ArcMode : std::uint8_t { None, Clockwise, CounterClockwise };

// RS-274 motion words: the same in every dialect.
constexpr int kGLine = 1;
constexpr int kGArcCw = 2;
constexpr int kGArcCcw = 3;

// 10^k for the decimals a number may have (kMaxNumberDigits).
constexpr std::array<long long, kMaxNumberDigits + 1> make_powers() {
    std::array<long long, kMaxNumberDigits + 1> p{};
    p[0] = 1;
    for (int k = 1; k <= kMaxNumberDigits; ++k) p[k] = p[k - 1] * 10;
    return p;
}
constexpr std::array<long long, kMaxNumberDigits + 1> kPowersOfTen = make_powers();

// The letters the reader gives a meaning to: the rest of a dialect's letters (Hypertherm's T of `M36 T1`, the D
// of `G41 D5`) are read and ignored with W124.
bool reads_letter(char letter, const EiaDialect& e) {
    return letter == 'N' || letter == 'X' || letter == 'Y' || letter == 'I' || letter == 'J' ||
           letter == e.dwell_letter;
}

// One address word: its letter, where it starts, and its number as written (mantissa x 10^-decimals).
struct Word {
    char letter = 0;
    std::uint32_t offset = 0;
    std::uint32_t length = 0;  // its bytes in the line, letter included (what a message quotes of it)
    long long mantissa = 0;
    int decimals = 0;
    [[nodiscard]] double value() const {
        return static_cast<double>(mantissa) / static_cast<double>(kPowersOfTen[static_cast<std::size_t>(decimals)]);
    }
    // The number as a G or M code: a whole number of at most 3 digits, else -1.
    [[nodiscard]] int code_number() const {
        if (decimals == 0) return mantissa >= 0 && mantissa <= kMaxCodeNumber ? static_cast<int>(mantissa) : -1;
        const long long scale = kPowersOfTen[static_cast<std::size_t>(decimals)];
        if (mantissa < 0 || mantissa % scale != 0 || mantissa / scale > kMaxCodeNumber) return -1;
        return static_cast<int>(mantissa / scale);
    }
};

// What a G number does in a dialect (EiaReader's table, from Profile::eia).
enum class GRole : std::uint8_t { None, Line, ArcCw, ArcCcw, Rapid, Preset, Inch, Mm, Function };

struct LineDiagnostic {
    Severity severity;
    DiagCode code;
    std::uint32_t offset;
    Msg msg = Msg::None;
    MessageArgs args;
};

// The blocks and diagnostics one line gives, before they are committed to the chunk.
struct LineResult {
    struct Out {
        std::uint32_t offset;
        BlockKind kind;
        std::uint16_t code;
        std::uint8_t packed;
        int words;
        std::int32_t w[5];
    };
    std::vector<Out> blocks;
    std::vector<LineDiagnostic> diagnostics;
};

std::string word_text(char letter, int number) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%c%02d", letter, number);
    return buf;
}

}  // namespace

class EiaReader final : public detail::ReaderDriver<EiaReader> {
public:
    EiaReader(std::string_view bytes, const Profile& profile) : ReaderDriver(bytes, profile, Msg::EiaTooManyErrors) {
        make_tables();
    }

    void reserve_whole(Tape& tape) const override;

private:
    friend class detail::ReaderDriver<EiaReader>;

    // The machine state the reader keeps (see the file's comment), changed only by committed lines.
    struct State {
        ArcMode arc = ArcMode::None;
        bool rapid = false;     // G00 (rapid_motion_g) in force
        bool absolute = false;  // the function 82 is in force
        bool inch = false;
        long long x = 0, y = 0;  // programmed position, unit increments
    };

    // The axis words of a block (null when absent).
    struct Axes {
        const Word *x = nullptr, *y = nullptr, *i = nullptr, *j = nullptr;
        [[nodiscard]] const Word* first() const;
    };

    // What the driver asks of a front end (reader_driver.hpp).
    bool read_line(std::uint32_t begin, std::uint32_t end, std::size_t max_blocks);
    void end_tape(Tape& chunk);
    void save_own(WireWriter& out) const {
        out.put_all(state_.arc, state_.rapid, state_.absolute, state_.inch, state_.x, state_.y, rounded_, rounded_line_,
                    rounded_column_);
    }
    [[nodiscard]] bool restore_own(WireReader& in) {
        return in.get_all(state_.arc, state_.rapid, state_.absolute, state_.inch, state_.x, state_.y, rounded_,
                          rounded_line_, rounded_column_);
    }

    void make_tables();
    void read_block(std::uint32_t begin, std::uint32_t end, LineResult& out, State& st);
    bool parse_words(std::uint32_t begin, std::uint32_t end, std::vector<Word>& words, LineResult& out) const;
    bool check_order(const std::vector<Word>& words, LineResult& out) const;
    void translate(const std::vector<Word>& words, LineResult& out, State& st) const;
    void motion(const Axes& axes, bool preset, LineResult& out, State& st) const;
    // The coordinate of `w` in unit increments into `u`; false (with the error) when it does not fit a word.
    [[nodiscard]] bool units(const Word& w, const State& st, LineResult& out, long long& u) const;
    // The ESSI function of G or M `number` in the dialect's table, or -1.
    [[nodiscard]] int function_of(char letter, int number) const {
        return (letter == 'G' ? g_function_ : m_function_)[static_cast<std::size_t>(number)];
    }
    // The value the word stands for with its function (Hypertherm M275 = 11+3), or -1.
    [[nodiscard]] int value_of(char letter, int number) const {
        return (letter == 'G' ? g_value_ : m_value_)[static_cast<std::size_t>(number)];
    }
    void function(std::uint32_t offset, int code, LineResult& out) const;
    void function_value(std::uint32_t offset, int code, double value, LineResult& out) const;
    void commit(const LineResult& r);
    void put_block(const LineResult::Out& o);
    // The digits and points of a number written from `begin`, before `end` (the line's end): what a message quotes.
    [[nodiscard]] std::string_view number_text_at(std::uint32_t begin, std::uint32_t end) const {
        std::uint32_t p = begin;
        while (p < end && ((src_[p] >= '0' && src_[p] <= '9') || src_[p] == '.')) ++p;
        return src_.substr(begin, p - begin);
    }

    // The dialect's words by number (make_tables): the function of each G and M, the role of each G.
    std::array<std::int16_t, kMaxCodeNumber + 1> g_function_{}, m_function_{}, g_value_{}, m_value_{};
    std::array<GRole, kMaxCodeNumber + 1> g_role_{};
    int unit_decimals_ = -1;  // unit_mm = 10^-unit_decimals_ (0-9), or -1 (another unit: in doubles)
    std::array<std::int8_t, 256> letter_rank_{};  // a letter's place in eia.letters, -1 when not allowed
    std::vector<Word> words_;                     // the line's words (kept: no allocation a line)
    LineResult line_out_;                         // the line's blocks and diagnostics (likewise)
    State state_;
    // Coordinates rounded to the unit (W125, one warning for the tape at the first).
    std::size_t rounded_ = 0;
    std::uint32_t rounded_line_ = 0, rounded_column_ = 0;
};

void EiaReader::reserve_whole(Tape& tape) const {
    const std::size_t lines = static_cast<std::size_t>(std::count(src_.begin(), src_.end(), '\n')) + 1;
    blocks_of(tape).reserve(lines);
    words_of(tape).reserve(2 * lines);
    word_index_of(tape).reserve(lines / Tape::kWordIndexStride + 1);
}

// Letters and their numbers; comments "( ... )" are skipped. False (with the error) when the line cannot be read.
bool EiaReader::parse_words(std::uint32_t begin, std::uint32_t end, std::vector<Word>& words, LineResult& out) const {
    std::uint32_t p = begin;
    const auto error = [&](DiagCode code, std::uint32_t at, Msg msg, MessageArgs args = {}) {
        out.diagnostics.push_back({Severity::Error, code, at, msg, std::move(args)});
        return false;
    };
    while (p < end) {
        const auto c = static_cast<unsigned char>(src_[p]);
        if (c == ' ' || c == '\t') {
            ++p;
            continue;
        }
        if (c == '(') {
            const std::size_t close = src_.substr(0, end).find(')', p);
            if (close == std::string_view::npos)
                return error(DiagCode::E126_EiaUnclosedComment, p, Msg::EiaUnclosedComment);
            p = static_cast<std::uint32_t>(close) + 1;
            continue;
        }
        const char letter = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
        if (letter_rank_[static_cast<unsigned char>(letter)] < 0) {
            std::string expected;
            for (char l : profile_.eia.letters) expected += (expected.empty() ? "" : " ") + std::string(1, l);
            if (c >= 0x80 || c < 0x20)
                return error(DiagCode::E119_EiaUnknownLetter, p, Msg::EiaUnknownByte,
                             {detail::hex_byte(c), expected, profile_.name});
            return error(DiagCode::E119_EiaUnknownLetter, p, Msg::EiaUnknownChar,
                         {src_.substr(p, 1), expected, profile_.name});
        }
        Word w;
        w.letter = letter;
        w.offset = p++;
        bool negative = false;
        if (p < end && (src_[p] == '+' || src_[p] == '-')) negative = src_[p++] == '-';
        int digits = 0;
        bool point = false;
        const std::uint32_t number_start = p;
        while (p < end && ((src_[p] >= '0' && src_[p] <= '9') || (src_[p] == '.' && !point))) {
            if (src_[p] == '.') {
                point = true;
            } else {
                if (++digits > kMaxNumberDigits)
                    return error(DiagCode::E122_EiaBadNumber, w.offset, Msg::EiaNumberTooLong,
                                 {std::string(1, letter), kMaxNumberDigits,
                                  excerpt(number_text_at(number_start, end), kExcerptChars)});
                w.mantissa = w.mantissa * 10 + (src_[p] - '0');
                if (point) ++w.decimals;
            }
            ++p;
        }
        if (digits == 0)
            return error(DiagCode::E122_EiaBadNumber, w.offset, Msg::EiaLetterWithoutNumber,
                         {std::string(1, letter), letter == 'G' || letter == 'M' ? "01" : "12.5"});
        if (negative) w.mantissa = -w.mantissa;
        w.length = p - w.offset;
        words.push_back(w);
    }
    return true;
}

// The dialect's order rules: letters in the order of Profile::eia.letters (when strict) and coordinates, N and F
// at most once; at most one of G, M and F (when the dialect says so).
bool EiaReader::check_order(const std::vector<Word>& words, LineResult& out) const {
    const EiaDialect& e = profile_.eia;
    int last = 0;
    std::uint32_t seen = 0;  // bit (letter - 'A') for each letter of the block so far
    const Word* function_word = nullptr;
    for (std::size_t k = 0; k < words.size(); ++k) {
        const Word& w = words[k];
        const int rank = letter_rank_[static_cast<unsigned char>(w.letter)];  // (parse_words let only allowed ones in)
        const bool repeatable = w.letter == 'G' || w.letter == 'M';
        const std::uint32_t bit = 1u << (w.letter - 'A');
        const bool twice = (seen & bit) != 0;
        seen |= bit;
        if (twice && (!repeatable || e.strict_order)) {
            out.diagnostics.push_back({Severity::Error,
                                       DiagCode::E120_EiaLetterOrder,
                                       w.offset,
                                       Msg::EiaLetterTwice,
                                       {std::string(1, w.letter)}});
            return false;
        }
        if (e.strict_order && k > 0 && rank < last) {
            std::string order;
            for (char l : e.letters) order += (order.empty() ? "" : " ") + std::string(1, l);
            out.diagnostics.push_back(
                {Severity::Error,
                 DiagCode::E120_EiaLetterOrder,
                 w.offset,
                 Msg::EiaLetterOrder,
                 {std::string(1, w.letter), std::string(1, words[k - 1].letter), order, profile_.name}});
            return false;
        }
        last = std::max(last, rank);
        const bool is_function = w.letter == 'G' || w.letter == 'M' || w.letter == 'F';
        if (is_function && e.one_function_per_block) {
            if (function_word != nullptr) {
                out.diagnostics.push_back(
                    {Severity::Error,
                     DiagCode::E121_EiaFunctionsInBlock,
                     w.offset,
                     Msg::EiaFunctionsInBlock,
                     {profile_.name, std::string(1, function_word->letter), std::string(1, w.letter)}});
                return false;
            }
            function_word = &w;
        }
    }
    return true;
}

void EiaReader::make_tables() {
    for (int k = 0; k <= 9; ++k)
        if (std::fabs(profile_.unit_mm * static_cast<double>(kPowersOfTen[static_cast<std::size_t>(k)]) - 1.0) < 1e-12)
            unit_decimals_ = k;
    letter_rank_.fill(-1);
    for (std::size_t k = 0; k < profile_.eia.letters.size() && k < 127; ++k)
        letter_rank_[static_cast<unsigned char>(profile_.eia.letters[k])] = static_cast<std::int8_t>(k);
    g_function_.fill(-1);
    m_function_.fill(-1);
    g_value_.fill(-1);
    m_value_.fill(-1);
    g_role_.fill(GRole::None);
    const EiaDialect& e = profile_.eia;
    for (auto it = e.codes.rbegin(); it != e.codes.rend(); ++it) {  // (the first row of a word wins)
        if (it->word.number < 0 || it->word.number > kMaxCodeNumber) continue;
        const auto n = static_cast<std::size_t>(it->word.number);
        (it->word.letter == 'G' ? g_function_ : m_function_)[n] = static_cast<std::int16_t>(it->function);
        (it->word.letter == 'G' ? g_value_ : m_value_)[n] = static_cast<std::int16_t>(it->value);
        if (it->word.letter == 'G') g_role_[n] = GRole::Function;
    }
    for (const EiaWord& w : e.inch_words)
        if (w.letter == 'G' && w.number >= 0 && w.number <= kMaxCodeNumber)
            g_role_[static_cast<std::size_t>(w.number)] = GRole::Inch;
    for (const EiaWord& w : e.mm_words)
        if (w.letter == 'G' && w.number >= 0 && w.number <= kMaxCodeNumber)
            g_role_[static_cast<std::size_t>(w.number)] = GRole::Mm;
    if (e.position_preset_g >= 0 && e.position_preset_g <= kMaxCodeNumber)
        g_role_[static_cast<std::size_t>(e.position_preset_g)] = GRole::Preset;
    if (e.rapid_motion_g >= 0 && e.rapid_motion_g <= kMaxCodeNumber)
        g_role_[static_cast<std::size_t>(e.rapid_motion_g)] = GRole::Rapid;
    g_role_[kGLine] = GRole::Line;  // RS-274's motions mean the same in every dialect
    g_role_[kGArcCw] = GRole::ArcCw;
    g_role_[kGArcCcw] = GRole::ArcCcw;
}

const Word* EiaReader::Axes::first() const {
    const Word* f = nullptr;
    for (const Word* w : {x, y, i, j})
        if (w && (!f || w->offset < f->offset)) f = w;
    return f;
}

// A coordinate in unit increments: mm (or inches after G20/G70) divided by the unit; rounded (W125) when it is
// finer than the unit, an error when it does not fit a word.
bool EiaReader::units(const Word& w, const State& st, LineResult& out, long long& result) const {
    // The common case in whole numbers, exactly: mm with `decimals` decimals in a unit of 10^-unit_decimals_ mm.
    if (unit_decimals_ >= 0 && !st.inch) {
        const int shift = unit_decimals_ - w.decimals;
        long long u = 0;
        bool on_grid = true;
        if (shift >= 0) {
            u = w.mantissa * kPowersOfTen[static_cast<std::size_t>(shift)];  // (|mantissa| < 10^12, shift <= 9: fits)
        } else {
            const long long scale = kPowersOfTen[static_cast<std::size_t>(-shift)];
            const long long q = w.mantissa / scale, r = w.mantissa % scale;
            on_grid = r == 0;
            u = q + (2 * (r < 0 ? -r : r) >= scale ? (r < 0 ? -1 : 1) : 0);  // half away from zero, as std::round
        }
        if (u >= -std::numeric_limits<std::int32_t>::max() && u <= std::numeric_limits<std::int32_t>::max()) {
            if (!on_grid)
                out.diagnostics.push_back({Severity::Warning, DiagCode::W125_EiaRounded, w.offset, Msg::None, {}});
            result = u;
            return true;
        }
    }
    const double mm = w.value() * (st.inch ? kMmPerInch : 1.0);
    const double exact = mm / profile_.unit_mm;
    if (!(std::fabs(exact) <= static_cast<double>(std::numeric_limits<std::int32_t>::max()))) {
        out.diagnostics.push_back({Severity::Error,
                                   DiagCode::E122_EiaBadNumber,
                                   w.offset,
                                   Msg::EiaCoordinateTooLarge,
                                   {std::string(1, w.letter), excerpt(std::to_string(profile_.unit_mm), 8)}});
        return false;
    }
    const double rounded = std::round(exact);
    if (std::fabs(exact - rounded) > kOnGrid) {
        out.diagnostics.push_back(
            {Severity::Warning, DiagCode::W125_EiaRounded, w.offset, Msg::None, {}});  // (counted)
    }
    result = static_cast<long long>(rounded);
    return true;
}

void EiaReader::function(std::uint32_t offset, int code, LineResult& out) const {
    out.blocks.push_back({offset, BlockKind::Function, static_cast<std::uint16_t>(code), 0, 0, {}});
}

void EiaReader::function_value(std::uint32_t offset, int code, double value, LineResult& out) const {
    const double thousandths = std::round(value * 1000.0);
    if (!(std::fabs(thousandths) <= static_cast<double>(std::numeric_limits<std::int32_t>::max()))) {
        out.diagnostics.push_back(
            {Severity::Error, DiagCode::E122_EiaBadNumber, offset, Msg::EiaValueTooLarge, {code}});
        return;
    }
    LineResult::Out o{offset, BlockKind::FunctionValue, static_cast<std::uint16_t>(code), Block::kValueThousandths, 1,
                      {}};
    o.w[0] = static_cast<std::int32_t>(thousandths);
    o.packed |= 1;  // one word
    out.blocks.push_back(o);
}

// X Y I J of a block: one motion block (or, with the position preset word, a zero offset: 83 and its block).
void EiaReader::motion(const Axes& axes, bool preset, LineResult& out, State& st) const {
    const std::uint32_t offset = axes.first()->offset;
    const bool relative = !st.absolute && !preset;
    long long ex = relative ? 0 : st.x, ey = relative ? 0 : st.y, ci = 0, cj = 0;
    const auto value = [&](const Word* w, long long& u) { return w == nullptr || units(*w, st, out, u); };
    const bool x_ok = value(axes.x, ex), y_ok = value(axes.y, ey), i_ok = value(axes.i, ci), j_ok = value(axes.j, cj);
    if (!(x_ok && y_ok && i_ok && j_ok)) return;  // (each reported its error)
    const long long end_x = relative ? st.x + ex : ex, end_y = relative ? st.y + ey : ey;
    if (preset) {
        // The position becomes (X, Y): the origin moves by (position - preset), relative to the current one (83).
        LineResult::Out o{offset, BlockKind::Motion, Block::kNoCode, 2, 2, {}};
        o.w[0] = static_cast<std::int32_t>(std::clamp<long long>(st.x - end_x, INT32_MIN, INT32_MAX));
        o.w[1] = static_cast<std::int32_t>(std::clamp<long long>(st.y - end_y, INT32_MIN, INT32_MAX));
        function(offset, fn::kZeroOffset, out);
        out.blocks.push_back(o);
        st.x = end_x;
        st.y = end_y;
        return;
    }
    const bool arc = axes.i != nullptr || axes.j != nullptr;
    if (arc && st.arc == ArcMode::None) {
        out.diagnostics.push_back({Severity::Error,
                                   DiagCode::E123_EiaArcWithoutDirection,
                                   (axes.i ? axes.i : axes.j)->offset,
                                   Msg::EiaArcWithoutDirection,
                                   {}});
        return;
    }
    LineResult::Out o{offset, BlockKind::Motion, Block::kNoCode, 0, arc ? 5 : 2, {}};
    // ESSI words: relative to the start (81) or absolute (82); the centre likewise, from I/J relative to the start.
    o.w[0] = static_cast<std::int32_t>(st.absolute ? end_x : end_x - st.x);
    o.w[1] = static_cast<std::int32_t>(st.absolute ? end_y : end_y - st.y);
    if (arc) {
        o.w[2] = static_cast<std::int32_t>(st.absolute ? st.x + ci : ci);
        o.w[3] = static_cast<std::int32_t>(st.absolute ? st.y + cj : cj);
        o.w[4] = 0;
        if (st.arc == ArcMode::Clockwise) o.packed |= Block::kTcNegative;  // TC '-': clockwise (ISO A.7)
    }
    o.packed |= static_cast<std::uint8_t>(o.words);
    out.blocks.push_back(o);
    st.x = end_x;
    st.y = end_y;
}

// One EIA block's words -> its ESSI blocks, in the order a controller runs them: G modes, F, M functions, the
// motion, then stops and the end.
void EiaReader::translate(const std::vector<Word>& words, LineResult& out, State& st) const {
    const EiaDialect& e = profile_.eia;
    const Word* dwell = nullptr;
    bool preset = false;
    std::uint32_t after_offset[2] = {};
    int after_code[2] = {-1, -1};  // stops and end codes: after the motion (at most two kept)
    const auto set_rapid = [&](bool on, std::uint32_t offset) {
        if (e.rapid_motion_g < 0 || st.rapid == on) return;
        function(offset, on ? fn::kRapidOn : fn::kRapidOff, out);
        st.rapid = on;
    };
    const auto unknown = [&](const Word& w, Msg msg, MessageArgs args) {
        out.diagnostics.push_back({Severity::Warning, DiagCode::W124_EiaUnknownCode, w.offset, msg, std::move(args)});
    };
    for (const Word& w : words) {
        if (w.letter == 'F') {
            function_value(w.offset, fn::kFeed, w.value() * (st.inch ? kMmPerInch : 1.0), out);
            continue;
        }
        if (w.letter != 'G' && w.letter != 'M') {
            if (!reads_letter(w.letter, e))
                unknown(w, Msg::EiaWordNotRead, {std::string(1, w.letter) + number_text(w.value())});
            continue;
        }
        const int n = w.code_number();
        if (n < 0) {
            unknown(w, Msg::EiaNotACode,
                    {excerpt(src_.substr(w.offset, w.length), kExcerptChars), std::string(1, w.letter)});
            continue;
        }
        const GRole role = w.letter == 'G' ? g_role_[static_cast<std::size_t>(n)] : GRole::Function;
        switch (role) {
            case GRole::Line:
            case GRole::ArcCw:
            case GRole::ArcCcw:
                set_rapid(false, w.offset);
                st.arc = role == GRole::Line    ? ArcMode::None
                         : role == GRole::ArcCw ? ArcMode::Clockwise
                                                : ArcMode::CounterClockwise;
                break;
            case GRole::Rapid:
                set_rapid(true, w.offset);
                st.arc = ArcMode::None;
                break;
            case GRole::Preset: preset = true; break;
            case GRole::Inch: st.inch = true; break;
            case GRole::Mm: st.inch = false; break;
            case GRole::None: unknown(w, Msg::EiaNotInTable, {word_text(w.letter, n), profile_.name}); break;
            case GRole::Function: {
                const int f = function_of(w.letter, n);
                if (f < 0) {
                    unknown(w, Msg::EiaNotInTable, {word_text(w.letter, n), profile_.name});
                } else if (f == fn::kDwell) {
                    dwell = &w;
                } else if (f == fn::kProgramStop || f == fn::kOptionalStop || is_end_function(f)) {
                    const int k = after_code[0] < 0 ? 0 : 1;
                    after_code[k] = f;
                    after_offset[k] = w.offset;
                } else if (const int v = value_of(w.letter, n); v >= 0) {
                    function_value(w.offset, f, v, out);
                } else {
                    if (f == fn::kAbsolute) st.absolute = true;
                    if (f == fn::kIncremental) st.absolute = false;
                    function(w.offset, f, out);
                }
                break;
            }
        }
    }
    Axes axes;
    const Word* dwell_time = nullptr;
    for (const Word& w : words) {
        if (dwell && w.letter == e.dwell_letter) dwell_time = &w;  // (G04 X: the time, not an axis)
        else if (w.letter == 'X') axes.x = &w;
        else if (w.letter == 'Y') axes.y = &w;
        else if (w.letter == 'I') axes.i = &w;
        else if (w.letter == 'J') axes.j = &w;
    }
    if (dwell) {
        // (seconds, written in the unit of ESSI's 41+v: the profile's dwell_unit_s)
        if (dwell_time)
            function_value(dwell->offset, fn::kDwell, dwell_time->value() * e.dwell_unit_s / profile_.dwell_unit_s,
                           out);
        else function(dwell->offset, fn::kDwell, out);  // the profile's dwell
    }
    if (axes.x || axes.y || axes.i || axes.j) motion(axes, preset, out, st);
    for (int k = 0; k < 2; ++k)
        if (after_code[k] >= 0) function(after_offset[k], after_code[k], out);
}

void EiaReader::read_block(std::uint32_t begin, std::uint32_t end, LineResult& out, State& st) {
    words_.clear();
    if (!parse_words(begin, end, words_, out) || words_.empty()) return;
    if (!check_order(words_, out)) return;
    translate(words_, out, st);
}

void EiaReader::put_block(const LineResult::Out& o) {
    words_of(chunk()).append(o.w, static_cast<std::size_t>(o.words));
    push_block(o.offset, o.kind, o.code, o.packed);
}

void EiaReader::commit(const LineResult& r) {
    for (const LineDiagnostic& d : r.diagnostics) {
        if (d.code == DiagCode::W125_EiaRounded) {
            if (rounded_++ == 0) {
                rounded_line_ = line_;
                rounded_column_ = column(d.offset);
            }
            continue;
        }
        report(d.severity, d.code, d.offset, d.msg, d.args);
    }
    for (const LineResult::Out& o : r.blocks) {
        if (ended_) break;
        put_block(o);
        if (o.kind == BlockKind::Function && is_end_function(o.code)) mark_program_end();
    }
}

// A line: its blocks are worked out first (read_block, on a copy of the machine state), then committed with its
// diagnostics unless they do not fit in the chunk.
bool EiaReader::read_line(std::uint32_t begin, std::uint32_t end, std::size_t max_blocks) {
    const std::string_view text = trim_blanks(src_.substr(begin, end - begin));
    const auto text_at = static_cast<std::uint32_t>(text.empty() ? begin : text.data() - src_.data());
    LineResult& r = line_out_;
    r.blocks.clear();
    r.diagnostics.clear();
    State st = state_;
    if (text.empty()) {
    } else if (text == "%") {
        r.blocks.push_back({text_at, BlockKind::Percent, Block::kNoCode, 0, 0, {}});
    } else if (ended_) {
        report(Severity::Warning, DiagCode::W110_ContentAfterEnd, text_at, Msg::ReadContentAfterEnd, {end_line_});
        after_end_seen_ = true;
        return false;
    } else if (text.size() == 1 && is_end_mark(text[0])) {
        r.blocks.push_back({text_at, BlockKind::EndMark, Block::kNoCode, 0, 0, {}});
    } else if (text.front() == '(' && text.back() == ')' && text.find(')') == text.size() - 1) {
        r.blocks.push_back({text_at, BlockKind::Comment, Block::kNoCode, 0, 0, {}});
    } else {
        read_block(begin, end, r, st);
    }
    // A line's blocks go into one chunk: stop before a line that does not fit (it is read again next time).
    if (chunk_blocks_ > 0 && chunk_blocks_ + r.blocks.size() > max_blocks) return false;
    if (r.blocks.size() == 1 && r.blocks[0].kind == BlockKind::Percent) {
        put_block(r.blocks[0]);
        if (program_started_ && !ended_) {
            percent_line_ = line_;
            percent_column_ = column(text_at);
        }
        return true;
    }
    if (!r.blocks.empty() && r.blocks[0].kind == BlockKind::EndMark) {
        put_block(r.blocks[0]);
        mark_program_end();
    } else {
        commit(r);
    }
    state_ = st;
    return true;
}

void EiaReader::end_tape(Tape& chunk) {
    if (rounded_ == 0) return;
    diagnostics_of(chunk).push_back(
        make_diagnostic(Severity::Warning, DiagCode::W125_EiaRounded, rounded_line_, rounded_column_, Msg::EiaRounded,
                        {rounded_, excerpt(std::to_string(profile_.unit_mm), 8), profile_.name}));
}

std::unique_ptr<BlockReader> make_eia_reader(std::string_view bytes, const Profile& profile) {
    return std::make_unique<EiaReader>(bytes, profile);
}

}  // namespace essi
