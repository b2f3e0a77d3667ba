// Text for the user's terminal in the charset of the user's locale. essikit writes UTF-8; a terminal set up for
// GB 18030 (zh_CN.GB18030, GBK, GB 2312 — common in Chinese workshops) would show it as mojibake, so the human
// output (the text reports, stderr) is converted to that charset there. Machine formats (JSON, SARIF, JUnit,
// GitHub annotations, tapes, SVG) stay UTF-8 or bytes, as their own specifications say.
#pragma once

#include <string>
#include <string_view>

namespace essi::native {

class TerminalText {
public:
    // The charset is the part after '.' (before any '@') of the first of LC_ALL, LC_CTYPE, LANG that is set and not
    // empty (each may be null); UTF-8 unless it names GB 18030, GBK or GB 2312 (any case, with or without '-').
    TerminalText(const char* lc_all, const char* lc_ctype, const char* lang);
    // "GB18030", "GBK", "GB2312", or "" for UTF-8 (no conversion).
    [[nodiscard]] const std::string& charset() const { return charset_; }
    // `utf8` in the terminal's charset; a character it has no code for is '?'.
    [[nodiscard]] std::string operator()(std::string_view utf8) const;

private:
    std::string charset_;
};

}  // namespace essi::native
