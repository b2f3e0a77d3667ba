// A part's shape (essi/parts.hpp) as the parts list compares and measures it: its loops as pieces (lines, arcs,
// parabolas) made canonical, and the rule that tells two shapes equal under a turn and a move (docs/semantics.md
// §9, "Parts and plates").
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "essi/geom.hpp"
#include "essi/motion.hpp"

namespace essi::parts {

// A piece of a loop: a line a-b; an arc a-b about `centre` (radius, signed sweep); a parabola a-b as a quadratic
// Bézier with control point `control`. `mid`: its point halfway (a line's too).
struct Seg {
    CurveKind curve = CurveKind::Line;
    Point a, b, mid;
    Point centre;   // arcs
    Point control;  // parabolas
    double radius = 0, sweep = 0;
    double length = 0;
};

// A closed loop, counter-clockwise, its pieces merged where one goes on as the other (collinear lines, arcs of
// one circle): the same outline cut from another start or in another direction gives the same pieces.
struct Loop {
    std::vector<Seg> segs;
    double area = 0;  // > 0 (exact: arcs and parabolas as curves)
    Point centroid;
    bool circle = false;  // one full circle: no point of it stands out
};

// A loop from its motions in order (the first starting, the last ending where the loop closes); `tolerance`: the
// same-shape tolerance, within which pieces that go on as one are merged.
[[nodiscard]] Loop make_loop(std::span<const MotionRecord> motions, double tolerance);

// A part: its outline (loops[0]) and holes, with what is compared first (the signature).
struct Shape {
    std::vector<Loop> loops;
    double area = 0;  // net: the outline's less the holes'
    Point centroid;   // of the net area
    double perimeter = 0;
    std::size_t pieces = 0;
    std::vector<double> lengths;         // of its pieces, sorted
    std::vector<double> hole_areas;      // sorted
    std::vector<double> hole_distances;  // of the holes' centroids from the part's, sorted
    std::vector<std::size_t> by_x;       // its loops by their centroid's x
};
[[nodiscard]] Shape make_shape(std::vector<Loop> loops);
// The shape mirrored in the x axis (a port part's starboard twin).
[[nodiscard]] Shape mirrored(const Shape& s);

// Whether the signatures of two shapes allow them to be equal within `tolerance`.
[[nodiscard]] bool similar(const Shape& a, const Shape& b, double tolerance);
// How far `a` is turned (radians, counter-clockwise) from `b` when it can be turned and moved onto it within
// `tolerance` (every piece's ends and middle, every loop); nullopt when it cannot.
[[nodiscard]] std::optional<double> turn_onto(const Shape& a, const Shape& b, double tolerance);

// The smallest rectangle enclosing the loop, in any direction: its length and width (length >= width).
struct OutlineRect {
    double length = 0, width = 0;
};
[[nodiscard]] OutlineRect smallest_rectangle(const Loop& outline);

// The loop as a polygon: its pieces' points within `tolerance` (mm), each arc or parabola in at most `max_chords`.
void flatten_loop(const Loop& loop, double tolerance, int max_chords, std::vector<Point>& out);
// The exact box of a piece.
[[nodiscard]] Box seg_box(const Seg& s);
// A point of the shape's material (inside its outline, outside its holes), for its label: `polygons`, its loops
// flattened (flatten_loop within kPlanChordToleranceMm, in at most kPlanMaxArcChords chords each).
[[nodiscard]] Point label_point(const Shape& s, const Box& box, std::span<const std::vector<Point>> polygons);

}  // namespace essi::parts
