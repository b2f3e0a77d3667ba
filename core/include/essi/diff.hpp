// Two revisions of a tape compared (`essi diff A B`, docs/cli.md): what they cut, contour by contour, not line by
// line, so that renumbered lines, a part cut in another order or moved on the plate read as what they are.
//
// A contour is one cut or one mark of one head (essi/contour.hpp, docs/semantics.md §9). Two contours have the
// same shape when their motions, relative to their start, are the same within kDiffToleranceMm (line ends, arc
// centres and directions; parabolas by their ends and lengths). Matching, in this order:
//   same      the same shape at the same place (each of A's matched once, in tape order);
//   moved     the same shape at another place (the nearest one left), with its offset, when it is no farther
//             than the contour's own size or nothing overlaps the contour;
//   changed   else another shape whose box overlaps the contour's (the nearest): an edited contour;
//   removed   A's contours left; added: B's contours left.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "essi/contour.hpp"
#include "essi/dialect.hpp"
#include "essi/geom.hpp"
#include "essi/report.hpp"

namespace essi {

// Two contours whose every point agrees within this are the same shape (mm): below any machine's step, above the
// rounding of a conversion between 0.1 mm and 0.01 mm units.
constexpr double kDiffToleranceMm = 1e-3;

// A contour as a diff compares it: where it lies, its length and shape.
struct DiffContour : Contour {
    Point start;  // where the tool came on: its first motion's start (mm, program coordinates)
    std::size_t motions = 0;
    Box box;
    double length_mm = 0;
    std::vector<double> shape;       // the motions relative to the start: x, y of each end, arc centre, sweep
    std::vector<MotionRecord> path;  // its motions, when asked for (tape_contours' keep_paths: to draw them)
};

// The contours of a tape as `setup` reads it (its check's result beside them).
struct TapeContours {
    CheckResult check;
    std::vector<DiffContour> contours;
};
[[nodiscard]] TapeContours tape_contours(std::string_view bytes, const TapeSetup& setup, bool keep_paths = false);

enum class ContourChange : std::uint8_t { Same, Moved, Changed, Removed, Added };
[[nodiscard]] const char* contour_change_name(ContourChange c);  // "same", "moved", "changed", "removed", "added"

struct ContourDiff {
    ContourChange change = ContourChange::Same;
    int a = -1, b = -1;  // the contour in A and in B (-1: none)
    Point offset;        // moved: B's start - A's start
};

struct TapeDiff {
    std::vector<ContourDiff> contours;  // A's in its order (same, moved, changed, removed), then B's added
    [[nodiscard]] std::size_t count(ContourChange c) const;
    [[nodiscard]] bool same() const { return count(ContourChange::Same) == contours.size(); }
};
[[nodiscard]] TapeDiff diff_contours(const std::vector<DiffContour>& a, const std::vector<DiffContour>& b);

// One side of a comparison: the name it is shown under and its contours.
struct DiffSide {
    std::string name;
    const TapeContours* tape = nullptr;
};

// The texts are in `lang` (core/i18n/messages/diff.def; English: what `essi diff` has always printed).
// One difference as `essi diff` says it: "moved: A lines 11-14 -> B lines 14-17, by (+5.000, +0.000) mm: cut
// 200.000 mm from (200.000, 0.000)" (no newline; of a Same only "same").
[[nodiscard]] std::string difference_text(const TapeContours& a, const TapeContours& b, const ContourDiff& d,
                                          Lang lang = Lang::En);
// The counts: "1 same, 1 moved, 0 changed, 0 removed, 0 added"; as a message, to be worded later (the viewer's
// notice of a comparison).
[[nodiscard]] std::string diff_counts_text(const TapeDiff& d, Lang lang = Lang::En);
[[nodiscard]] Message diff_counts_message(const TapeDiff& d);

// `essi diff`'s text: each side's statistics, a line a contour that is not the same (its lines in A and in B),
// the counts, and the statistics before and after; every line ends in a newline.
[[nodiscard]] std::string diff_text(const DiffSide& a, const DiffSide& b, const TapeDiff& d, Lang lang = Lang::En);
// `essi diff --format json`: {"a": {...}, "b": {...}, "summary": {...}, "contours": [...], "stats_change": {...}}
// (docs/cli.md): keys and values for programs, the same in every language.
[[nodiscard]] std::string diff_json(const DiffSide& a, const DiffSide& b, const TapeDiff& d);

}  // namespace essi
