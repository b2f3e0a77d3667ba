// Contours (essi/contour.hpp): the rule of ContourBuilder on streams made here (where a contour begins and ends,
// both heads, the stream indices), a contour's motions read back from a store, and the one model seen from both
// callers: `essi diff`'s contours and the cut plan's are the same contours of the same tape.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "essi/contour.hpp"
#include "essi/diff.hpp"
#include "essi/interp.hpp"
#include "essi/plan.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "../bench/nest_generator.hpp"
#include "deferred_plan.hpp"
#include "paths.hpp"

using namespace essi;

namespace {

// A stream fed to a builder (of the contours `kTools` make): every contour as it began (its identity then) and
// as it ended, and every motion kept.
template <std::uint8_t kTools = kCuttingTools | kMarkingTools>
class Stream {
public:
    // Where a contour goes when it ends.
    auto ended_into() {
        return [this](Contour& c) { ended.push_back(c); };
    }
    Stream& motion(MotionKind kind, std::uint32_t line, Point from, Point to, std::uint8_t head = 1) {
        MotionRecord m;
        m.kind = kind;
        m.line = line;
        m.start = from;
        m.end = to;
        m.head = head;
        motions_.push_back(m);
        builder_.motion(
            m, [&](Contour& c) { began.push_back(c); }, ended_into());
        return *this;
    }
    Stream& tools(std::uint8_t after) {
        builder_.event(after, ended_into());
        return *this;
    }
    Stream& end() {
        builder_.end(ended_into());
        return *this;
    }
    [[nodiscard]] const ContourBuilder<Contour, kTools>& builder() const { return builder_; }
    [[nodiscard]] const std::vector<MotionRecord>& motions() const { return motions_; }

    std::vector<Contour> began, ended;

private:
    ContourBuilder<Contour, kTools> builder_;
    std::vector<MotionRecord> motions_;
};

class VectorStore final : public MotionStore {
public:
    explicit VectorStore(const std::vector<MotionRecord>& m) : motions_(m) {}
    [[nodiscard]] MotionRecord motion(std::size_t index) const override { return motions_.at(index); }

private:
    const std::vector<MotionRecord>& motions_;
};

constexpr std::uint8_t kOxygen = kToolOxygen, kPunch = kToolPunch;

// Cuts and marks, as `essi diff` finds them: lines 3-4 a cut, 5-7 a mark, 11 a cut, 14 another.
template <std::uint8_t kTools>
void cuts_and_marks(Stream<kTools>& s) {
    s.motion(MotionKind::Travel, 1, {0, 0}, {10, 0}).tools(kOxygen);
    s.motion(MotionKind::Cut, 3, {10, 0}, {20, 0}).motion(MotionKind::Cut, 4, {20, 0}, {20, 10});
    s.motion(MotionKind::Mark, 5, {20, 10}, {30, 10});  // a motion of another kind ends the cut, begins a mark
    s.tools(kPunch).motion(MotionKind::Mark, 7, {30, 10}, {40, 10});
    s.tools(0).motion(MotionKind::Travel, 9, {40, 10}, {50, 10});  // the marker off ends the mark
    s.tools(kOxygen | kPunch).motion(MotionKind::Cut, 11, {50, 10}, {60, 10});
    s.tools(kPunch).tools(kOxygen | kPunch);  // the torch off and on again, the marker on: a new cut
    s.motion(MotionKind::Cut, 14, {60, 10}, {70, 10}).end();
}

}  // namespace

TEST(ContourRule, ARunOfOneKindOfToolOfOneHead) {
    Stream<> s;
    cuts_and_marks(s);
    ASSERT_EQ(s.ended.size(), 4u);
    const Contour& cut = s.ended[0];
    EXPECT_EQ(cut.kind, MotionKind::Cut);
    EXPECT_EQ(cut.head, 1);
    EXPECT_EQ(cut.first_line, 3u);
    EXPECT_EQ(cut.last_line, 4u);
    EXPECT_EQ(cut.first_motion, 1u);
    EXPECT_EQ(cut.end_motion, 3u);
    const Contour& mark = s.ended[1];
    EXPECT_EQ(mark.kind, MotionKind::Mark);
    EXPECT_EQ(mark.first_line, 5u);
    EXPECT_EQ(mark.last_line, 7u);
    EXPECT_EQ(mark.first_motion, 3u);
    EXPECT_EQ(mark.end_motion, 5u);
    EXPECT_EQ(s.ended[2].first_line, 11u);
    EXPECT_EQ(s.ended[2].last_line, 11u);
    EXPECT_EQ(s.ended[2].first_motion, 6u);
    EXPECT_EQ(s.ended[3].first_line, 14u);
    EXPECT_EQ(s.ended[3].first_motion, 7u);
    EXPECT_EQ(s.ended[3].end_motion, 8u);
    // Each began with its first motion, before the motion was in it.
    ASSERT_EQ(s.began.size(), 4u);
    EXPECT_EQ(s.began[1].kind, MotionKind::Mark);
    EXPECT_EQ(s.began[1].first_line, 5u);
    EXPECT_EQ(s.began[1].first_motion, 3u);
    EXPECT_EQ(s.began[1].end_motion, 0u);
    EXPECT_EQ(s.builder().open(1), nullptr);
}

TEST(ContourRule, TheCutsOnlyAreTheSameCuts) {
    // The cut plan's builder makes no marks: a mark motion is one of another kind, which ends a cut.
    Stream<kCuttingTools> s;
    cuts_and_marks(s);
    ASSERT_EQ(s.ended.size(), 3u);
    for (const Contour& c : s.ended) EXPECT_EQ(c.kind, MotionKind::Cut);
    EXPECT_EQ(s.ended[0].first_line, 3u);
    EXPECT_EQ(s.ended[0].last_line, 4u);
    EXPECT_EQ(s.ended[0].end_motion, 3u);
    EXPECT_EQ(s.ended[1].first_motion, 6u);
    EXPECT_EQ(s.ended[2].first_motion, 7u);
}

TEST(ContourRule, EachHeadItsOwnContours) {
    Stream<> s;
    s.tools(kOxygen);
    s.motion(MotionKind::Cut, 1, {0, 0}, {10, 0});
    s.motion(MotionKind::Cut, 2, {0, 200}, {10, 200}, 2);
    s.motion(MotionKind::Cut, 3, {10, 0}, {10, 10});
    ASSERT_NE(s.builder().open(1), nullptr);
    ASSERT_NE(s.builder().open(2), nullptr);
    EXPECT_EQ(s.builder().open(2)->first_line, 2u);
    s.motion(MotionKind::Travel, 4, {10, 200}, {20, 200}, 2);  // ends head 2's contour, not head 1's
    ASSERT_EQ(s.ended.size(), 1u);
    EXPECT_EQ(s.ended[0].head, 2);
    EXPECT_EQ(s.ended[0].first_motion, 1u);
    EXPECT_EQ(s.ended[0].end_motion, 2u);
    EXPECT_EQ(s.builder().open(2), nullptr);
    s.motion(MotionKind::Cut, 5, {10, 10}, {0, 10}).tools(0);
    ASSERT_EQ(s.ended.size(), 2u);
    const Contour& head1 = s.ended[1];
    EXPECT_EQ(head1.head, 1);
    EXPECT_EQ(head1.first_line, 1u);
    EXPECT_EQ(head1.last_line, 5u);
    EXPECT_EQ(head1.first_motion, 0u);
    EXPECT_EQ(head1.end_motion, 5u);
    // Its motions read back from the stream: head 2's between them are not its.
    const VectorStore store(s.motions());
    const std::vector<MotionRecord> own = contour_motions(head1, store);
    ASSERT_EQ(own.size(), 3u);
    EXPECT_EQ(own[0].line, 1u);
    EXPECT_EQ(own[1].line, 3u);
    EXPECT_EQ(own[2].line, 5u);
    const std::vector<MotionRecord> other = contour_motions(s.ended[0], store);
    ASSERT_EQ(other.size(), 1u);
    EXPECT_EQ(other[0].line, 2u);
}

TEST(ContourRule, TheEndOfTheStreamEndsEveryContourHeadOneFirst) {
    Stream<> s;
    s.tools(kOxygen).motion(MotionKind::Cut, 1, {0, 0}, {10, 0}, 2).motion(MotionKind::Cut, 2, {0, 0}, {10, 0});
    EXPECT_TRUE(s.ended.empty());
    s.end();
    ASSERT_EQ(s.ended.size(), 2u);
    EXPECT_EQ(s.ended[0].head, 1);
    EXPECT_EQ(s.ended[1].head, 2);
}

namespace {

// The cut plan's contours of a tape, with the stream they were found in kept as a store.
struct PlanOfTape {
    std::vector<PlanContour> contours;
    RecordedMotions stream;
};
class PlanAndStream final : public MotionSink {
public:
    PlanAndStream(CutPlan& plan, RecordedMotions& stream) : plan_(plan), stream_(stream) {}
    void on_motion(const MotionRecord& m) override {
        plan_.on_motion(m);
        stream_.on_motion(m);
    }
    void on_event(const MachineEvent& e) override { plan_.on_event(e); }

private:
    CutPlan& plan_;
    RecordedMotions& stream_;
};
void plan_of_tape(const std::string& bytes, const Profile& profile, PlanOfTape& out) {
    CutPlan plan(profile, /*keep_contours*/ true);
    PlanAndStream both(plan, out.stream);
    std::vector<Diagnostic> ignored;
    interpret(read_tape(bytes, profile), bytes, profile, both, ignored);
    (void)plan.finish();
    out.contours = plan.contours();
}

}  // namespace

TEST(ContourModel, ThePlansLoopIsReachableAsMotionsParabolasWhole) {
    // examples/parabola.esi: a lead-in (line 11), then a loop of a parabola, two lines and a parabola back to the
    // lead-in's end (lines 12-15); then a parabola and a line back to their start (lines 19-20).
    const std::string bytes = read_file(examples_dir() + "/parabola.esi");
    const Profile profile = *builtin_profile("iso6582");
    PlanOfTape p;
    plan_of_tape(bytes, profile, p);
    ASSERT_EQ(p.contours.size(), 2u);
    const PlanContour& bracket = p.contours[0];
    EXPECT_EQ(bracket.kind, MotionKind::Cut);
    EXPECT_EQ(bracket.first_line, 11u);
    EXPECT_EQ(bracket.last_line, 15u);
    EXPECT_EQ(bracket.first_motion, 1u);  // (motion 0: the travel of line 9)
    EXPECT_EQ(bracket.end_motion, 6u);
    EXPECT_TRUE(bracket.lead_in);
    EXPECT_EQ(bracket.loop_begin, 1u);
    EXPECT_EQ(bracket.loop_end, 5u);
    EXPECT_NEAR(bracket.loop_start.x, 50, 1e-9);
    EXPECT_NEAR(bracket.loop_start.y, 30, 1e-9);
    const std::vector<MotionRecord> motions = contour_motions(bracket, p.stream);
    ASSERT_EQ(motions.size(), 5u);
    EXPECT_EQ(motions[0].start, (Point{50, 10}));
    EXPECT_EQ(motions[bracket.loop_begin].line, bracket.loop_first_line);
    EXPECT_EQ(motions[bracket.loop_end - 1].line, bracket.loop_last_line);
    EXPECT_EQ(motions[1].curve, CurveKind::Parabola);  // whole, not the chords the plan's tests use
    EXPECT_EQ(motions[4].curve, CurveKind::Parabola);
    EXPECT_EQ(motions[4].end, bracket.loop_start);
    const PlanContour& second = p.contours[1];
    EXPECT_FALSE(second.lead_in);
    EXPECT_EQ(second.loop_begin, 0u);
    EXPECT_EQ(second.loop_end, 2u);
    const std::vector<MotionRecord> second_motions = contour_motions(second, p.stream);
    ASSERT_EQ(second_motions.size(), 2u);
    EXPECT_EQ(second_motions[0].curve, CurveKind::Parabola);
}

TEST(ContourModel, DiffAndPlanFindTheSameContours) {
    const std::string nest = bench::generate_nest_tape(200000, 3);  // (several plates)
    for (const char* name :
         {"kerf_parts.esi", "three_axis.esi", "marking.esi", "parabola.esi", "plate_holes.esi", "nest"}) {
        SCOPED_TRACE(name);
        const std::string bytes = std::string(name) == "nest" ? nest : read_file(examples_dir() + "/" + name);
        TapeSetup setup;
        setup.profile = *builtin_profile("iso6582");
        const TapeContours diff = tape_contours(bytes, setup);
        const std::vector<PlanContour> plan = plan_contours(bytes, setup.profile);
        ASSERT_FALSE(plan.empty());
        std::size_t marks = 0;
        for (const DiffContour& d : diff.contours) marks += d.kind == MotionKind::Mark ? 1 : 0;
        EXPECT_EQ(marks > 0, std::string(name) == "marking.esi");
        for (const PlanContour& c : plan) {  // (the plan's are the cuts with a loop)
            const DiffContour* same = nullptr;
            for (const DiffContour& d : diff.contours)
                if (d.first_motion == c.first_motion && d.head == c.head) same = &d;
            ASSERT_NE(same, nullptr) << "the cut of lines " << c.first_line << "-" << c.last_line;
            EXPECT_EQ(same->kind, MotionKind::Cut);
            EXPECT_EQ(same->first_line, c.first_line);
            EXPECT_EQ(same->last_line, c.last_line);
            EXPECT_EQ(same->end_motion, c.end_motion);
        }
    }
}
