// The cut plan's pieces shared by its files (essi/plan.hpp): a cut as its motions, its loop, and a plate's
// analysis.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "essi/contour.hpp"
#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/motion.hpp"
#include "essi/diagnostic_cap.hpp"
#include "essi/plan.hpp"
#include "essi/profile.hpp"

namespace essi::plan {

// A programmed motion of a cut, as small as the analysis needs it (parabolas arrive as lines).
struct Piece {
    Point start, end;
    Point centre;       // arcs
    double sweep = 0;   // arcs: signed, radians
    double radius = 0;  // arcs
    std::uint32_t line = 0;
    bool arc = false;
    bool continues = false;  // a parabola's chord after its first: of the same motion as the piece before
};
// Its exact box (an arc's extremes inside its sweep included) and length.
[[nodiscard]] Box arc_box(const Piece& p);
[[nodiscard]] inline Box piece_box(const Piece& p) { return p.arc ? arc_box(p) : Box::of(p.start, p.end); }
[[nodiscard]] double piece_length(const Piece& p);

// One cut: a cut contour, pierce to torch off, one head. Its pieces are the plate's pieces [first_piece, end_piece).
struct Cut : Contour {
    std::uint32_t first_piece = 0, end_piece = 0;
    std::uint32_t first_record = 0, end_record = 0;  // its motions kept as records (CutPlan::keep_plate_motions)
    int order = 0;                                   // cutting order in the plate
    KerfSide kerf = KerfSide::Off;  // the side in force on the whole cut (Off when it changes along it)
    bool kerf_changed = false;      // (while it is cut: the side changed along it)
    bool closed = false;            // it holds a loop
    double kerf_width_mm = 0;       // the full width the compensation cuts (0 when off)
    Box box;
    std::size_t points = 0;  // its pieces' points flattened (plan_points of its motions)

    // Its loop, when it holds one: pieces [loop_begin, loop_end) (plate indices), starting at `loop_start` on the
    // first of them (its start, or a point on it for a path that closes on a line rather than at a point).
    std::uint32_t loop_begin = 0, loop_end = 0;
    Point loop_start;
    Box loop_box;
    double area_mm2 = 0;  // signed, exact (arcs as arcs)
    // Left open: how far the end is from where the contour began, and that point's line.
    double gap_mm = 0;
    Point gap_from;
    std::uint32_t gap_line = 0;
};

// The chords of an arc of `radius` and `sweep` for the plan's tests: within kPlanChordToleranceMm, at most
// kPlanMaxArcChords.
[[nodiscard]] int arc_chords(double radius, double sweep);
// The points a cutting motion adds to its contour flattened for the plan's tests (a plate's budget,
// kPlanMaxPlatePoints): a line 1, an arc its chords, a parabola its pieces.
[[nodiscard]] std::size_t curve_points(const MotionRecord& m);  // (an arc or a parabola)
[[nodiscard]] inline std::size_t plan_points(const MotionRecord& m) {
    return m.curve == CurveKind::Line ? 1 : curve_points(m);
}

// Appends the pieces of a cutting motion to `out`: itself, or a parabola's chords (append_parabola).
void append_parabola(const MotionRecord& m, std::vector<Piece>& out);
inline void append_pieces(const MotionRecord& m, std::vector<Piece>& out) {
    if (m.curve == CurveKind::Parabola) [[unlikely]] {
        append_parabola(m, out);
        return;
    }
    out.push_back({m.start, m.end, m.centre, m.sweep, m.radius, m.line, m.curve == CurveKind::Arc});
}
// The motion piece `k` of the cut is part of, counted from the cut's first (0).
[[nodiscard]] std::uint32_t motion_of_piece(const Cut& cut, std::span<const Piece> pieces, std::uint32_t k);

// Finds the cut's box and its loop (or its gap): fills box, closed, loop_*, area, gap_*. `closure_mm`: ends this close
// to a point passed close the loop (the arc tolerance in mm).
void close_loop(Cut& cut, std::span<const Piece> pieces, double closure_mm, double gap_limit_mm);
// The loop flattened within kPlanChordToleranceMm, without repeating its first point.
std::vector<Point> loop_polygon(const Cut& cut, std::span<const Piece> pieces);
// Pieces [first, end) flattened, from the first one's start (an empty list when there are none).
std::vector<Point> pieces_points(std::span<const Piece> pieces, std::uint32_t first, std::uint32_t end);

// Appends the piece's points within kPlanChordToleranceMm, without its start.
void flatten_piece(const Piece& p, std::vector<Point>& out);

// The shortest distance between the segments a-b and c-d, and a point where it is reached (on a-b).
double segment_distance(Point a, Point b, Point c, Point d, Point& where);
// Whether q lies inside the cut's loop (even-odd, arcs as arcs).
bool inside_loop(const Cut& cut, std::span<const Piece> pieces, Point q);

// A plate's cuts analysed: roles by nesting and the rules that need contours (W601-W607, W610, N612).
struct PlateSettings {
    double closure_mm = 0;    // the arc tolerance in mm
    double gap_limit_mm = 0;  // closure_gap_mm
    bool lead_in_required = false;
    int plate = 1;
    std::optional<TableLimits> table;  // W611
    std::size_t max_per_code = kDefaultMaxPerCode;
};
// The plate's diagnostics go to `out` as far as `cap` (max_per_code within the plate) admits them; it counts the rest.
void analyse_plate(std::vector<Cut>& cuts, std::span<const Piece> pieces, const PlateSettings& settings,
                   std::vector<Diagnostic>& out, DiagnosticCap& cap, std::vector<PlanContour>* contours);

}  // namespace essi::plan
