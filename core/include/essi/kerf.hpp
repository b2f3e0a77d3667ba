// Phase 3, geom: the kerf-compensated path (docs/semantics.md §8), the torch's path as a CNC tool-radius offset.
//
// KerfPath reads the programmed motion stream (every motion, in order) and writes the compensated one: motions
// without compensation unchanged, the others offset by their `kerf_mm` to their `kerf` side. The rules are
// LinuxCNC's G41/G42 (rs274ngc), so that its `rs274` can check them:
//   - a line is shifted along its left or right normal; an arc keeps its centre and its radius grows or shrinks;
//     a parabola is offset point by point within the chord tolerance (as lines);
//   - at a convex corner the offset pieces are joined by an arc of the offset radius around the programmed
//     corner (before a rapid: a straight line to where that arc ends); at a concave corner they are trimmed at
//     the intersection of their programmed motions' offsets that LinuxCNC takes; a corner that turns less than
//     kKerfCornerTolerance is neither: the next piece starts where the last one ended;
//   - a corner within kKerfCornerTolerance of a full reversal is trimmed when the torch is outside the next
//     piece's arc, or the next piece is a line and the torch is outside the arc before; else it is joined,
//     whichever way it turns (two lines turning back 178° towards the kerf side: a 182° join round the tip);
//   - a gouge (KerfGouge, E307 in the check) where LinuxCNC refuses the program: a concave corner whose pieces
//     do not meet or whose piece before would run backwards to the intersection, and a piece trimmed at its start
//     that runs backwards to its end, found at its next concave corner, at a convex corner before a line, or
//     where the compensation ends;
//   - entry: the first motion with compensation runs from where the torch is to the compensated end of its own
//     piece (a line: its end shifted along the normal of the entry's own direction; an arc: to its end moved
//     along the radius, about a centre on the same radius line that is equally far from both ends, which a trim
//     keeps; the corner after it turns from the programmed arc's direction); an entry is never a gouge;
//   - exit: the last compensated piece ends at its end shifted along its normal; the first motion without
//     compensation runs from there to its programmed end.
// Pieces carry the programmed motion's line, block, kind, tools, feed and kerf; a join arc carries those of
// the motion after the corner. A compensated piece is final only once the next one is known (one piece of
// look-ahead): events that come while a piece is open are passed on after it.
#pragma once

#include "essi/i18n.hpp"

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "essi/motion.hpp"

namespace essi {

// Corners whose direction changes by less than this (radians) are neither joined nor trimmed (LinuxCNC's
// TOLERANCE_CONCAVE_CORNER).
constexpr double kKerfCornerTolerance = 0.05;
// A trimmed arc may sweep this much more than programmed (radians) before it is a gouge (LinuxCNC's, in mm).
constexpr double kKerfArcSweepSlack = 0.0254;
// Lengths below this (mm) are zero for the compensated path (a trimmed piece may end where it starts).
constexpr double kKerfLengthEpsilon = 1e-9;

// A corner the torch cannot get into: the motion (line, block) whose piece the corner would make run backwards.
struct KerfGouge {
    std::uint32_t line = 0, block = 0;
    Msg msg = Msg::None;  // why, with its arguments (the E307 diagnostic's message)
    MessageArgs args;
};

class KerfPath {
public:
    // `out` gets the compensated stream. `chord_tolerance_mm` bounds the offset of parabolas (as lines).
    KerfPath(MotionSink& out, double chord_tolerance_mm);

    void motion(const MotionRecord& programmed);
    void event(const MachineEvent& e);
    // The end of the program: the open piece ends as it stands.
    void finish();

    // Whether a compensated piece is open (the next motion decides its end): while not, a motion without
    // compensation passes unchanged.
    [[nodiscard]] bool open() const { return open_; }
    // The block of the open piece (while open()): what the next motion's pieces come after.
    [[nodiscard]] std::uint32_t open_block() const { return pieces_[open_index_].rec.block; }
    [[nodiscard]] bool has_gouges() const { return !gouges_.empty(); }
    // The gouges found so far, in the order found; taking them empties the list.
    [[nodiscard]] std::vector<KerfGouge> take_gouges();

private:
    // A compensated piece and what the corners need of it: the programmed end point (the corner) and the
    // programmed directions of travel at both ends.
    struct Piece {
        MotionRecord rec;
        Point corner;
        Point tangent_end;
        Point tangent_start;       // the programmed direction of travel at the start
        double sweep = 0;          // an arc's programmed sweep (radians, unsigned)
        Point start_radius;        // an arc's programmed start less its centre
        bool chord = false;        // one of a parabola's chords
        bool start_moved = false;  // its start is not its offset start (trimmed, or where the piece before ended)
    };
    void enter(const MotionRecord& m);
    void leave(const MotionRecord& m);
    void follow(const MotionRecord& m);
    void turn_corner(Piece& next, const MotionRecord& m);
    bool trim_concave(Piece& next, const MotionRecord& m);
    [[nodiscard]] bool torch_outside(const MotionRecord& r) const;
    bool open_may_end_at(Point x);
    void check_open_end(const MotionRecord& m);
    void emit_open();
    void emit(const MotionRecord& rec);
    void gouge(const MotionRecord& m, Msg why, MessageArgs args);
    // The compensated pieces of a programmed motion, before corners: one for a line or an arc (returned), the
    // chords of the offset curve for a parabola (the first returned, the rest in chords_).
    void offset_piece(const MotionRecord& m, Piece& p);
    void take_chords(Piece& first);
    [[nodiscard]] double offset_mm() const { return side_ * radius_; }

    MotionSink& out_;
    double chord_tolerance_mm_;
    bool open_ = false;
    // The open piece and the next one, in turn (no copies of pieces per motion).
    Piece pieces_[2];
    int open_index_ = 0;
    Piece& open_piece() { return pieces_[open_index_]; }
    Piece& next_piece() { return pieces_[1 - open_index_]; }
    // The open piece is an entry (it starts at the torch): a concave corner after it may trim it anywhere.
    bool open_is_entry_ = false;
    std::vector<Piece> chords_;  // a parabola's chords after the first
    double side_ = 1;            // +1: left of the direction of travel, -1: right
    double radius_ = 0;          // the offset (mm)
    Point torch_;                // where the last piece passed on ended
    bool torch_known_ = false;
    std::vector<std::variant<MotionRecord, MachineEvent>> held_;  // behind the open piece
    std::vector<KerfGouge> gouges_;
};

// A MotionSink that passes the compensated stream of what it gets to `out` (for `essi trace --kerf` and the
// tests): call finish() after the last motion.
class KerfSink final : public MotionSink {
public:
    KerfSink(MotionSink& out, double chord_tolerance_mm) : path_(out, chord_tolerance_mm) {}
    void on_motion(const MotionRecord& m) override { path_.motion(m); }
    void on_event(const MachineEvent& e) override { path_.event(e); }
    void finish() { path_.finish(); }
    [[nodiscard]] std::vector<KerfGouge> take_gouges() { return path_.take_gouges(); }

private:
    KerfPath path_;
};

}  // namespace essi
