// Where a diagnostic is drawn: its mark's place on the drawing, the lines it concerns (its block, its contour, the
// related places) and a collision's overlapping area. One rule for every drawing: `essi render`'s SVG
// (render_svg.cpp) and the viewer's marks (web/app) both ask here.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/motion.hpp"

namespace essi {

// What the motion stream says about one source line: the end of its first motion (when the line has one) and the
// end of the last motion before the line (where the machine is when the line's block runs).
struct LineEnds {
    std::optional<Point> first_motion_end;
    std::optional<Point> end_before;
};

// The mark's place (program mm, as the motions): `d.at` when the diagnostic has one; else the end of the first
// motion of its line; else (a block that is no motion: a function) where the machine is at that block, the end of
// the last motion before it. None for line 0 (no position) or a line before any motion.
[[nodiscard]] std::optional<Point> diagnostic_place(const Diagnostic& d, const LineEnds& ends);

// The places of a list of diagnostics, from the motion stream as it goes by (the SVG's one pass): motion(line, end)
// for every motion in order, then places(). The stream's lines never go back (the interpreter's order).
class DiagnosticPlaces {
public:
    explicit DiagnosticPlaces(const std::vector<Diagnostic>& diagnostics);
    void motion(std::uint32_t line, Point end);
    // One per diagnostic, in the list's order.
    [[nodiscard]] std::vector<std::optional<Point>> places() const;

private:
    const std::vector<Diagnostic>& diagnostics_;
    std::vector<std::uint32_t> lines_;  // the lines asked for, sorted, once each
    std::vector<LineEnds> ends_;        // by lines_
    std::size_t next_ = 0;              // the first line of lines_ the stream has not passed
    std::optional<Point> last_end_;
};

// A range of source lines [first, last].
struct LineRange {
    std::uint32_t first = 0, last = 0;
    friend bool operator==(const LineRange&, const LineRange&) = default;
};
// The lines a diagnostic concerns on the drawing: its own line, and its contour (contour_first..contour_last) when
// it has one. Empty for line 0 without a contour.
[[nodiscard]] std::vector<LineRange> concerned_lines(const Diagnostic& d);
// The lines of its related places (RelatedLocation line..end_line).
[[nodiscard]] std::vector<LineRange> related_lines(const Diagnostic& d);
// Ranges sorted and merged (overlapping or adjacent ranges become one).
[[nodiscard]] std::vector<LineRange> merge_ranges(std::vector<LineRange> ranges);

// The overlapping area of `polygons` (the area inside every one of them: Diagnostic::overlap) along the horizontal
// line y: the x intervals [a, b], sorted. A polygon is closed (its last point joins its first); inside by the
// even-odd rule. None for no polygon. (The viewer fills the area row by row from these.)
[[nodiscard]] std::vector<std::pair<double, double>> overlap_spans(const std::vector<std::vector<Point>>& polygons,
                                                                   double y);

}  // namespace essi
