#include "app/DocumentSink.hpp"

#include <limits>

namespace essi::viewer {

void DocumentSink::on_motion(const MotionRecord& r) {
    Document& d = doc_;
    Motion m = start_motion(r.line, r.kind, r.curve, r.tools, r.head, r.kerf, r.start, r.end, r.kerf_mm, r.feed_mm_min);
    // Compact when every point is whole units (always, but for positions beyond 32 bits), not a parabola, and
    // its kerf is what the flags say.
    UnitPoint start, centre;
    // (a cut by several torches keeps its record: the drawing makes its copies from it)
    const bool eligible = r.curve != CurveKind::Parabola && r.torches == 1 && kerf_in_flags(r.kerf, r.kerf_mm);
    const bool end_in_units = eligible && d.to_units(r.end, m.end_units);
    // A motion that starts where a compact one ended (no jump: there is one before) has that one's end units as
    // its start.
    const bool continues = (m.flags & Motion::kFlagJump) == 0 && (d.motions.back().flags & Motion::kFlagKept) == 0;
    bool compact = end_in_units;
    if (compact && continues) start = d.motions.back().end_units;
    else if (compact) compact = d.to_units(r.start, start);
    if (compact && r.curve == CurveKind::Arc) compact = d.to_units(r.centre, centre);
    if (!compact) {
        m.flags |= Motion::kFlagKept;
        d.kept.emplace_back(static_cast<std::uint32_t>(d.motions.size()), r);
    } else if (r.curve == CurveKind::Arc) {
        if (r.ccw) m.flags |= Motion::kFlagCcw;
        d.arc_centres.push_back(centre);
    }
    d.arc_rank.push_back(compact && r.curve == CurveKind::Arc);
    if (r.curve != CurveKind::Line) ++d.curves;
    add(m);
}

void DocumentSink::on_line(const UnitLine& l) {
    constexpr long long kMax = std::numeric_limits<std::int32_t>::max();
    const auto fits = [](long long v) { return v >= -kMax && v <= kMax; };
    if (!kerf_in_flags(l.kerf, l.kerf_mm) || !fits(l.start_x) || !fits(l.start_y) || !fits(l.end_x) || !fits(l.end_y)) {
        on_motion(record_of(l));
        return;
    }
    Motion m =
        start_motion(l.line, l.kind, CurveKind::Line, l.tools, 1, l.kerf, l.start, l.end, l.kerf_mm, l.feed_mm_min);
    m.end_units = {static_cast<std::int32_t>(l.end_x), static_cast<std::int32_t>(l.end_y)};
    doc_.arc_rank.push_back(false);
    add(m);
}

Motion DocumentSink::start_motion(std::uint32_t line, MotionKind kind, CurveKind curve, std::uint8_t tools, int head,
                                  KerfSide kerf_side, Point start, Point end, double kerf_mm, double feed_mm_min) {
    Document& d = doc_;
    const auto index = static_cast<std::uint32_t>(d.motions.size());
    Motion m;
    m.line = line;
    m.kind = kind;
    m.curve = curve;
    m.tools = tools;
    if (head == 2) m.flags |= Motion::kFlagHead2;
    if (kerf_side == KerfSide::Left) m.flags |= Motion::kFlagKerfLeft;
    if (kerf_side == KerfSide::Right) m.flags |= Motion::kFlagKerfRight;
    if (index == 0 || !(last_end_ == start)) {
        m.flags |= Motion::kFlagJump;
        d.jumps.emplace_back(index, start);
    }
    last_end_ = end;
    // Kerf compensation goes on and off with every contour: its value is listed only where it is on.
    const float kerf = static_cast<float>(kerf_mm);
    if (kerf_side != KerfSide::Off && (d.kerfs.empty() ? kerf != 0.f : d.kerfs.back().second != kerf))
        d.kerfs.emplace_back(index, kerf);
    // Rapids alternate with cuts: their feed (the rapid speed) is a flag, and only the others' changes are listed.
    const float feed = static_cast<float>(feed_mm_min);
    if (feed == rapid_feed_) m.flags |= Motion::kFlagRapidFeed;
    else if (d.feeds.empty() ? feed != 0.f : d.feeds.back().second != feed) d.feeds.emplace_back(index, feed);
    return m;
}

void DocumentSink::add(const Motion& m) {
    Document& d = doc_;
    if (pierces_.at_motion(m.tools)) d.pierces.push_back(static_cast<std::uint32_t>(d.motions.size()));
    d.motions.push_back(m);
}

}  // namespace essi::viewer
