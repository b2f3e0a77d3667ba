// The whole message catalogue (core/i18n/messages/*.def, essi/i18n.hpp) in its three languages: every row has a
// text in each, the same arguments in each, German and Chinese texts that are translations and not English left
// over; and the language tags and locales the viewer and the CLI read.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "essi/i18n.hpp"

namespace {

using essi::Lang;
using essi::Msg;

// The argument numbers a template uses: {N} and {N|one|other} (format_template's reading).
std::set<int> placeholders(std::string_view t) {
    std::set<int> out;
    for (std::size_t i = 0; i + 2 < t.size(); ++i) {
        if (t[i] != '{' || t[i + 1] < '0' || t[i + 1] > '9') continue;
        if (t[i + 2] == '}' || t[i + 2] == '|') out.insert(t[i + 1] - '0');
    }
    return out;
}

// A word to translate: a run of letters that is not a unit's symbol (units stay as they are in every language).
bool has_words(std::string_view t) {
    static const std::set<std::string_view> kUnits = {"mm", "min", "ms", "s", "m", "KB", "MB", "GiB"};
    const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    for (std::size_t i = 0; i < t.size();) {
        if (!letter(t[i])) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < t.size() && letter(t[j])) ++j;
        if (!kUnits.contains(t.substr(i, j - i))) return true;
        i = j;
    }
    return false;
}

// Texts with words that are the same in English and the other language on purpose: names and abbreviations every
// language writes alike (units and numbers need no entry: has_words).
const std::set<std::string_view> kSameInEveryLanguage = {"OK", "SVG", "PNG", "Ctrl+O", "Ctrl+V"};

std::string where(Msg m) { return std::string(essi::msg_name(m)); }

}  // namespace

TEST(I18nCatalogue, EveryRowHasAllThreeLanguages) {
    const auto count = static_cast<unsigned>(Msg::Count);
    ASSERT_GT(count, 1u);
    for (unsigned i = 1; i < count; ++i) {
        const auto m = static_cast<Msg>(i);
        for (const Lang lang : essi::kLanguages)
            EXPECT_FALSE(essi::text(m, lang).empty()) << where(m) << " has no " << essi::lang_code(lang) << " text";
    }
}

TEST(I18nCatalogue, TheThreeTextsTakeTheSameArguments) {
    for (unsigned i = 1; i < static_cast<unsigned>(Msg::Count); ++i) {
        const auto m = static_cast<Msg>(i);
        const std::set<int> en = placeholders(essi::text(m, Lang::En));
        EXPECT_EQ(placeholders(essi::text(m, Lang::De)), en) << where(m) << " (de): " << essi::text(m, Lang::De);
        EXPECT_EQ(placeholders(essi::text(m, Lang::Zh)), en) << where(m) << " (zh): " << essi::text(m, Lang::Zh);
    }
}

TEST(I18nCatalogue, GermanAndChineseAreTranslated) {
    for (unsigned i = 1; i < static_cast<unsigned>(Msg::Count); ++i) {
        const auto m = static_cast<Msg>(i);
        const std::string_view en = essi::text(m, Lang::En);
        if (!has_words(en) || kSameInEveryLanguage.contains(en)) continue;
        EXPECT_NE(essi::text(m, Lang::De), en) << where(m) << ": the German text is the English one";
        EXPECT_NE(essi::text(m, Lang::Zh), en) << where(m) << ": the Chinese text is the English one";
    }
}

TEST(I18nCatalogue, ThePlaceholderAndWordReadersReadTemplates) {
    EXPECT_EQ(placeholders("{0} {0|error|errors}, {1} of {2}"), (std::set<int>{0, 1, 2}));
    EXPECT_EQ(placeholders("no arguments {x} {}"), std::set<int>{});
    EXPECT_FALSE(has_words(", {0} mm/min"));
    EXPECT_FALSE(has_words("{0} ms, 12.5 KB"));
    EXPECT_TRUE(has_words("{0}x machine speed"));
    EXPECT_TRUE(has_words("kerf width {0} mm"));
}

TEST(I18nLanguage, ParseLangReadsTagsAndLocales) {
    EXPECT_EQ(essi::parse_lang("de-DE"), Lang::De);
    EXPECT_EQ(essi::parse_lang("de_AT.UTF-8"), Lang::De);
    EXPECT_EQ(essi::parse_lang("zh-CN"), Lang::Zh);
    EXPECT_EQ(essi::parse_lang("zh_TW"), Lang::Zh);
    EXPECT_EQ(essi::parse_lang("en-US"), Lang::En);
    EXPECT_EQ(essi::parse_lang("C"), Lang::En);
    EXPECT_EQ(essi::parse_lang("fr"), std::nullopt);
    EXPECT_EQ(essi::parse_lang("fr_FR.UTF-8"), std::nullopt);
    // The viewer's setting and essikit.setLanguage store the code: it reads back.
    for (const Lang lang : essi::kLanguages) EXPECT_EQ(essi::parse_lang(essi::lang_code(lang)), lang);
}

TEST(I18nLanguage, EachLanguageIsNamedInItself) {
    EXPECT_EQ(essi::lang_native_name(Lang::En), "English");
    EXPECT_EQ(essi::lang_native_name(Lang::De), "Deutsch");
    EXPECT_EQ(essi::lang_native_name(Lang::Zh), "中文");
}
