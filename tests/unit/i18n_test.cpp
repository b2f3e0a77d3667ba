// The message catalogue's formatter and the diagnostics in three languages (essi/i18n.hpp, docs/languages.md).
#include <gtest/gtest.h>

#include <string>

#include "essi/diagnostics.hpp"
#include "essi/i18n.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"

using essi::Lang;
using essi::MessageArgs;
using essi::Msg;

TEST(I18n, TemplatesPutArgumentsAndPluralWords) {
    EXPECT_EQ(essi::format_template("a {1} b {0}", Lang::En, {"x", 7}), "a 7 b x");
    EXPECT_EQ(essi::format_template("{0} word{0||s}", Lang::En, {1}), "1 word");
    EXPECT_EQ(essi::format_template("{0} word{0||s}", Lang::En, {2}), "2 words");
    EXPECT_EQ(essi::format_template("{0} {0|Wort|Wörter}", Lang::De, {3}), "3 Wörter");
    EXPECT_EQ(essi::format_template("{2}", Lang::En, {"only"}), "");      // a missing argument: nothing
    EXPECT_EQ(essi::format_template("{x} {", Lang::En, {"a"}), "{x} {");  // not a placeholder: as written
}

TEST(I18n, ArgumentsThatAreWordsAreShownInTheReadersLanguage) {
    const MessageArgs args{Msg::WordATab};
    EXPECT_EQ(essi::format_message(Msg::ReadWhitespaceSkipped, Lang::En, args),
              "a tab inside a block was skipped; ESSI blocks hold only + - 0-9");
    EXPECT_EQ(essi::format_message(Msg::ReadWhitespaceSkipped, Lang::De, args),
              "ein Tabulator in einem Satz wurde übersprungen; ESSI-Sätze enthalten nur + - 0-9");
    EXPECT_EQ(essi::format_message(Msg::ReadWhitespaceSkipped, Lang::Zh, args),
              "已跳过程序块内的制表符;ESSI 程序块只含 + - 0-9");
}

TEST(I18n, ListsJoinInTheReadersLanguage) {
    const MessageArgs alternatives{MessageArgs::Arg::alternatives({"63", "64", "/"})};
    EXPECT_EQ(essi::format_template("{0}", Lang::En, alternatives), "63, 64 or /");
    EXPECT_EQ(essi::format_template("{0}", Lang::De, alternatives), "63, 64 oder /");
    EXPECT_EQ(essi::format_template("{0}", Lang::Zh, alternatives), "63、64 或 /");
    const MessageArgs tools{MessageArgs::Arg::combined({Msg::ToolOxygen, Msg::ToolPunch})};
    EXPECT_EQ(essi::format_template("{0}", Lang::En, tools), "oxygen+punch");
    EXPECT_EQ(essi::format_template("{0}", Lang::De, tools), "Sauerstoff+Körner");
    // Bytes the packing uses cannot come in through a text argument.
    EXPECT_EQ(essi::format_template("{0}|{1}", Lang::En,
                                    {"a\x1f"
                                     "b",
                                     "c"}),
              "a\\x1Fb|c");
}

TEST(I18n, LanguageFromTagsAndTheEnvironment) {
    EXPECT_EQ(essi::parse_lang("de_DE.UTF-8"), Lang::De);
    EXPECT_EQ(essi::parse_lang("zh-Hans-CN"), Lang::Zh);
    EXPECT_EQ(essi::parse_lang("POSIX"), Lang::En);
    EXPECT_FALSE(essi::parse_lang("fr_FR").has_value());
    EXPECT_EQ(essi::lang_from_environment(nullptr, nullptr, "de_AT.UTF-8"), Lang::De);
    EXPECT_EQ(essi::lang_from_environment("", "zh_CN.GB18030", "de_DE"), Lang::Zh);  // an empty LC_ALL is unset
    EXPECT_EQ(essi::lang_from_environment("C", "zh_CN", "de_DE"), Lang::En);         // LC_ALL wins
    EXPECT_EQ(essi::lang_from_environment(nullptr, nullptr, "fr_FR"), Lang::En);     // none of ours: English
    EXPECT_EQ(essi::lang_from_environment(nullptr, nullptr, nullptr), Lang::En);
}

// A tape's diagnostics, read once, shown in each language.
TEST(I18n, DiagnosticsOfATapeInEachLanguage) {
    const essi::CheckResult r = essi::check_tape("7\n+100+0\n+0+1x\n+1+2+3\n8\n", *essi::builtin_profile("woyda"));
    ASSERT_EQ(r.diagnostics.size(), 3u);
    const essi::Diagnostic& bad_char = r.diagnostics[0];
    EXPECT_EQ(bad_char.code, essi::DiagCode::E101_InvalidCharacter);
    EXPECT_EQ(essi::diagnostic_message(bad_char, Lang::En), "unexpected 'x' (0x78); expected + - or a digit");
    EXPECT_EQ(essi::diagnostic_message(bad_char, Lang::De),
              "unerwartetes Zeichen 'x' (0x78); erwartet: + - oder eine Ziffer");
    EXPECT_EQ(essi::diagnostic_message(bad_char, Lang::Zh), "意外的字符 'x'(0x78);应为 + - 或数字");
    const essi::Diagnostic& count = r.diagnostics[1];
    EXPECT_EQ(count.code, essi::DiagCode::E105_WordCount);
    EXPECT_EQ(essi::diagnostic_message(count, Lang::De),
              "3 Wörter mit Vorzeichen gefunden; erwartet: 2 (Strecke DX DY), 5 (Kreisbogen DX DY XC YC TC) oder 6 "
              "(Parabel DX DY XP YP TC TP)");
    const essi::Diagnostic& no_end = r.diagnostics[2];
    EXPECT_EQ(no_end.code, essi::DiagCode::W114_NoProgramEnd);
    EXPECT_EQ(essi::diagnostic_message(no_end, Lang::Zh), "控制带结束时没有程序结束;最后一个程序块应为 63、64 或 /");
    EXPECT_EQ(essi::diagnostic_line("t.esi", bad_char, Lang::De),
              "t.esi:3:5: Fehler E101: unerwartetes Zeichen 'x' (0x78); erwartet: + - oder eine Ziffer");
}

// A diagnostic made from the catalogue keeps the row and its arguments, no sentence: its text in each language is
// made when asked, the same in a copy, and its other places go with it.
TEST(I18n, CatalogueDiagnosticIsWordedWhenShown) {
    essi::Diagnostic d =
        essi::make_diagnostic(essi::Severity::Error, essi::DiagCode::E602_KerfIntoPart, 7, 0, Msg::PlanKerfInsidePart,
                              {Msg::PlanSideLeft, Msg::PlanClockwise, Msg::PlanSideRight});
    d.add_related({9, 12, Msg::RelatedOtherPart, {}});
    EXPECT_EQ(d.msg, Msg::PlanKerfInsidePart);
    const essi::Diagnostic copy = d;
    for (const Lang lang : essi::kLanguages) {
        const std::string text = essi::format_message(Msg::PlanKerfInsidePart, lang,
                                                      {Msg::PlanSideLeft, Msg::PlanClockwise, Msg::PlanSideRight});
        EXPECT_EQ(essi::diagnostic_message(d, lang), text);
        EXPECT_EQ(essi::diagnostic_message(copy, lang), text);
    }
    EXPECT_NE(essi::diagnostic_message(d, Lang::En).find("inside this part (left (29), travelling clockwise)"),
              std::string::npos)
        << essi::diagnostic_message(d, Lang::En);
    EXPECT_NE(essi::diagnostic_message(d, Lang::De).find("links (29)"), std::string::npos);
    EXPECT_NE(essi::diagnostic_message(d, Lang::Zh).find("左侧(29)"), std::string::npos);
    ASSERT_EQ(copy.related().size(), 1u);
    EXPECT_EQ(copy.related()[0].end_line, 12u);
    EXPECT_EQ(essi::related_message(copy.related()[0], Lang::De), "das andere Teil");
    EXPECT_TRUE(copy.overlap().empty());
}

// A diagnostic given a text of its own keeps it as it is, in every language (no template, no escaping).
TEST(I18n, FreeTextDiagnosticKeepsItsText) {
    essi::Diagnostic d =
        essi::make_diagnostic(essi::Severity::Warning, essi::DiagCode::W201_UnknownFunction, 3, 1, Msg::PlanSideLeft);
    const std::string text = "a text of its own: {0} {1|one|other} \x1f \"quoted\"";
    d.set_text(text);
    EXPECT_EQ(d.msg, Msg::None);
    for (const Lang lang : essi::kLanguages) EXPECT_EQ(essi::diagnostic_message(d, lang), text);
    const essi::Diagnostic copy = d;
    EXPECT_EQ(essi::diagnostic_message(copy, Lang::Zh), text);
    EXPECT_EQ(essi::diagnostic_line("t.esi", copy, Lang::En), "t.esi:3:1: warning W201: " + text);
}

TEST(I18n, CodeSummariesInEachLanguage) {
    EXPECT_EQ(essi::code_summary(essi::DiagCode::E302_ArcZeroRadius), "An arc whose centre is its start point.");
    EXPECT_EQ(essi::code_summary(essi::DiagCode::E302_ArcZeroRadius, Lang::De),
              "Ein Kreisbogen, dessen Mittelpunkt sein Anfangspunkt ist.");
    EXPECT_EQ(essi::code_summary(essi::DiagCode::E302_ArcZeroRadius, Lang::Zh), "圆弧的圆心与起点重合。");
    for (essi::DiagCode c : essi::all_codes())
        for (Lang lang : essi::kLanguages) EXPECT_FALSE(essi::code_summary(c, lang).empty()) << essi::code_name(c);
}

TEST(I18n, TerminalWidthCountsWideCharactersTwice) {
    EXPECT_EQ(essi::display_width("cut length"), 10u);
    EXPECT_EQ(essi::display_width("切割长度"), 8u);
    EXPECT_EQ(essi::display_width("Schnittlänge"), 12u);
}
