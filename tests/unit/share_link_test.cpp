// The share link fragment (essi/share_link.hpp): what the page's two kinds of link carry, read by the core.
#include <gtest/gtest.h>

#include <string>

#include "essi/share_link.hpp"

using namespace essi;

TEST(ShareLink, ReadsTheInlineLink) {
    const std::string packed("\x01\x02\xFF\x00\x7F", 5);
    const ShareLink l =
        parse_share_fragment("#c=12.5,-3,0.25&l=17&n=part+7%2Fa.esi&t=" + base64url_encode(packed) + "&p=woyda");
    ASSERT_TRUE(l.view.has_value());
    EXPECT_DOUBLE_EQ(l.view->x, 12.5);
    EXPECT_DOUBLE_EQ(l.view->y, -3);
    EXPECT_DOUBLE_EQ(l.view->zoom, 0.25);
    EXPECT_EQ(l.line, 17u);
    EXPECT_EQ(l.name, "part 7/a.esi");  // '+' a space, %2F a slash (as URLSearchParams)
    EXPECT_EQ(l.packed, packed);
    EXPECT_EQ(l.profile, "woyda");
    EXPECT_TRUE(l.problems.empty());
    EXPECT_TRUE(l.has_tape());
}

TEST(ShareLink, ReadsTheStoreLink) {
    const std::string id(64, 'a');
    const ShareLink l = parse_share_fragment("share=" + id + "&c=1,2,3&l=0&n=x.esi");
    EXPECT_EQ(l.store_id, id);
    EXPECT_TRUE(l.packed.empty());
    EXPECT_TRUE(l.has_tape());
    EXPECT_EQ(l.line, 0u);
}

TEST(ShareLink, EachBadFieldIsAProblemAndTheRestIsUsed) {
    const ShareLink l = parse_share_fragment("c=1,2,0&l=-4&share=ABC&t=a$b&p=a%0Ab&n=ok.esi&future=1");
    EXPECT_FALSE(l.view.has_value());  // zoom 0
    EXPECT_EQ(l.line, 0u);
    EXPECT_TRUE(l.store_id.empty());
    EXPECT_TRUE(l.packed.empty());
    EXPECT_TRUE(l.profile.empty());
    EXPECT_EQ(l.name, "ok.esi");
    ASSERT_EQ(l.problems.size(), 5u);  // c, l, share, t, p; the unknown key is ignored
    EXPECT_EQ(l.problems[0].rfind("c: expected X,Y,ZOOM", 0), 0u) << l.problems[0];
    EXPECT_NE(l.problems[3].find("base64url"), std::string::npos);
    EXPECT_FALSE(l.has_tape());
}

TEST(ShareLink, LimitsAndHostileText) {
    EXPECT_FALSE(parse_share_fragment(std::string(kMaxShareFragmentBytes + 1, 'a')).problems.empty());
    const ShareLink longname = parse_share_fragment("n=" + std::string(1000, 'x'));
    EXPECT_LE(longname.name.size(), kMaxShareNameBytes + 3);
    EXPECT_EQ(longname.problems.size(), 1u);
    // NaN, infinity and trailing text are no numbers; a quoted value is shown safely
    EXPECT_FALSE(parse_share_fragment("c=nan,1,1").view.has_value());
    EXPECT_FALSE(parse_share_fragment("c=1,inf,1").view.has_value());
    EXPECT_FALSE(parse_share_fragment("c=1,2,3x").view.has_value());
    const ShareLink ctl = parse_share_fragment("c=%01%FF");
    ASSERT_EQ(ctl.problems.size(), 1u);
    EXPECT_NE(ctl.problems[0].find("\\x01"), std::string::npos) << ctl.problems[0];
}

TEST(ShareLink, Base64UrlRoundTripsAndRefusesOtherAlphabets) {
    for (std::size_t n = 0; n < 40; ++n) {
        std::string bytes;
        for (std::size_t i = 0; i < n; ++i) bytes += static_cast<char>((i * 37 + n) & 0xFF);
        const std::string text = base64url_encode(bytes);
        EXPECT_EQ(text.find_first_of("+/="), std::string::npos);
        EXPECT_EQ(base64url_decode(text), bytes) << n;
    }
    EXPECT_EQ(base64url_encode("hello"), "aGVsbG8");
    EXPECT_FALSE(base64url_decode("aGVsbG8=").has_value());  // padding
    EXPECT_FALSE(base64url_decode("a+b/").has_value());      // standard base64's letters
    EXPECT_FALSE(base64url_decode("abcde").has_value());     // a length no bytes have
}

TEST(ShareLink, ViewQueryReadsBack) {
    const std::string q = share_view_query({1234.5, -0.125, 3.5}, 42);
    EXPECT_EQ(q, "c=1234.5,-0.125,3.5&l=42");
    const ShareLink l = parse_share_fragment(q);
    ASSERT_TRUE(l.view.has_value());
    EXPECT_DOUBLE_EQ(l.view->x, 1234.5);
    EXPECT_EQ(l.line, 42u);
}

TEST(ShareLink, CarriesHowTheTapeWasRead) {
    const std::string profile = R"({"name": "my-shop", "base": "woyda", "unit_mm": 0.01})";
    const std::string query = share_reading_query("my-shop", profile, InputFormat::Eia);
    EXPECT_EQ(query.rfind("p=my-shop&pj=", 0), 0u) << query;
    const ShareLink l = parse_share_fragment("c=1,2,3&l=0&" + query + "&n=a.eia&b=1234&t=" + base64url_encode("x"));
    EXPECT_TRUE(l.problems.empty()) << l.problems.front();
    EXPECT_EQ(l.profile, "my-shop");
    EXPECT_EQ(l.profile_json, profile);
    EXPECT_EQ(l.input, InputFormat::Eia);
    ASSERT_TRUE(l.tape_bytes.has_value());
    EXPECT_EQ(*l.tape_bytes, 1234u);
    // a built-in profile, the format from the content: p only
    EXPECT_EQ(share_reading_query("auto", "", std::nullopt), "p=auto");
    const ShareLink plain = parse_share_fragment("p=auto&t=eA");
    EXPECT_EQ(plain.profile, "auto");
    EXPECT_TRUE(plain.profile_json.empty());
    EXPECT_FALSE(plain.input.has_value());
    EXPECT_FALSE(plain.tape_bytes.has_value());
}

// A profile's name goes through the link as it is: '+' (a user profile on a built-in's base), spaces, UTF-8.
TEST(ShareLink, AProfileNameReadsBackAsWritten) {
    for (const std::string name : {"iso6582+custom", "Werk 2 – Plasma", "a&b=c%d#e"}) {
        const std::string query = share_reading_query(name, "{}", InputFormat::Essi);
        const ShareLink l = parse_share_fragment(query + "&t=eA");
        EXPECT_TRUE(l.problems.empty()) << name << ": " << l.problems.front();
        EXPECT_EQ(l.profile, name) << query;
        EXPECT_EQ(l.input, InputFormat::Essi);
    }
    EXPECT_EQ(share_reading_query("iso6582+custom", "", std::nullopt), "p=iso6582%2Bcustom");
}

TEST(ShareLink, BadReadingFieldsAreProblems) {
    const ShareLink l = parse_share_fragment(
        "i=gcode&b=-1&pj=" + base64url_encode(std::string(kMaxShareProfileBytes + 1, 'x')) + "&p=ok");
    EXPECT_FALSE(l.input.has_value());
    EXPECT_FALSE(l.tape_bytes.has_value());
    EXPECT_TRUE(l.profile_json.empty());
    EXPECT_EQ(l.profile, "ok");
    ASSERT_EQ(l.problems.size(), 3u);
    EXPECT_EQ(l.problems[0].rfind("i: expected essi or eia", 0), 0u) << l.problems[0];
    EXPECT_EQ(l.problems[1].rfind("b: expected the tape's length", 0), 0u) << l.problems[1];
    EXPECT_EQ(l.problems[2].rfind("pj: expected a profile's JSON", 0), 0u) << l.problems[2];
}

// A store id is a SHA-256 as `essi serve` names it: 64 lower-case hex digits, nothing else (the link and the server
// both ask is_store_id).
TEST(ShareLink, StoreIdIsSixtyFourLowerCaseHexDigits) {
    const std::string id = "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1";
    EXPECT_TRUE(is_store_id(id));
    EXPECT_TRUE(is_store_id(std::string(64, '0')));
    EXPECT_FALSE(is_store_id(""));
    EXPECT_FALSE(is_store_id("abc"));
    EXPECT_FALSE(is_store_id(id.substr(1)));          // 63 digits
    EXPECT_FALSE(is_store_id(id + "0"));              // 65 digits
    EXPECT_FALSE(is_store_id(std::string(64, 'A')));  // upper case
    EXPECT_FALSE(is_store_id(std::string(63, 'a') + "/"));
    EXPECT_FALSE(is_store_id(std::string(63, 'a') + "g"));
    EXPECT_EQ(parse_share_fragment("share=" + id).store_id, id);
    const ShareLink bad = parse_share_fragment("share=" + std::string(64, 'A'));
    EXPECT_TRUE(bad.store_id.empty());
    EXPECT_EQ(bad.problems.size(), 1u);
}
