// Input format and dialect from a tape's content (essi/dialect.hpp). The evidence rules are a table: a token
// pattern, the dialect it points to, and what it says; adding a dialect's sign is a row, not a branch.
#include "essi/dialect.hpp"

#include <algorithm>
#include <array>

#include "essi/lines.hpp"
#include "essi/text.hpp"

namespace essi {
namespace {

// The evidence is read from the tape's head and tail (a tape's dialect shows in its header and set-up, and in how
// it ends), so that the scan costs the same for any size.
constexpr std::size_t kHeadBytes = 16 << 10;
constexpr std::size_t kTailBytes = 4 << 10;
constexpr std::size_t kEvidencePerDialect = 3;  // what a report lists of each dialect's evidence
constexpr std::size_t kQuoteChars = 24;

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// Calls f(line number, trimmed text) for each non-empty line of `part`, whose first line is line `line`; stops
// when f returns false (and returns false).
template <class F>
bool for_each_line_of(std::string_view part, std::uint32_t line, F& f) {
    const char* p = part.data();
    std::size_t pos = 0;
    while (pos < part.size()) {
        const std::size_t end = find_line_end(part, pos);
        const std::string_view text = trim_blanks(std::string_view(p + pos, end - pos));
        if (!text.empty() && !f(line, text)) return false;
        if (end >= part.size()) break;
        pos = past_line_end(reinterpret_cast<const unsigned char*>(part.data()), static_cast<std::uint32_t>(end),
                            static_cast<std::uint32_t>(part.size()));
        ++line;
    }
    return true;
}

// Where a tape's tail starts (the first whole line of its last kTailBytes), or npos for a short tape that is
// scanned whole.
std::size_t tail_start(std::string_view bytes) {
    if (bytes.size() <= kHeadBytes + kTailBytes) return std::string_view::npos;
    const std::size_t end = bytes.find_first_of("\r\n", bytes.size() - kTailBytes);
    if (end == std::string_view::npos) return bytes.size();
    return past_line_end(reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<std::uint32_t>(end),
                         static_cast<std::uint32_t>(bytes.size()));
}

// Line numbers of the tail's lines count from kTailLine: the true number is worked out (a pass over the middle of
// the tape) only for the rare evidence found there.
constexpr std::uint32_t kTailLine = 0x80000000u;

// for_each_line_of over the head and the tail of a long tape (whole lines of each), or over the whole of a
// short one.
template <class F>
void for_each_line(std::string_view bytes, F&& f) {
    const std::size_t tail = tail_start(bytes);
    if (tail == std::string_view::npos) {
        for_each_line_of(bytes, 1, f);
        return;
    }
    std::string_view head = bytes.substr(0, kHeadBytes);
    head = head.substr(0, head.find_last_of("\r\n") + 1);  // (a cut-off line says nothing)
    if (!for_each_line_of(head, 1, f)) return;
    for_each_line_of(bytes.substr(tail), kTailLine, f);
}

// One sign of a dialect: an ESSI block ("/", "135+", "43") or an EIA word ("G05", "M70"), what it means (a row of
// core/i18n/messages/dialect.def).
struct Sign {
    std::string_view token;
    std::string_view dialect;
    Msg meaning;
};

// ESSI: a function code alone ("43"), with a value ("135+"), or a mark ("/").
constexpr std::array kEssiSigns = {
    Sign{"/", "woyda", Msg::EvidenceEndsProgram},           Sign{"135+", "woyda", Msg::EvidenceBurnerCount},
    Sign{"136+", "woyda", Msg::EvidenceBurnerSpacing},      Sign{"43", "woyda", Msg::EvidenceWoydaOxygenOff},
    Sign{"62", "woyda", Msg::EvidenceWoydaProgramZero},     Sign{"66", "woyda", Msg::EvidenceWoydaRepeatStart},
    Sign{"11+", "hypertherm", Msg::EvidenceMarkerOffsetOn}, Sign{"12+", "hypertherm", Msg::EvidenceMarkerOffsetOff},
};

// Which bytes start a sign's token: a line that starts otherwise is none of them (most function codes).
template <std::size_t N>
constexpr std::array<bool, 256> first_bytes_of(const std::array<Sign, N>& signs) {
    std::array<bool, 256> first{};
    for (const Sign& s : signs) first[static_cast<unsigned char>(s.token.front())] = true;
    return first;
}
constexpr std::array<bool, 256> kEssiSignFirstBytes = first_bytes_of(kEssiSigns);

// EIA words.
constexpr std::array kEiaSigns = {
    Sign{"G05", "woyda", Msg::EvidenceWoydaRapidOn},
    Sign{"G06", "woyda", Msg::EvidenceWoydaRapidOff},
    Sign{"M70", "woyda", Msg::EvidenceWoydaCuttingOn},
    Sign{"M71", "woyda", Msg::EvidenceWoydaCuttingOff},
    Sign{"M22", "woyda", Msg::EvidenceWoydaPlasmaOn},
    Sign{"M67", "woyda", Msg::EvidenceWoydaKerfLeft},
    Sign{"M68", "woyda", Msg::EvidenceWoydaKerfRight},
    Sign{"G90", "din66025", Msg::EvidenceDinAbsolute},
    Sign{"G71", "din66025", Msg::EvidenceDinMillimetres},
    Sign{"G70", "din66025", Msg::EvidenceDinInches},
    Sign{"M03", "din66025", Msg::EvidenceDinToolOn},
    Sign{"M05", "din66025", Msg::EvidenceDinToolOff},
    Sign{"G21", "hypertherm", Msg::EvidenceHyperthermMillimetres},
    Sign{"G20", "hypertherm", Msg::EvidenceHyperthermInches},
    Sign{"M07", "hypertherm", Msg::EvidenceHyperthermCutOn},
    Sign{"M08", "hypertherm", Msg::EvidenceHyperthermCutOff},
};

// One sign found: where, and what the line says.
struct Found {
    const Sign* sign;
    std::uint32_t line;  // kTailLine + k: line k of the tail
    std::string quote;
};

struct Tally {
    std::string_view dialect;
    std::size_t signs = 0;  // distinct signs seen
    std::vector<Found> found;
};

struct Evidence {
    std::vector<Tally> tallies;
    std::vector<std::string_view> seen;  // tokens already counted (each sign counts once)
    void add(const Sign& s, std::uint32_t line, std::string_view quote) {
        if (std::find(seen.begin(), seen.end(), s.token) != seen.end()) return;
        seen.push_back(s.token);
        auto it = std::find_if(tallies.begin(), tallies.end(), [&](const Tally& t) { return t.dialect == s.dialect; });
        if (it == tallies.end()) it = tallies.insert(tallies.end(), Tally{s.dialect, 0, {}});
        ++it->signs;
        if (it->found.size() < kEvidencePerDialect) it->found.push_back({&s, line, excerpt(quote, kQuoteChars)});
    }
};

// "woyda: `/` ends the program at line 29" (DialectEvidence), the tail's lines numbered from the start of the tape.
Message evidence_message(const Found& f, std::string_view bytes) {
    std::uint32_t line = f.line;
    if (line >= kTailLine) {
        LineIndex index;  // (the lines before the tail: only for evidence found there)
        index.build(bytes.substr(0, tail_start(bytes)));
        line = line - kTailLine + static_cast<std::uint32_t>(index.line_count()) + 1;
    }
    return {Msg::DialectEvidence, {f.sign->dialect, f.quote, f.sign->meaning, line}};
}

// The ESSI token of a line for kEssiSigns: "/", "135+" (a function with a value), "43" (a function alone); empty
// for the others (motions, most lines: they start with a sign).
std::string_view essi_token(std::string_view t) {
    if (t == "/") return t;
    std::size_t digits = 0;
    while (digits < t.size() && t[digits] >= '0' && t[digits] <= '9') ++digits;
    if (digits == 0 || digits > 3) return {};
    if (digits == t.size()) return t;
    if (t[digits] == '+' && t.find_first_of("+-", digits + 1) == std::string_view::npos) return t.substr(0, digits + 1);
    return {};
}

void scan_essi(std::string_view bytes, Evidence& ev) {
    bool comment = false, after_63 = false;
    std::uint32_t line_63 = 0;
    for_each_line(bytes, [&](std::uint32_t line, std::string_view t) {
        if (comment) {
            comment = t != "4";
            return true;
        }
        if (t == "3") {
            comment = true;
            return true;
        }
        if (after_63 && (t.front() == '+' || t.front() == '-')) {
            static constexpr Sign kGoesOn{"63 ...", "iso6582", Msg::EvidenceGoesOnAfter63};  // (at the 63's line)
            ev.add(kGoesOn, line_63, "63");
            after_63 = false;
        }
        if (t == "63") {
            after_63 = true;
            line_63 = line;
        }
        if (!kEssiSignFirstBytes[static_cast<unsigned char>(t.front())]) return true;
        const std::string_view token = essi_token(t);
        if (token.empty()) return true;
        for (const Sign& s : kEssiSigns)
            if (token == s.token) ev.add(s, line, t);
        return true;
    });
}

void scan_eia(std::string_view bytes, Evidence& ev) {
    for_each_line(bytes, [&](std::uint32_t line, std::string_view t) {
        bool comment = false;
        for (std::size_t i = 0; i < t.size(); ++i) {
            if (t[i] == '(') comment = true;
            if (t[i] == ')') comment = false;
            if (comment || !is_letter(t[i]) || (t[i] != 'G' && t[i] != 'M' && t[i] != 'g' && t[i] != 'm')) continue;
            std::size_t j = i + 1;
            while (j < t.size() && t[j] >= '0' && t[j] <= '9') ++j;
            if (j == i + 1 || j - i - 1 > 3) continue;
            const int n = std::stoi(std::string(t.substr(i + 1, j - i - 1)));
            char word[8];
            std::snprintf(word, sizeof word, "%c%02d", t[i] == 'g' || t[i] == 'G' ? 'G' : 'M', n);
            for (const Sign& s : kEiaSigns)
                if (s.token == word) ev.add(s, line, word);
        }
        return true;
    });
}

}  // namespace

InputFormat detect_input_format(std::string_view bytes) {
    InputFormat found = InputFormat::Essi;
    for_each_line(bytes, [&](std::uint32_t, std::string_view t) {
        if (t == "%" || t.front() == '(' || t.front() == ';') return true;  // marks and comments say nothing
        found = is_letter(t.front()) ? InputFormat::Eia : InputFormat::Essi;
        return false;
    });
    return found;
}

DialectGuess guess_dialect(std::string_view bytes, InputFormat format) {
    Evidence ev;
    if (format == InputFormat::Eia) scan_eia(bytes, ev);
    else scan_essi(bytes, ev);
    DialectGuess g;
    g.profile = format == InputFormat::Eia ? "woyda" : "iso6582";
    std::stable_sort(ev.tallies.begin(), ev.tallies.end(),
                     [](const Tally& a, const Tally& b) { return a.signs > b.signs; });
    if (!ev.tallies.empty()) {
        g.profile = std::string(ev.tallies[0].dialect);
        g.clear = ev.tallies.size() == 1 || ev.tallies[0].signs > ev.tallies[1].signs;
        for (const Tally& t : ev.tallies)
            for (const Found& f : t.found) {
                g.evidence_messages.push_back(evidence_message(f, bytes));
                g.evidence.push_back(g.evidence_messages.back().text(Lang::En));
            }
    }
    return g;
}

bool parse_input_choice(std::string_view text, std::optional<InputFormat>& format) {
    if (text == "auto" || text.empty()) {
        format.reset();
        return true;
    }
    const auto named = parse_input_format(text);
    if (named) format = named;
    return named.has_value();
}

TapeSetup setup_tape(std::string_view bytes, std::optional<InputFormat> format, const std::optional<Profile>& profile) {
    TapeSetup s;
    s.format = format ? *format : detect_input_format(bytes);
    DialectGuess guess = guess_dialect(bytes, s.format);
    s.evidence = guess.evidence;
    s.evidence_messages = guess.evidence_messages;
    if (!profile) {
        s.auto_profile = true;
        s.profile = *builtin_profile(guess.profile);
        return s;
    }
    s.profile = *profile;
    // A custom profile is named after its base ("woyda+custom") unless it names itself.
    const std::string_view base = std::string_view(profile->name).substr(0, profile->name.find('+'));
    if (guess.clear && base != guess.profile) {
        std::vector<Message> why;  // (the evidence of the dialect it looks like)
        for (std::size_t i = 0; i < guess.evidence_messages.size(); ++i)
            if (guess.evidence[i].rfind(guess.profile + ":", 0) == 0) why.push_back(guess.evidence_messages[i]);
        s.note = make_diagnostic(Severity::Note, DiagCode::N403_OtherDialect, 1, 1, Msg::DialectLooksLike,
                                 {guess.profile, MessageArgs::Arg::messages(why), profile->name});
    }
    return s;
}

}  // namespace essi
