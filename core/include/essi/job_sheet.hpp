// The job sheet of a tape (`essi report`, docs/cli.md): what goes on it, in what order and with its numbers
// formatted, in one language, worked out once here (make_job_sheet); written as one self-contained HTML file
// (job_sheet_html, here) and as PDF (native/pdf/: cairo and pango, in the builds that have them). Both writers draw
// the same page: A4 portrait, the drawing at the same size on paper, the same strokes and colours.
//
// Parts, plates and remnants come through one seam, SheetParts: the core's parts list fills it when there is one
// (sheet_parts). While it is empty the sheet has no Parts or Plates section and no numbers on the drawing.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/dialect.hpp"
#include "essi/geom.hpp"
#include "essi/i18n.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"
#include "essi/render_svg.hpp"
#include "essi/report.hpp"

namespace essi {

// The page, in mm: A4 portrait and its margins.
constexpr double kSheetPageWidthMm = 210, kSheetPageHeightMm = 297, kSheetMarginMm = 15;
constexpr double kSheetContentWidthMm = kSheetPageWidthMm - 2 * kSheetMarginMm;
// The drawing on paper: as wide as the page's content, at most this high (its aspect ratio kept).
constexpr double kSheetDrawingMaxHeightMm = 120;
// The drawing's margin around the motions, as a part of their extent.
constexpr double kSheetDrawingMargin = 0.03;
// Arcs and parabolas are flattened within this part of the drawing's extent, and a polyline keeps no point closer
// than that to the one before it: finer than the printer, whatever the tape's size.
constexpr double kSheetDrawingTolerance = 1.0 / 4000;
// At most this many diagnostics are listed (and marked) unless the caller says otherwise; a note counts the rest.
constexpr std::size_t kSheetDefaultMaxDiagnostics = 200;

// How a motion kind is drawn on paper (mm): its colour (essi/render_svg.hpp's, as every colour of the sheet's
// drawing: kSvgPierceColor, sheet_mark_color), width and dashes (0: solid).
struct SheetStroke {
    std::string_view color;
    double width_mm = 0;
    double dash_mm = 0;
};
[[nodiscard]] SheetStroke sheet_stroke(MotionKind kind);
// The kinds in the order they are drawn: rapid and travel under marking under cutting.
inline constexpr std::array<MotionKind, 4> kSheetDrawOrder{MotionKind::Rapid, MotionKind::Travel, MotionKind::Mark,
                                                           MotionKind::Cut};
// Sizes on paper (mm): a pierce's circle, a diagnostic's mark (its radius), a part number's text height.
constexpr double kSheetPierceRadiusMm = 0.6, kSheetMarkRadiusMm = 1.4, kSheetLabelHeightMm = 2.8;
[[nodiscard]] std::string_view sheet_mark_color(Severity s);

// The drawing: the tape's motions as polylines in program mm, and where they go on paper.
struct SheetDrawing {
    Box box;                             // the program's area shown (the motions' extent and a margin)
    double width_mm = 0, height_mm = 0;  // its size on paper
    std::array<std::vector<std::vector<Point>>, 4> paths;  // by MotionKind: polylines
    std::vector<Point> pierces;
    struct Mark {
        Point at;
        Severity severity = Severity::Error;
    };
    std::vector<Mark> marks;  // the listed diagnostics that have a place (essi/diagnostic_marks.hpp)
    struct Label {
        Point at;
        std::string text;
    };
    std::vector<Label> labels;  // the parts' group numbers
    // A point of the program on paper: mm from the drawing's top left corner, y down.
    [[nodiscard]] Point to_paper(Point p) const;
};

// A line of the legend under the drawing: a sample of how it is drawn, and its name.
struct SheetLegendEntry {
    enum class Sample : std::uint8_t { Stroke, Pierce, Mark, Label };
    Sample sample = Sample::Stroke;
    std::string text;
    MotionKind kind = MotionKind::Cut;    // Stroke
    Severity severity = Severity::Error;  // Mark
};

// A section of the sheet: a heading and fields (label: value), or a table, or the drawing; a note under it.
struct SheetField {
    std::string label, value;
};
struct SheetTable {
    std::vector<std::string> columns;
    std::vector<bool> numeric;  // by column: right-aligned
    std::vector<std::vector<std::string>> rows;
    std::vector<std::optional<Severity>> row_severity;  // one a row: a diagnostic's (its first cell in its colour)
};
struct SheetSection {
    std::string id;  // job, drawing, statistics, time, parts, plates, profile, diagnostics (the HTML's ids)
    std::string title;
    std::vector<SheetField> fields;
    std::optional<SheetTable> table;
    bool drawing = false;
    std::string note;
};

struct JobSheet {
    Lang lang = Lang::En;
    std::string title;   // "Job sheet: NAME"
    std::string tape;    // the tape's name
    std::string sha256;  // of the tape's bytes, 64 hex digits
    std::string date;    // "2026-11-27 14:05 UTC"
    std::int64_t created_unix = 0;
    std::string footer;         // on every page: the tape, the start of its digest, the date
    std::string page_template;  // "page {0} of {1}" in the sheet's language
    std::vector<SheetSection> sections;
    SheetDrawing drawing;
    std::vector<SheetLegendEntry> legend;
};

// The parts seam. A group is a set of equal parts, numbered from 1; each part on the drawing shows its group's
// number at `label_at`; a plate's remnant is the rectangle left over beyond its parts.
struct SheetPartGroup {
    unsigned number = 0;
    unsigned count = 0;
    double width_mm = 0, height_mm = 0, area_mm2 = 0;
};
struct SheetPart {
    unsigned group = 0;
    Point label_at;
};
struct SheetPlate {
    unsigned number = 0;
    double width_mm = 0, height_mm = 0;
    double utilisation = 0;  // the parts' area / the plate's, 0..1
    std::optional<Box> remnant;
};
struct SheetParts {
    std::vector<SheetPartGroup> groups;
    std::vector<SheetPart> parts;
    std::vector<SheetPlate> plates;
    [[nodiscard]] bool empty() const { return groups.empty() && plates.empty(); }
};
// The parts of a checked tape, from the core's parts list: none while the core has no parts list.
[[nodiscard]] SheetParts sheet_parts(const CheckResult& result);

// What the sheet says about where it comes from.
struct JobSheetInput {
    std::string tape_name;          // as the user named it (made safe to print here)
    std::string sha256;             // of the tape's bytes
    std::int64_t created_unix = 0;  // the sheet's date (seconds since 1970, UTC)
    Lang lang = Lang::En;
    std::size_t max_diagnostics = kSheetDefaultMaxDiagnostics;
};

// "2026-11-27 14:05 UTC".
[[nodiscard]] std::string sheet_date_text(std::int64_t unix_seconds);

// The drawing of a tape: the check's diagnostics placed on it. Reads the tape once more (the motion stream).
[[nodiscard]] SheetDrawing draw_sheet(std::string_view bytes, const TapeSetup& setup,
                                      const std::vector<Diagnostic>& marked, const Stats& stats);

// The sheet of a checked tape: its sections in order (job, drawing, statistics, time and cost, parts, plates,
// profile, diagnostics), every text in `in.lang`.
[[nodiscard]] JobSheet make_job_sheet(const CheckResult& result, const Profile& profile, SheetDrawing drawing,
                                      const SheetParts& parts, const JobSheetInput& in);

// Checks the tape as `setup` says and makes its sheet: what `essi report` writes.
struct JobSheetResult {
    JobSheet sheet;
    CheckResult result;
};
[[nodiscard]] JobSheetResult job_sheet(std::string_view bytes, const TapeSetup& setup, const JobSheetInput& in);
// The sheet of a tape already checked as `setup` says (`result`, its diagnostics all there: at most
// in.max_diagnostics of them are listed): what the viewer prints.
[[nodiscard]] JobSheet job_sheet_of(std::string_view bytes, const TapeSetup& setup, CheckResult result,
                                    const JobSheetInput& in);

// The sheet as one self-contained HTML file: CSS and the drawing (SVG) inline, A4 when printed. Well-formed XML
// too (every element closed, text escaped).
[[nodiscard]] std::string job_sheet_html(const JobSheet& sheet);
// The style sheet of that HTML, its one <style> element's text: a page that shows the sheet under a Content
// Security Policy allows exactly this (the viewer's, native/serve_security.cpp). The sheet has no other inline style.
[[nodiscard]] const std::string& job_sheet_css();

}  // namespace essi
