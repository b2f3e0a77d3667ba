// What every subcommand of `essi` shares: its exit codes, the language of its messages, and where its output goes
// (stdout as it is, or in the terminal's charset for people; stderr for problems).
#pragma once

#include <string>
#include <string_view>

#include "essi/i18n.hpp"

namespace essi::cli {

constexpr int kExitOk = 0;
constexpr int kExitTapeErrors = 1;
constexpr int kExitUsage = 2;  // bad arguments, unreadable file or profile, output failure

constexpr int kJsonIndent = 2;

// The language of every message and report (--lang, else the environment): set once in main().
[[nodiscard]] Lang lang();
void set_lang(Lang lang);

// Output as it is: JSON, SARIF, JUnit, GitHub annotations, tapes, traces, pictures (UTF-8 or bytes by their format).
void out(std::string_view s);
// Output for people (the text formats): in the terminal's charset (UTF-8, or GB 18030 / GBK / GB 2312 by the locale).
void out_text(std::string_view s);
// A problem on stderr, in the terminal's charset.
void err(std::string_view s);

// `path` ("-": stdout) holds `bytes`; false when it cannot be written (errno says why).
[[nodiscard]] bool write_file(const std::string& path, std::string_view bytes);

// `code`, or kExitUsage after a message when stdout could not be written (a full disk, a closed pipe).
[[nodiscard]] int finish(int code);

}  // namespace essi::cli
