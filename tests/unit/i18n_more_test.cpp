// The texts that came to the catalogue last (docs/languages.md): `essi diff` and the viewer's compare window
// (diff.def), the dialect's evidence and N403 (dialect.def), the profile's errors E402 (profile.def), a share link's
// problems (link.def); each in German and Chinese, and in English as it always was. And the argument they share:
// messages with their own arguments (MessageArgs::Arg::messages).
#include <gtest/gtest.h>

#include <string>

#include "essi/dialect.hpp"
#include "essi/diff.hpp"
#include "essi/i18n.hpp"
#include "essi/profile.hpp"
#include "essi/share_link.hpp"

using essi::Lang;
using essi::Message;
using essi::MessageArgs;
using essi::Msg;

namespace {

essi::TapeContours contours_of(const std::string& tape) {
    essi::TapeSetup setup;
    setup.profile = *essi::builtin_profile("iso6582");
    return essi::tape_contours(tape, setup);
}

// Two revisions: a square and a second one that B moves 5 mm along x (the lines renumbered by a comment).
struct TwoRevisions {
    essi::TapeContours a = contours_of(
        "7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+2000+0\n6\n7\n+500+0\n+0+500\n-500+0\n+0-500\n8\n64\n");
    essi::TapeContours b = contours_of(
        "3\nREV "
        "B\n4\n7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+2050+0\n6\n7\n+500+0\n+0+500\n-500+0\n+0-500\n8\n64\n");
    essi::TapeDiff d = essi::diff_contours(a.contours, b.contours);
    essi::DiffSide sa{"a.esi", &a}, sb{"b.esi", &b};
};

}  // namespace

TEST(I18nMore, MessagesWithTheirOwnArgumentsAreWordedInTheReadersLanguage) {
    const Message burner{Msg::DialectEvidence, {"woyda", "135+2", Msg::EvidenceBurnerCount, 9}};
    const Message slash{Msg::DialectEvidence, {"woyda", "/", Msg::EvidenceEndsProgram, 29}};
    const MessageArgs args{MessageArgs::Arg::messages({burner, slash}), "x"};
    EXPECT_EQ(essi::format_template("({0}) {1}", Lang::En, args),
              "(woyda: `135+2` sets the burner count at line 9; woyda: `/` ends the program at line 29) x");
    EXPECT_EQ(essi::format_template("({0}) {1}", Lang::De, args),
              "(woyda: `135+2` setzt die Anzahl Brenner in Zeile 9; woyda: `/` beendet das Programm in Zeile 29) x");
    EXPECT_EQ(essi::format_template("({0}) {1}", Lang::Zh, args),
              "(woyda:第 9 行 `135+2` 设定割炬数量;woyda:第 29 行 `/` 结束程序) x");
    // One message, and one whose arguments hold a list and the bytes the nesting uses: nothing leaks out (\xNN).
    EXPECT_EQ(essi::format_template("{0}|{1}", Lang::De, {MessageArgs::Arg(slash), "y"}),
              "woyda: `/` beendet das Programm in Zeile 29|y");
    const Message list{Msg::ReadNoProgramEnd, {MessageArgs::Arg::alternatives({"63", "64"})}};
    const Message odd{Msg::DialectEvidence,
                      {"a\x18"
                       "b",
                       "c\x19"
                       "d\x1f"
                       "e",
                       Msg::EvidenceEndsProgram, 1}};
    EXPECT_EQ(essi::format_template("{0}|{1}", Lang::Zh, {MessageArgs::Arg::messages({list, odd}), "z"}),
              "控制带结束时没有程序结束;最后一个程序块应为 63 或 64;a\\x18b:第 1 行 `c\\x19d\\x1Fe` 结束程序|z");
    EXPECT_EQ(essi::format_template("[{0}]", Lang::En, {MessageArgs::Arg::messages({})}), "[]");
    EXPECT_EQ(list.text(Lang::En), "the tape ends without an end of program; expected 63 or 64 as the last block");
}

TEST(I18nMore, DiffInEachLanguage) {
    const TwoRevisions r;
    ASSERT_EQ(r.d.count(essi::ContourChange::Moved), 1u);
    const essi::ContourDiff& moved = r.d.contours[1];
    ASSERT_EQ(moved.change, essi::ContourChange::Moved);
    // English as `essi diff` has always written it (tests/cli/diff_cli.sh reads it too).
    EXPECT_EQ(essi::difference_text(r.a, r.b, moved),
              "moved: A lines 11-14 -> B lines 14-17, by (+5.000, +0.000) mm: cut 200.000 mm from (200.000, 0.000)");
    EXPECT_EQ(
        essi::difference_text(r.a, r.b, moved, Lang::De),
        "verschoben: A Zeilen 11-14 -> B Zeilen 14-17, um (+5.000, +0.000) mm: Schnitt 200.000 mm ab (200.000, 0.000)");
    EXPECT_EQ(essi::difference_text(r.a, r.b, moved, Lang::Zh),
              "移位:A 第 11-14 行 -> B 第 14-17 行,偏移 (+5.000, +0.000) mm:切割 200.000 mm,起点 (200.000, 0.000)");
    EXPECT_EQ(essi::difference_text(r.a, r.b, r.d.contours[0], Lang::De), "gleich");
    EXPECT_EQ(essi::diff_counts_text(r.d), "1 same, 1 moved, 0 changed, 0 removed, 0 added");
    EXPECT_EQ(essi::diff_counts_text(r.d, Lang::De), "1 gleich, 1 verschoben, 0 geändert, 0 entfernt, 0 hinzugefügt");
    EXPECT_EQ(essi::diff_counts_text(r.d, Lang::Zh), "相同 1,移位 1,修改 0,删除 0,新增 0");
    EXPECT_EQ(essi::diff_counts_message(r.d).text(Lang::Zh), essi::diff_counts_text(r.d, Lang::Zh));
    EXPECT_EQ(essi::diff_text(r.sa, r.sb, r.d),
              "A: a.esi (profile iso6582): 2 contours, cut 600.000 mm, 2 pierces, time 0:00:41\n"
              "B: b.esi (profile iso6582): 2 contours, cut 600.000 mm, 2 pierces, time 0:00:41\n"
              "moved: A lines 11-14 -> B lines 14-17, by (+5.000, +0.000) mm: cut 200.000 mm from (200.000, 0.000)\n"
              "contours: 1 same, 1 moved, 0 changed, 0 removed, 0 added\n"
              "statistics: travel_length_mm 200.000 -> 205.000 (+5.000), estimated_time_s 41.200 -> 41.230 (+0.030)\n");
    EXPECT_EQ(
        essi::diff_text(r.sa, r.sb, r.d, Lang::De),
        "A: a.esi (Profil iso6582): 2 Konturen, Schneiden 600.000 mm, 2 Anschnitte, Zeit 0:00:41\n"
        "B: b.esi (Profil iso6582): 2 Konturen, Schneiden 600.000 mm, 2 Anschnitte, Zeit 0:00:41\n"
        "verschoben: A Zeilen 11-14 -> B Zeilen 14-17, um (+5.000, +0.000) mm: Schnitt 200.000 mm ab (200.000, 0.000)\n"
        "Konturen: 1 gleich, 1 verschoben, 0 geändert, 0 entfernt, 0 hinzugefügt\n"
        "Statistik: Leerweglänge (mm) 200.000 -> 205.000 (+5.000), geschätzte Zeit (s) 41.200 -> 41.230 (+0.030)\n");
    const std::string zh = essi::diff_text(r.sa, r.sb, r.d, Lang::Zh);
    EXPECT_NE(zh.find("A:a.esi(配置 iso6582):轮廓 2 个,切割 600.000 mm,穿孔 2 次,时间 0:00:41\n"), std::string::npos)
        << zh;
    EXPECT_NE(zh.find("\n统计:空行程长度(mm) 200.000 -> 205.000 (+5.000)、估计时间(s) 41.200 -> 41.230 (+0.030)\n"),
              std::string::npos)
        << zh;
    // The JSON is for programs: the same keys and values whatever the language.
    EXPECT_NE(essi::diff_json(r.sa, r.sb, r.d).find("\"change\": \"moved\""), std::string::npos);
}

TEST(I18nMore, DiffOfTheSameCutAndTheOtherChanges) {
    const essi::TapeContours a = contours_of("7\n+1000+0\n8\n9\n+0+500\n10\n64\n");
    const essi::TapeContours b = contours_of("7\n+1000+0\n8\n9\n+0+600\n10\n5\n+5000+5000\n6\n7\n+100+0\n8\n64\n");
    const essi::TapeDiff d = essi::diff_contours(a.contours, b.contours);
    ASSERT_EQ(d.count(essi::ContourChange::Changed), 1u);
    ASSERT_EQ(d.count(essi::ContourChange::Added), 1u);
    for (const essi::ContourDiff& c : d.contours) {
        if (c.change == essi::ContourChange::Changed) {
            EXPECT_EQ(essi::difference_text(a, b, c),
                      "changed: A line 5 -> B line 5: mark 50.000 mm from (100.000, 0.000) -> mark 60.000 mm from "
                      "(100.000, 0.000)");
            EXPECT_EQ(essi::difference_text(a, b, c, Lang::De),
                      "geändert: A Zeile 5 -> B Zeile 5: Markierung 50.000 mm ab (100.000, 0.000) -> Markierung 60.000 "
                      "mm ab (100.000, 0.000)");
        }
        if (c.change == essi::ContourChange::Added) {
            EXPECT_EQ(essi::difference_text(a, b, c, Lang::Zh),
                      "新增:B 第 11 行:切割 10.000 mm,起点 (600.000, 560.000)");
        }
    }
    const essi::TapeDiff back = essi::diff_contours(b.contours, a.contours);
    for (const essi::ContourDiff& c : back.contours) {
        if (c.change == essi::ContourChange::Removed) {
            EXPECT_EQ(essi::difference_text(b, a, c, Lang::De),
                      "entfernt: A Zeile 11: Schnitt 10.000 mm ab (600.000, 560.000)");
        }
    }
}

TEST(I18nMore, DialectEvidenceAndN403InEachLanguage) {
    const std::string tape = "3\nPART\n4\n135+2\n136+6000\n7\n+100+0\n8\n/\n";
    const essi::TapeSetup chosen = essi::setup_tape(tape, std::nullopt, std::nullopt);
    ASSERT_EQ(chosen.evidence.size(), 3u);
    ASSERT_EQ(chosen.evidence_messages.size(), chosen.evidence.size());
    for (std::size_t i = 0; i < chosen.evidence.size(); ++i)
        EXPECT_EQ(chosen.evidence_messages[i].text(Lang::En), chosen.evidence[i]);
    EXPECT_EQ(chosen.evidence[0], "woyda: `135+2` sets the burner count at line 4");
    EXPECT_EQ(chosen.evidence_messages[0].text(Lang::De), "woyda: `135+2` setzt die Anzahl Brenner in Zeile 4");
    EXPECT_EQ(chosen.evidence_messages[2].text(Lang::Zh), "woyda:第 9 行 `/` 结束程序");
    const essi::DialectGuess eia = essi::guess_dialect("G90 G71\nG00 X1\nM03\n", essi::InputFormat::Eia);
    ASSERT_FALSE(eia.evidence_messages.empty());
    EXPECT_EQ(eia.evidence[0], "din66025: `G90` absolute dimensions (DIN 66025) at line 1");
    EXPECT_EQ(eia.evidence_messages[0].text(Lang::De), "din66025: `G90` Absolutmaße (DIN 66025) in Zeile 1");
    EXPECT_EQ(eia.evidence_messages[0].text(Lang::Zh), "din66025:第 1 行 `G90` 绝对尺寸(DIN 66025)");

    // N403: the evidence is an argument of the note, in the reader's language too.
    const essi::TapeSetup iso = essi::setup_tape(tape, std::nullopt, essi::builtin_profile("iso6582"));
    ASSERT_TRUE(iso.note.has_value());
    EXPECT_EQ(essi::diagnostic_message(*iso.note, essi::Lang::En),
              "this tape looks like woyda (woyda: `135+2` sets the burner count at line 4; woyda: `136+6000` sets the "
              "burner spacing at line 5; woyda: `/` ends the program at line 9), not iso6582; try --profile woyda or "
              "--profile auto");
    EXPECT_EQ(essi::diagnostic_message(*iso.note, Lang::De),
              "dieses Programm sieht nach woyda aus (woyda: `135+2` setzt die Anzahl Brenner in Zeile 4; woyda: "
              "`136+6000` setzt den Brennerabstand in Zeile 5; woyda: `/` beendet das Programm in Zeile 9), nicht nach "
              "iso6582; --profile woyda oder --profile auto versuchen");
    EXPECT_EQ(essi::diagnostic_message(*iso.note, Lang::Zh),
              "该控制带看起来属于 woyda(woyda:第 4 行 `135+2` 设定割炬数量;woyda:第 5 行 `136+6000` 设定割炬间距;"
              "woyda:第 9 行 `/` 结束程序),而不是 iso6582;请尝试 --profile woyda 或 --profile auto");
}

TEST(I18nMore, ProfileErrorsInEachLanguage) {
    const essi::ProfileResult r = essi::parse_profile(
        R"({"feed_mm_min": 1e300, "kerf": "x", "colour": 1, "zero_offsets": {"G55": {"x_mm": 1}}, "eia": {"strict_order": 2}})");
    ASSERT_FALSE(r.profile.has_value());
    ASSERT_EQ(r.diagnostics.size(), 5u);
    for (const essi::Diagnostic& d : r.diagnostics) {
        EXPECT_EQ(d.code, essi::DiagCode::E402_BadProfile);
        EXPECT_EQ(d.line, 1u);  // at its key
        EXPECT_NE(d.msg, Msg::None) << essi::diagnostic_message(d,
                                                                Lang::En);  // (made from the catalogue: any language)
    }
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[0], Lang::En), "\"kerf\" must be a number");
    EXPECT_EQ(r.diagnostics[0].column, 24u);
    EXPECT_EQ(r.diagnostics[1].column, 2u);
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[1], essi::Lang::En),
              "\"feed_mm_min\" must be between 1e-09 and 1000000000; found 1e+300");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[1], Lang::De),
              "\"feed_mm_min\" muss zwischen 1e-09 und 1000000000 liegen; gefunden: 1e+300");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[1], Lang::Zh),
              "\"feed_mm_min\" 必须在 1e-09 到 1000000000 之间;实际为 1e+300");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[2], essi::Lang::En),
              "\"zero_offsets\" entry \"G55\" needs a number \"y_mm\" between -1000000000 and 1000000000");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[2], Lang::De),
              "Eintrag \"G55\" von \"zero_offsets\" braucht eine Zahl \"y_mm\" zwischen -1000000000 und 1000000000");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[2], Lang::Zh),
              "\"zero_offsets\" 的条目 \"G55\" 需要 -1000000000 到 1000000000 之间的数值 \"y_mm\"");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[3], essi::Lang::En), "\"eia.strict_order\" must be true or false");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[3], Lang::Zh), "\"eia.strict_order\" 必须是 true 或 false");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[4], essi::Lang::En), "unknown key \"colour\"");
    EXPECT_EQ(essi::diagnostic_message(r.diagnostics[4], Lang::De), "unbekannter Schlüssel \"colour\"");

    const essi::ProfileResult not_json = essi::parse_profile("{");
    ASSERT_EQ(not_json.diagnostics.size(), 1u);
    EXPECT_EQ(
        essi::diagnostic_message(not_json.diagnostics[0], essi::Lang::En),
        "the text is not valid JSON at line 1, column 2 (syntax error while parsing object key - unexpected end "
        "of input; expected string literal); expected an object such as {\"base\": \"woyda\", \"feed_mm_min\": 1200}");
    EXPECT_EQ(essi::diagnostic_message(not_json.diagnostics[0], Lang::Zh),
              "文本在第 1 行第 2 列不是有效的 JSON(syntax error while parsing object key - unexpected end of input; "
              "expected string literal);应为 {\"base\": \"woyda\", \"feed_mm_min\": 1200} 这样的对象");
    // A number beyond a double: where it is, and why.
    const essi::ProfileResult huge = essi::parse_profile("{\"name\": \"x\",\n  \"unit_mm\": 1e999}");
    ASSERT_EQ(huge.diagnostics.size(), 1u);
    EXPECT_EQ(essi::diagnostic_message(huge.diagnostics[0], essi::Lang::En),
              "the text is not valid JSON at line 2, column 14 (number overflow parsing '1e999'); expected an object "
              "such as {\"base\": \"woyda\", \"feed_mm_min\": 1200}");
    const essi::ProfileResult base = essi::parse_profile(R"({"base": "nope"})");
    ASSERT_EQ(base.diagnostics.size(), 1u);
    EXPECT_EQ(
        essi::diagnostic_message(base.diagnostics[0], Lang::De),
        "unbekanntes Basisprofil \"nope\"; erwartet: eines von " + [] {
            std::string s;
            for (const std::string& n : essi::builtin_profile_names()) s += (s.empty() ? "" : ", ") + n;
            return s;
        }());
}

TEST(I18nMore, ShareLinkProblemsInEachLanguage) {
    const essi::ShareLink l = essi::parse_share_fragment("c=1,2,0&l=-4&i=gif");
    ASSERT_EQ(l.problems.size(), 3u);
    ASSERT_EQ(l.problem_messages.size(), 3u);
    for (std::size_t i = 0; i < l.problems.size(); ++i) EXPECT_EQ(l.problem_messages[i].text(Lang::En), l.problems[i]);
    EXPECT_EQ(l.problems[0], "c: expected X,Y,ZOOM: three numbers, the zoom above 0 (\"1,2,0\")");
    EXPECT_EQ(l.problem_messages[0].text(Lang::De), "c: erwartet: X,Y,ZOOM: drei Zahlen, der Zoom über 0 (\"1,2,0\")");
    EXPECT_EQ(l.problem_messages[0].text(Lang::Zh), "c:应为 X,Y,ZOOM:三个数,缩放大于 0(\"1,2,0\")");
    EXPECT_EQ(l.problems[1], "l: expected a line number (\"-4\")");
    EXPECT_EQ(l.problems[2], "i: expected essi or eia (\"gif\")");
    EXPECT_EQ(l.problem_messages[2].text(Lang::De), "i: erwartet: essi oder eia (\"gif\")");
    // As the viewer's "Share link problem" window says them: all of them, in one sentence of its own.
    const MessageArgs args{MessageArgs::Arg::messages(l.problem_messages)};
    const std::string zh = essi::format_message(Msg::UiLinkCut, Lang::Zh, args);
    EXPECT_NE(zh.find("l:应为行号(\"-4\");i:应为 essi 或 eia(\"gif\")"), std::string::npos) << zh;
    const essi::ShareLink name = essi::parse_share_fragment("n=" + std::string(300, 'a'));
    ASSERT_EQ(name.problem_messages.size(), 1u);
    EXPECT_EQ(name.problems[0].rfind("n: the name is longer than 255 bytes; cut (\"aaaa", 0), 0u) << name.problems[0];
    EXPECT_EQ(name.problem_messages[0].text(Lang::De).rfind("n: der Name ist länger als 255 Bytes; gekürzt (\"aaaa", 0),
              0u);
    const essi::ShareLink big = essi::parse_share_fragment(std::string(essi::kMaxShareFragmentBytes + 1, 'a'));
    ASSERT_EQ(big.problem_messages.size(), 1u);
    EXPECT_EQ(big.problems[0], "the link is 3000001 bytes long; at most 3000000 are read");
    EXPECT_EQ(big.problem_messages[0].text(Lang::Zh), "链接长 3000001 字节;最多读取 3000000 字节");
}
