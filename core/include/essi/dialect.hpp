// Which reading applies to a tape: its input format (ESSI or EIA, from the content) and its dialect (the built-in
// profile its evidence points to: `--profile auto`), with the evidence in words (docs/semantics.md §11).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"

namespace essi {

// The profile name that asks for the dialect the tape's evidence shows (`--profile auto`, the viewer's default).
constexpr std::string_view kAutoProfile = "auto";

// EIA when the first block (after %, blank lines and comments) starts with an address letter, else ESSI.
[[nodiscard]] InputFormat detect_input_format(std::string_view bytes);

struct DialectGuess {
    std::string profile;                       // a built-in profile name
    std::vector<std::string> evidence;         // "woyda: `/` ends the program at line 120", at most a few per dialect
    bool clear = false;                        // some evidence, and more of it than for any other dialect
    std::vector<Message> evidence_messages{};  // the evidence to be worded in any language (evidence[i]: the English)
};
// The dialect whose codes the tape uses (a scan of its lines, no interpretation). Without evidence: iso6582 for
// ESSI, woyda for EIA (the EIA table ESSI tapes pair with, §10).
[[nodiscard]] DialectGuess guess_dialect(std::string_view bytes, InputFormat format);

// How a tape is read: its format and profile, chosen or given (what `--input` and `--profile` say).
struct TapeSetup {
    InputFormat format = InputFormat::Essi;
    Profile profile;
    bool auto_profile = false;          // chosen from the evidence
    std::vector<std::string> evidence;  // the guess's evidence (for an auto profile: why it was chosen), in English
    std::optional<Diagnostic> note;     // N403 when the given profile is not the one the evidence clearly shows
    std::vector<Message> evidence_messages{};  // the evidence to be worded in any language (.text(lang))
};
// The format asked for (`--input`, the server's and the Python module's `input`): a format's name
// (parse_input_format), or "auto" or "" for the content's choice (nullopt, as setup_tape takes it). False for any
// other text.
[[nodiscard]] bool parse_input_choice(std::string_view text, std::optional<InputFormat>& format);
// `format`: nullopt = from the content; `profile`: nullopt = auto.
[[nodiscard]] TapeSetup setup_tape(std::string_view bytes, std::optional<InputFormat> format,
                                   const std::optional<Profile>& profile);

}  // namespace essi
