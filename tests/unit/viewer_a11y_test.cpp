// The viewer's keyboard and screen-reader pieces that are portable code (web/app): the key queue that loses no key
// between frames (KeyQueue.cpp) and the page's title and text for screen readers (PageMirror.cpp), in English, German
// and Chinese, with the problems list capped.
#include <gtest/gtest.h>

#include <string>

#include "app/KeyQueue.hpp"
#include "app/Language.hpp"
#include "app/PageMirror.hpp"
#include "viewer_util.hpp"

using namespace essi;
using essi::viewer::KeyEvent;
using essi::viewer::KeyQueue;
using essi::viewer::PageMirror;
using essi::viewer::Selection;

namespace {

constexpr int kPress = 1, kRelease = 0, kRepeat = 2;
constexpr int kHome = 268, kEnd = 269, kRight = 262, kShift = 340, kTab = 258;  // (GLFW's key codes)

// An arc whose end is off its circle at line 12 (E301), as examples/bad_arc_off_circle.esi.
const std::string kBadArc = "3\n4\n39+500\n+500+500\n7\n+1000+0\n+500+500+0+550+\n+0+1000\n-1500+0\n+0-1500\n8\n63\n";
const std::string kClean = "3\n4\n7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n63\n";

// Sets the viewer's language for one test and puts English back.
struct InLanguage {
    explicit InLanguage(Lang lang) { viewer::set_ui_lang(lang); }
    ~InLanguage() { viewer::set_ui_lang(Lang::En); }
};

// A tape with `n` findings: `n` blocks with a character the reader refuses (E101 each).
std::string tape_with_findings(std::size_t n) {
    std::string t = "3\n4\n";
    for (std::size_t i = 0; i < n; ++i) t += "+10+0Q\n";
    return t + "63\n";
}

}  // namespace

// A widget's format in the UI's language: the argument's place takes the printf spec, a '%' of the text is doubled.
TEST(ViewerLanguage, AFormatHasTheSpecWhereTheArgumentGoes) {
    EXPECT_EQ(viewer::tr_format(Msg::UiSliderMotion, "%d"), "motion %d");
    EXPECT_EQ(viewer::tr_format(Msg::UiSliderSpeed, "%.0f"), "%.0fx machine speed");
    const InLanguage de(Lang::De);
    EXPECT_EQ(viewer::tr_format(Msg::UiSliderMotion, "%d"), "Bewegung %d");
    EXPECT_EQ(viewer::tr_format(Msg::UiSliderSpeed, "%.0f"), "%.0f-fache Maschinengeschwindigkeit");
}

TEST(ViewerKeyQueue, ATapWithinOneFrameIsDownForAFrameThenUp) {
    KeyQueue q;
    q.push({kHome, 0, kPress, 0});
    q.push({kHome, 0, kRelease, 0});
    std::vector<KeyEvent> frame = q.take_frame();
    ASSERT_EQ(frame.size(), 1u);
    EXPECT_EQ(frame[0].key, kHome);
    EXPECT_EQ(frame[0].action, kPress);
    frame = q.take_frame();
    ASSERT_EQ(frame.size(), 1u);
    EXPECT_EQ(frame[0].action, kRelease);
    EXPECT_TRUE(q.take_frame().empty());
}

TEST(ViewerKeyQueue, SeveralKeysInOneFrameAreAllApplied) {
    // Home, End and Right tapped within one frame: each is down in a frame of its own order, none is lost.
    KeyQueue q;
    for (const int key : {kHome, kEnd, kRight, kRight}) {
        q.push({key, 0, kPress, 0});
        q.push({key, 0, kRelease, 0});
    }
    std::vector<std::vector<KeyEvent>> frames;
    while (q.queued() > 0) frames.push_back(q.take_frame());
    // frame 1: Home down; 2: Home up, End down; 3: End up, Right down; 4: Right up; 5: Right down; 6: Right up
    ASSERT_EQ(frames.size(), 6u);
    int presses[4] = {};
    std::size_t n = 0;
    for (const auto& f : frames) {
        for (const KeyEvent& e : f) {
            ++n;
            if (e.action == kPress) ++presses[e.key == kHome ? 0 : e.key == kEnd ? 1 : 2];
        }
        for (std::size_t i = 0; i < f.size(); ++i)
            for (std::size_t j = i + 1; j < f.size(); ++j)
                EXPECT_NE(f[i].key, f[j].key) << "a key changed twice in a frame";
    }
    EXPECT_EQ(n, 8u);
    EXPECT_EQ(presses[0], 1);
    EXPECT_EQ(presses[1], 1);
    EXPECT_EQ(presses[2], 2);
    EXPECT_EQ(frames[0].size(), 1u);
    EXPECT_EQ(frames[1].size(), 2u);
}

TEST(ViewerKeyQueue, AModifierAndItsKeyArriveInTheSameFrame) {
    KeyQueue q;
    q.push({kShift, 0, kPress, 0});
    q.push({kTab, 0, kPress, 1});
    q.push({kTab, 0, kRelease, 1});
    q.push({kShift, 0, kRelease, 0});
    const std::vector<KeyEvent> first = q.take_frame();
    ASSERT_EQ(first.size(), 2u);
    EXPECT_EQ(first[0].key, kShift);
    EXPECT_EQ(first[1].key, kTab);
    EXPECT_EQ(first[1].mods, 1);
    EXPECT_EQ(q.take_frame().size(), 2u);
}

TEST(ViewerKeyQueue, AKeyHeldDownRepeatsAFrameAtATimeAndTheQueueIsBounded) {
    KeyQueue q;
    q.push({kRight, 0, kPress, 0});
    for (int i = 0; i < 1000; ++i) q.push({kRight, 0, kRepeat, 0});
    EXPECT_EQ(q.queued(), KeyQueue::kMaxQueued);
    EXPECT_EQ(q.take_frame().size(), 1u);
    EXPECT_EQ(q.queued(), KeyQueue::kMaxQueued - 1);
}

TEST(ViewerPageMirror, TheStartScreenNamesTheViewer) {
    const PageMirror m = viewer::page_mirror(nullptr, Selection{}, nullptr);
    EXPECT_EQ(m.lang, "en");
    EXPECT_EQ(m.title, "essikit viewer");
    EXPECT_EQ(
        m.status,
        "essikit viewer: ESSI cutting tapes (ISO 6582) Drop a tape here, press Open..., or paste its text (Ctrl+V).");
    EXPECT_TRUE(m.problems.empty());
    EXPECT_EQ(m.problems_heading, "Diagnostics");
    EXPECT_FALSE(m.label.empty());
    const std::string name = "big.esi";
    EXPECT_EQ(viewer::page_mirror(nullptr, Selection{}, &name).status, "Loading big.esi...");
}

TEST(ViewerPageMirror, TitleAndLiveRegionNameTheTapeAndItsVerdict) {
    const auto doc = essi_test::load_document(kBadArc);
    ASSERT_EQ(doc->diagnostics.size(), 1u);
    const Diagnostic& d = doc->diagnostics[0];
    ASSERT_EQ(code_name(d.code), "E301");
    ASSERT_EQ(d.line, 7u);
    const std::string problem = "E301 line 7:" + std::to_string(d.column) + ": " + diagnostic_message(d, Lang::En);
    PageMirror m = viewer::page_mirror(doc.get(), Selection{}, nullptr);
    EXPECT_EQ(m.title, "tape — 1 error, 0 warnings — essikit viewer");
    EXPECT_EQ(m.status, "tape: 1 error, 0 warnings.");
    ASSERT_EQ(m.problems.size(), 1u);
    EXPECT_EQ(m.problems[0], problem);
    EXPECT_EQ(m.more, "");
    // The selected line's problem follows the verdict.
    Selection s;
    s.line = 7;
    m = viewer::page_mirror(doc.get(), s, nullptr);
    EXPECT_EQ(m.status, "tape: 1 error, 0 warnings. Selected: " + problem);
    // A line without a problem: its motion in words, as the inspector says it.
    s.line = 6;
    for (std::size_t i = 0; i < doc->motions.size() && s.motion == Selection::npos; ++i)
        if (doc->motions[i].line == 6) s.motion = i;
    ASSERT_NE(s.motion, Selection::npos);
    m = viewer::page_mirror(doc.get(), s, nullptr);
    EXPECT_EQ(m.status.rfind("tape: 1 error, 0 warnings. Selected: line 6: ", 0), 0u) << m.status;
    EXPECT_NE(m.status.find(" mm"), std::string::npos) << m.status;

    const auto clean = essi_test::load_document(kClean);
    m = viewer::page_mirror(clean.get(), Selection{}, nullptr);
    EXPECT_EQ(m.title, "tape — ok — essikit viewer");
    EXPECT_EQ(m.status, "tape: ok.");
    ASSERT_EQ(m.problems.size(), 1u);
    EXPECT_EQ(m.problems[0], "No problems found.");
}

TEST(ViewerPageMirror, GermanAndChineseTexts) {
    const auto doc = essi_test::load_document(kBadArc);
    {
        const InLanguage de(Lang::De);
        const PageMirror m = viewer::page_mirror(doc.get(), Selection{}, nullptr);
        EXPECT_EQ(m.lang, "de");
        EXPECT_EQ(m.title, "tape — 1 Fehler, 0 Warnungen — essikit-Viewer");
        EXPECT_EQ(m.status, "tape: 1 Fehler, 0 Warnungen.");
        EXPECT_EQ(m.problems_heading, "Meldungen");
        EXPECT_EQ(m.problems[0].rfind("E301 Zeile 7:", 0), 0u) << m.problems[0];
        EXPECT_NE(m.problems[0].find(diagnostic_message(doc->diagnostics[0], Lang::De)), std::string::npos);
    }
    const InLanguage zh(Lang::Zh);
    const PageMirror m = viewer::page_mirror(doc.get(), Selection{}, nullptr);
    EXPECT_EQ(m.lang, "zh");
    EXPECT_EQ(m.title, "tape — 1 个错误，0 个警告 — essikit 查看器");
    EXPECT_EQ(m.status, "tape：1 个错误，0 个警告。");
    EXPECT_EQ(m.problems_heading, "诊断");
}

TEST(ViewerPageMirror, TheProblemsListIsCappedAndSaysHowManyMore) {
    const std::size_t extra = 37;
    const auto doc = essi_test::load_document(tape_with_findings(viewer::kMirrorProblems + extra));
    ASSERT_GT(doc->diagnostics.size(), viewer::kMirrorProblems);
    const PageMirror m = viewer::page_mirror(doc.get(), Selection{}, nullptr);
    ASSERT_EQ(m.problems.size(), viewer::kMirrorProblems);
    const std::size_t more = doc->diagnostics.size() - viewer::kMirrorProblems;
    EXPECT_EQ(m.more, "and " + std::to_string(more) +
                          " more (all of them in the Diagnostics list and in Export... > Problems as CSV)");
}

TEST(ViewerPageMirror, TheKeeperMakesItAgainOnlyWhenWhatItShowsChanges) {
    const auto doc = essi_test::load_document(kBadArc);
    viewer::PageMirrorKeeper keeper;
    bool changed = false;
    Selection s;
    keeper.update(doc.get(), 1, s, nullptr, &changed);
    EXPECT_TRUE(changed);
    keeper.update(doc.get(), 1, s, nullptr, &changed);
    EXPECT_FALSE(changed) << "the same frame again";
    s.line = 7;
    EXPECT_NE(keeper.update(doc.get(), 1, s, nullptr, &changed).status.find("Selected"), std::string::npos);
    EXPECT_TRUE(changed);
    s.line = 0;
    keeper.update(doc.get(), 2, s, nullptr, &changed);  // (the same tape loaded again: the same text)
    EXPECT_TRUE(changed);
    keeper.update(doc.get(), 3, s, nullptr, &changed);
    EXPECT_FALSE(changed) << "nothing it shows changed";
    {
        const InLanguage de(Lang::De);
        EXPECT_EQ(keeper.update(doc.get(), 3, s, nullptr, &changed).lang, "de");
        EXPECT_TRUE(changed);
    }
}
