// The document's copy of the motion stream (Document.hpp's compact form): the `also` sink of the TapeChecker that
// DocumentLoader runs, so the statistics and diagnostics stay the checker's own. A motion whose points are whole
// units within 32 bits is kept in 16 bytes (an arc's centre beside it); any other keeps its full record.
#pragma once

#include <cstdint>

#include "app/Document.hpp"
#include "essi/stats.hpp"

namespace essi::viewer {

class DocumentSink final : public MotionSink {
public:
    explicit DocumentSink(Document& doc) : doc_(doc) {}

    void on_motion(const MotionRecord& r) override;
    // Most motions: their units as the interpreter has them (no division and rounding back from mm). With no
    // setup offset, mm = units x unit_mm exactly, so these are the units Document::to_units gives for the mm.
    void on_line(const UnitLine& l) override;
    void on_event(const MachineEvent& e) override { pierces_.on_tools(e.tools_after); }

private:
    // The compact form has no kerf value where compensation is off: a motion whose kerf is not 0 there (which the
    // interpreter never makes) keeps its record.
    static bool kerf_in_flags(KerfSide side, double kerf_mm) {
        return side != KerfSide::Off || static_cast<float>(kerf_mm) == 0.f;
    }
    // What every motion records: its kind, flags, whether it starts where the one before ended, the kerf and
    // feed when they change.
    Motion start_motion(std::uint32_t line, MotionKind kind, CurveKind curve, std::uint8_t tools, int head,
                        KerfSide kerf_side, Point start, Point end, double kerf_mm, double feed_mm_min);
    void add(const Motion& m);

    Document& doc_;
    const float rapid_feed_ = static_cast<float>(doc_.profile.rapid_mm_min);
    Point last_end_;         // of the motion before (a motion that starts elsewhere is a jump)
    PierceTracker pierces_;  // the statistics' pierces, each at its motion
};

}  // namespace essi::viewer
