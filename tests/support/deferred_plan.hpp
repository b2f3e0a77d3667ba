// The check with the cut plan's plates kept and analysed one by one after it (TapeChecker::defer_plan, the viewer's
// way for big tapes), compared with check_tape: the same diagnostics in the same order. For the plan's unit tests
// and the examples.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "essi/plan.hpp"
#include "essi/read.hpp"
#include "essi/pipeline.hpp"

// Every motion the checker passes on, kept as records: the store the kept plates are read back from.
class RecordedMotions final : public essi::MotionSink, public essi::MotionStore {
public:
    void on_motion(const essi::MotionRecord& m) override { motions_.push_back(m); }
    void on_event(const essi::MachineEvent&) override {}
    [[nodiscard]] essi::MotionRecord motion(std::size_t index) const override { return motions_.at(index); }

private:
    std::vector<essi::MotionRecord> motions_;
};

inline void expect_deferred_plan_is_the_same(const std::string& tape, const essi::Profile& profile,
                                             essi::InputFormat format = essi::InputFormat::Essi) {
    const essi::CheckResult direct = essi::check_tape(tape, profile, format);
    RecordedMotions store;
    essi::TapeChecker checker(tape, profile, &store);
    checker.defer_plan(&store);
    essi::TapeReader reader(tape, profile, format);
    essi::Tape chunk;
    while (reader.read_chunk(chunk, 64)) checker.check_chunk(chunk);  // (small chunks: plates end mid-chunk)
    essi::CheckResult later = checker.finish_before_plan();
    const std::size_t plates = checker.plan_plates();
    EXPECT_EQ(checker.plan_plates_left(), plates);
    std::size_t analysed = 0;
    while (checker.analyse_plan_plate()) ++analysed;
    EXPECT_EQ(analysed, plates);
    EXPECT_EQ(checker.plan_plates_left(), 0u);
    for (essi::Diagnostic& d : checker.plan_findings()) later.diagnostics.push_back(std::move(d));
    essi::sort_diagnostics(later.diagnostics);
    ASSERT_EQ(later.diagnostics.size(), direct.diagnostics.size());
    for (std::size_t k = 0; k < direct.diagnostics.size(); ++k) {
        const essi::Diagnostic& a = direct.diagnostics[k];
        const essi::Diagnostic& b = later.diagnostics[k];
        SCOPED_TRACE(essi::diagnostic_message(a, essi::Lang::En));
        EXPECT_EQ(a.code, b.code);
        EXPECT_EQ(a.line, b.line);
        EXPECT_EQ(a.column, b.column);
        EXPECT_EQ(essi::diagnostic_message(a, essi::Lang::En), essi::diagnostic_message(b, essi::Lang::En));
        EXPECT_EQ(a.contour_first, b.contour_first);
        EXPECT_EQ(a.contour_last, b.contour_last);
        EXPECT_EQ(a.related().size(), b.related().size());
        EXPECT_EQ(a.overlap().size(), b.overlap().size());
    }
    EXPECT_EQ(later.stats.motions, direct.stats.motions);
}
