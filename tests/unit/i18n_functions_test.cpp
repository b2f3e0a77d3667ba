// The machine function table in English, German and Chinese (essi/functions.hpp, core/i18n/messages/functions.def):
// every function of every dialect has its words in all three languages, describe_function and the kerf texts
// speak German and Chinese, and their English stays what it was.
#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <string_view>

#include "essi/function_codes.hpp"
#include "essi/functions.hpp"
#include "essi/i18n.hpp"
#include "essi/profile.hpp"

namespace {

using essi::Dialect;
using essi::Lang;
using essi::Msg;

constexpr Dialect kDialects[] = {Dialect::Iso6582, Dialect::Woyda, Dialect::Hypertherm};

bool has_letters(std::string_view s) {
    for (char c : s)
        if (std::isalpha(static_cast<unsigned char>(c))) return true;
    return false;
}

// `translated` is the text of `english` in another language: not empty, and not the English left as it is
// (a text without letters, "+X -Y", may well be the same).
void expect_translated(std::string_view english, std::string_view translated, const std::string& where) {
    EXPECT_FALSE(translated.empty()) << where;
    if (has_letters(english)) {
        EXPECT_NE(translated, english) << where;
    }
}

TEST(I18nFunctions, EveryFunctionOfEveryDialectHasItsWordsInEveryLanguage) {
    int named = 0;
    for (Dialect d : kDialects) {
        for (int code = 0; code < essi::fn::kCodeCount; ++code) {
            const auto info = essi::function_info(code, d);
            ASSERT_TRUE(info) << code;
            if (info->name.empty()) continue;
            ++named;
            const std::string where =
                "dialect " + std::to_string(static_cast<int>(d)) + " code " + std::to_string(code);
            // The English the callers read is the catalogue's English.
            EXPECT_EQ(info->name, essi::text(info->name_msg, Lang::En)) << where;
            EXPECT_EQ(info->explanation, essi::text(info->explanation_msg, Lang::En)) << where;
            EXPECT_EQ(info->value_unit, essi::text(info->unit_msg, Lang::En)) << where;
            EXPECT_FALSE(info->explanation.empty()) << where;
            for (Lang lang : {Lang::De, Lang::Zh}) {
                const std::string in = where + " in " + std::string(essi::lang_code(lang));
                expect_translated(info->name, essi::text(info->name_msg, lang), in + " (name)");
                expect_translated(info->explanation, essi::text(info->explanation_msg, lang), in + " (explanation)");
                if (info->unit_msg != Msg::None) {
                    EXPECT_FALSE(essi::text(info->unit_msg, lang).empty()) << in;
                }
            }
        }
    }
    EXPECT_EQ(named, 3 * essi::fn::kCodeCount);  // every code has a name, if only "Unknown"
}

TEST(I18nFunctions, TheTableNamesItsCatalogueRows) {
    const auto iso7 = essi::function_info(7, Dialect::Iso6582);
    EXPECT_EQ(essi::msg_name(iso7->name_msg), "FnIso7Name");
    EXPECT_EQ(essi::msg_name(iso7->explanation_msg), "FnIso7Text");
    EXPECT_EQ(iso7->unit_msg, Msg::None);
    const auto kerf = essi::function_info(29, Dialect::Hypertherm);
    EXPECT_EQ(essi::msg_name(kerf->name_msg), "FnHypertherm29Name");
    EXPECT_EQ(kerf->unit_msg, Msg::FnUnitIncrements);
    EXPECT_EQ(kerf->value_unit, "unit increments");
    // Woyda reads ISO's rows where it has none of its own.
    EXPECT_EQ(essi::msg_name(essi::function_info(7, Dialect::Woyda)->name_msg), "FnIso7Name");
    EXPECT_EQ(essi::msg_name(essi::function_info(136, Dialect::Woyda)->name_msg), "FnWoyda136Name");
    EXPECT_EQ(essi::function_info(57, Dialect::Iso6582)->name_msg, Msg::FnManufacturerName);
    EXPECT_EQ(essi::function_info(71, Dialect::Iso6582)->name_msg, Msg::FnDrawingMachineName);
    EXPECT_EQ(essi::function_info(37, Dialect::Iso6582)->name_msg, Msg::FnUnassignedName);
    EXPECT_EQ(essi::function_info(37, Dialect::Hypertherm)->explanation_msg, Msg::FnUnknownNotInTableText);
    EXPECT_EQ(essi::function_info(500, Dialect::Woyda)->explanation_msg, Msg::FnUnknownBeyondIsoText);
}

// Every row of functions.def (the Fn* ids) has all three texts, and a German or Chinese template uses only
// arguments its English one has.
TEST(I18nFunctions, EveryFunctionRowIsCompleteAndItsTemplatesMatch) {
    const auto arguments = [](std::string_view t) {
        std::string digits;
        for (std::size_t i = 0; i + 1 < t.size(); ++i)
            if (t[i] == '{' && std::isdigit(static_cast<unsigned char>(t[i + 1])) &&
                digits.find(t[i + 1]) == std::string::npos)
                digits += t[i + 1];
        return digits;
    };
    int rows = 0;
    for (std::size_t i = 1; i < static_cast<std::size_t>(Msg::Count); ++i) {
        const Msg id = static_cast<Msg>(i);
        const std::string_view name = essi::msg_name(id);
        if (name.substr(0, 2) != "Fn") continue;
        ++rows;
        const std::string en_args = arguments(essi::text(id, Lang::En));
        for (Lang lang : essi::kLanguages) {
            const std::string_view t = essi::text(id, lang);
            EXPECT_FALSE(t.empty()) << name;
            for (char a : arguments(t)) EXPECT_NE(en_args.find(a), std::string::npos) << name << " {" << a << "}";
        }
    }
    EXPECT_GT(rows, 2 * 128);  // a name and an explanation for each of the table's rows, and more
}

TEST(I18nFunctions, DescribeFunctionInGerman) {
    const essi::Profile iso;  // iso6582: 0.1 mm a unit, a kerf width of 2 mm
    EXPECT_EQ(essi::describe_function(7, false, 0, iso, Lang::De),
              "Funktion 7: Schneidsauerstoff EIN: Schneidsauerstoff am Mittelbrenner (Werkzeug 1) ein: das Schneiden "
              "beginnt");
    EXPECT_EQ(essi::describe_function(29, false, 0, iso, Lang::De),
              "Funktion 29: Schnittfugenkompensation links EIN, laut Profil Schnittfugenbreite 2 mm (Brenner 1 mm "
              "seitlich versetzt): Schnittfugenkompensation links der Fahrtrichtung");
    EXPECT_EQ(essi::describe_function(30, true, 30, iso, Lang::De),
              "Funktion 30: Schnittfugenkompensation rechts EIN, Schnittfugenbreite 3 mm (Brenner 1.5 mm seitlich "
              "versetzt): Schnittfugenkompensation rechts der Fahrtrichtung");
    EXPECT_EQ(essi::describe_function(39, true, 1400, iso, Lang::De),
              "Funktion 39: Programmierter Vorschub, 1400 mm/min: setzt den Schneidvorschub");
    EXPECT_EQ(essi::describe_function(41, true, 2, iso, Lang::De),
              "Funktion 41: Verweilzeit, 2 s: wartet, damit die Ecken dicker Bleche sauber werden");
    EXPECT_EQ(essi::describe_function(37, false, 0, iso, Lang::De),
              "Funktion 37: Nicht belegt (wird ignoriert): in ISO 6582 nicht belegt; eine Steuerung ignoriert sie");
    EXPECT_EQ(essi::describe_function(1000, false, 0, iso, Lang::De), "Funktion 1000: keine Maschinenfunktion");
    const essi::Profile woyda = *essi::builtin_profile("woyda");
    EXPECT_EQ(essi::describe_function(136, true, 1000, woyda, Lang::De),
              "Funktion 136: Brennerabstand, 100 mm: Abstand der aktiven Brennerwagen (Woyda)");
    EXPECT_EQ(essi::describe_function(135, true, 3, woyda, Lang::De),
              "Funktion 135: Anzahl Brenner, Wert 3: Anzahl der zu verwendenden Brenner; muss unmittelbar vor der 136 "
              "stehen (Woyda)");
}

TEST(I18nFunctions, DescribeFunctionInChinese) {
    const essi::Profile iso;
    EXPECT_EQ(essi::describe_function(7, false, 0, iso, Lang::Zh),
              "功能 7:切割氧开:中心割炬(工具 1)切割氧开启:开始切割");
    EXPECT_EQ(essi::describe_function(29, false, 0, iso, Lang::Zh),
              "功能 29:左割缝补偿开,配置的割缝宽度 2 mm(割炬向一侧偏移 1 mm):沿运动方向左侧的割缝补偿");
    EXPECT_EQ(essi::describe_function(30, true, 30, iso, Lang::Zh),
              "功能 30:右割缝补偿开,割缝宽度 3 mm(割炬向一侧偏移 1.5 mm):沿运动方向右侧的割缝补偿");
    EXPECT_EQ(essi::describe_function(39, true, 1400, iso, Lang::Zh),
              "功能 39:编程进给速度,1400 mm/min:设定切割进给速度");
    EXPECT_EQ(essi::describe_function(37, false, 0, iso, Lang::Zh),
              "功能 37:未分配(已忽略):GB/T 22217 未分配此功能,控制器将其忽略");
    EXPECT_EQ(essi::describe_function(1000, false, 0, iso, Lang::Zh), "功能 1000:不是机器功能");
    const essi::Profile hypertherm = *essi::builtin_profile("hypertherm");
    EXPECT_EQ(essi::describe_function(5, false, 0, hypertherm, Lang::Zh),
              "功能 5:启用快速移动:以快速移动速度运动,直至 6(Hypertherm:G00,装载时选定)");
}

TEST(I18nFunctions, KerfTextsInGermanAndChinese) {
    essi::Profile p;
    p.kerf_value = essi::KerfValueMeaning::Width;
    EXPECT_EQ(essi::kerf_value_text(2, p, Lang::De), "Schnittfugenbreite 2 mm (Brenner 1 mm seitlich versetzt)");
    EXPECT_EQ(essi::kerf_value_text(2, p, Lang::Zh), "割缝宽度 2 mm(割炬向一侧偏移 1 mm)");
    p.kerf_value = essi::KerfValueMeaning::Offset;
    EXPECT_EQ(essi::kerf_value_text(1.5, p, Lang::De), "Brennerversatz 1.5 mm (Schnittfuge 3 mm breit)");
    EXPECT_EQ(essi::kerf_value_text(1.5, p, Lang::Zh), "割缝偏移量 1.5 mm(割缝宽 3 mm)");
    EXPECT_EQ(essi::kerf_offset_text(essi::KerfSide::Left, 1.5, Lang::De),
              "Brenner 1.500 mm nach links versetzt (Schnittfuge 3.000 mm breit)");
    EXPECT_EQ(essi::kerf_offset_text(essi::KerfSide::Right, 1.5, Lang::Zh), "割炬向右偏移 1.500 mm(割缝宽 3.000 mm)");
}

// The English is what it was before the catalogue (the golden traces and the expected JSON rely on it).
TEST(I18nFunctions, EnglishUnchanged) {
    const essi::Profile iso;
    EXPECT_EQ(essi::describe_function(7, false, 0, iso),
              "function 7: Oxygen ON: cutting oxygen on at the centre torch (tool 1): cutting starts");
    EXPECT_EQ(essi::describe_function(29, false, 0, iso, Lang::En),
              "function 29: Left kerf compensation ON, the profile's kerf width 2 mm (the torch 1 mm to the side): "
              "kerf compensation left of the direction of travel");
    EXPECT_EQ(essi::describe_function(39, true, 1400, iso),
              "function 39: Programmed feed, 1400 mm/min: sets the cutting feed");
    EXPECT_EQ(essi::describe_function(37, true, 25, iso),
              "function 37: Unassigned (ignored), value 25: not assigned by ISO 6582; a controller ignores it");
    EXPECT_EQ(essi::describe_function(1000, false, 0, iso), "function 1000: not a machine function");
    const essi::Profile hypertherm = *essi::builtin_profile("hypertherm");
    EXPECT_EQ(essi::describe_function(41, true, 25, hypertherm),
              "function 41: Dwell, 0.025 s: waits: 41 alone the control's preset dwell, 41+v v milliseconds (the "
              "profile's dwell_unit_s; Hypertherm G04)");
    EXPECT_EQ(essi::describe_function(40, true, 25, hypertherm),
              "function 40: Programmable kerf, kerf width 2.5 mm (the torch 1.25 mm to the side): the kerf 29 and 30 "
              "use from here on, when they have no value of their own (Hypertherm G43 X)");
    EXPECT_EQ(essi::describe_function(136, true, 25, hypertherm),
              "function 136: Unknown (ignored), 2.5 mm: not in this dialect's code table: its control refuses it");
    essi::Profile p;
    p.kerf_value = essi::KerfValueMeaning::Offset;
    EXPECT_EQ(essi::kerf_value_text(1.235, p), "kerf offset 1.235 mm (a cut 2.47 mm wide)");
    EXPECT_EQ(essi::kerf_offset_text(essi::KerfSide::Right, 0.5), "torch 0.500 mm to the right (a cut 1.000 mm wide)");
    EXPECT_EQ(essi::kerf_offset_text(essi::KerfSide::Off, 0), "torch not offset (kerf compensation off)");
}

}  // namespace
