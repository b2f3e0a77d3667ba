// Messages never carry raw input bytes: whatever byte a tape or a profile holds where a message quotes it, the
// message is valid UTF-8 without control characters in every language (\xNN for the rest), and a quote stops at
// its word (never running on past the line's end).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/text.hpp"

using namespace essi;

namespace {

// Every message of `diagnostics`, in every language, is safe text.
void expect_safe(const std::vector<Diagnostic>& diagnostics, int byte, const char* what) {
    for (const Diagnostic& d : diagnostics) {
        for (Lang lang : kLanguages) {
            const std::string m = diagnostic_message(d, lang);
            EXPECT_TRUE(is_valid_utf8(m)) << what << " byte " << byte << ": " << display_text(m);
            EXPECT_EQ(display_text(m), m) << what << " byte " << byte << " " << code_name(d.code);
        }
    }
}

std::string byte_text(int b) { return std::string(1, static_cast<char>(b)); }

}  // namespace

TEST(Quoting, EveryByteInEveryQuotingPlaceIsEscaped) {
    const Profile din = *builtin_profile("din66025");
    for (int b = 0; b < 256; ++b) {
        const std::string x = byte_text(b);
        // W124: a G word that is no code, the byte right after it (and a line after that one).
        expect_safe(check_tape("%\nG90\nM03\nG-1" + x + "\nM05\nM30\n", din, InputFormat::Eia).diagnostics, b, "W124");
        // E122: a number of too many digits, the byte after its digits.
        expect_safe(check_tape("%\nG90\nX12345678901234" + x + "\nM30\n", din, InputFormat::Eia).diagnostics, b,
                    "E122");
        // E119: the byte where a letter should be.
        expect_safe(check_tape("%\nG90\nX1" + x + "Y2\nM30\n", din, InputFormat::Eia).diagnostics, b, "E119");
        // E101/E102/W109 and E103: ESSI bytes, and a function code of too many digits before the byte.
        expect_safe(check_tape("+10+0" + x + "\n1234567890123" + x + "\n64\n", Profile{}).diagnostics, b, "ESSI");
        // The dialect's evidence (N403) quotes a line of the tape.
        expect_safe(check_tape("7\n+10+0\n8\n/" + x + "\n",
                               setup_tape("7\n+10+0\n8\n/" + x + "\n", InputFormat::Essi, *builtin_profile("iso6582")))
                        .diagnostics,
                    b, "N403");
    }
}

TEST(Quoting, AQuoteStopsAtItsWord) {
    const Profile din = *builtin_profile("din66025");
    const CheckResult r = check_tape("%\nG90\nM03\nG-1 (\xff)\nM05\nM30\n", din, InputFormat::Eia);
    const Diagnostic* w124 = nullptr;
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == DiagCode::W124_EiaUnknownCode) w124 = &d;
    ASSERT_NE(w124, nullptr);
    EXPECT_EQ(w124->line, 4u);
    EXPECT_EQ(essi::diagnostic_message(*w124, essi::Lang::En), "G-1 is not a G code; it is ignored");
    const CheckResult e122 = check_tape("%\nX12345678901234\x1b[2J\nM30\n", din, InputFormat::Eia);
    ASSERT_FALSE(e122.diagnostics.empty());
    EXPECT_EQ(e122.diagnostics[0].code, DiagCode::E122_EiaBadNumber);
    EXPECT_EQ(essi::diagnostic_message(e122.diagnostics[0], essi::Lang::En).find('\x1b'), std::string::npos)
        << essi::diagnostic_message(e122.diagnostics[0], essi::Lang::En);
    EXPECT_NE(essi::diagnostic_message(e122.diagnostics[0], essi::Lang::En).find("12345678901234"), std::string::npos)
        << essi::diagnostic_message(e122.diagnostics[0], essi::Lang::En);
}

TEST(Quoting, MessageArgumentsAreMadeSafe) {
    const Diagnostic d = make_diagnostic(Severity::Error, DiagCode::E402_BadProfile, 0, 0, Msg::ProfileUnknownKey,
                                         {std::string("a\x1b[31m\xff\nb")});
    EXPECT_EQ(essi::diagnostic_message(d, essi::Lang::En), "unknown key \"a\\x1B[31m\\xFF\\x0Ab\"");
    EXPECT_EQ(diagnostic_message(d, Lang::Zh), "未知的键 \"a\\x1B[31m\\xFF\\x0Ab\"");
}

TEST(Quoting, AProfileNameIsPrintableAndShort) {
    const ProfileResult ok = parse_profile(R"({"name": "Werk 2 – Plasma 零件"})");
    ASSERT_TRUE(ok.profile);
    EXPECT_EQ(ok.profile->name, "Werk 2 – Plasma 零件");
    for (const std::string& bad : {std::string(R"({"name": "a\u001b[2Jb"})"), std::string(R"({"name": "two\nlines"})"),
                                   std::string(R"({"name": ""})"), R"({"name": ")" + std::string(65, 'n') + "\"}"}) {
        const ProfileResult r = parse_profile(bad);
        EXPECT_FALSE(r.profile) << bad;
        ASSERT_EQ(r.diagnostics.size(), 1u) << bad;
        EXPECT_NE(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En)
                      .find("\"name\" must be 1 to 64 bytes of printable UTF-8 text"),
                  std::string::npos)
            << essi::diagnostic_message(r.diagnostics[0], essi::Lang::En);
        EXPECT_EQ(display_text(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En)),
                  essi::diagnostic_message(r.diagnostics[0], essi::Lang::En));
    }
}
