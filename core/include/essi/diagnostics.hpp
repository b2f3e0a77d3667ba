// Diagnostics: every problem essikit finds is a value with a severity, a stable code, a position and a
// sentence that says what was found and what was expected. The list of codes lives in one place
// (diagnostics.cpp) and is documented in docs/diagnostics.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "essi/i18n.hpp"
#include "essi/motion.hpp"
#include "essi/wire.hpp"

namespace essi {

enum class Severity : std::uint8_t { Note, Warning, Error };

// Stable diagnostic codes. The number never changes once released; the letter says the default
// severity (E error, W warning, N note). 1xx: reading, 2xx: interpreting, 3xx: geometry, 4xx: machine/profile,
// 5xx: conversion, 6xx: the cut plan.
enum class DiagCode : std::uint16_t {
    // --- read ---
    E101_InvalidCharacter = 101,     // a byte that is not + - 0-9 (or a block end) outside a 3/4 section
    E102_NonAsciiByte = 102,         // a byte >= 0x80 (UTF-8 BOM, GB 18030 text) outside a 3/4 section
    E103_FunctionCodeTooLong = 103,  // a machine function of more than 3 digits (ISO 3.4.1)
    E104_NumberTooLarge = 104,       // a word whose value does not fit in 9 digits
    E105_WordCount = 105,            // signed words only, but not 2, 5 or 6 of them
    E106_FunctionWordCount = 106,    // a leading number followed by 3, 4 or more than 6 signed words
    E107_UnclosedIgnore = 107,       // a 3 (ignore ON) with no 4 (ignore OFF) after it
    E108_WhitespaceStrict = 108,     // space or tab inside a block, whitespace policy "strict"
    W109_WhitespaceSkipped = 109,    // space or tab inside a block, skipped (default policy)
    W110_ContentAfterEnd = 110,      // blocks after the end of the program: not executed
    W111_StrayIgnoreOff = 111,       // a 4 (ignore OFF) with no 3 before it
    W112_MisplacedPercent = 112,     // % in the middle of the program
    E113_EmptyTape = 113,            // no block at all
    W114_NoProgramEnd = 114,         // the tape ends without an end code (63, 64, / by default)
    E115_TooManyErrors = 115,        // reading stopped after too many errors (binary file?)
    E116_MisplacedMark = 116,        // % or / with other characters in the same block
    E117_TapeTooLarge = 117,         // more than 4 GiB: positions would not fit
    E118_FunctionValueSign = 118,    // a machine function's value after a '-' (41-50): the value follows a '+'
    // EIA (RS-274) tapes (core/read/eia_reader.cpp)
    E119_EiaUnknownLetter = 119,        // a letter or character the dialect's EIA blocks do not have
    E120_EiaLetterOrder = 120,          // letters out of the dialect's order (N G X Y I J F M), or one letter twice
    E121_EiaFunctionsInBlock = 121,     // more than one of G, M and F in a block where the dialect allows one (Woyda)
    E122_EiaBadNumber = 122,            // a letter without a number, or a malformed or too large number
    E123_EiaArcWithoutDirection = 123,  // I/J while neither G02 nor G03 is in force
    W124_EiaUnknownCode = 124,          // a G or M word the dialect's EIA table does not have: ignored
    W125_EiaRounded = 125,              // coordinates finer than the profile's unit, rounded to it
    E126_EiaUnclosedComment = 126,      // '(' without ')' on its line

    // --- interp ---
    W201_UnknownFunction = 201,              // unassigned or unknown machine function
    W202_FunctionValueIgnored = 202,         // a value given to a function that takes none
    E203_FunctionValueMissing = 203,         // a function that needs a value (135, 136) has none
    W204_KerfWhileCutting = 204,             // 29/30/38 while a cutting tool is on
    W205_AddressOutside3Axis = 205,          // head address without 19 (3-axis mode)
    E206_BadHeadAddress = 206,               // head address other than 1 or 2
    E207_ZeroOffsetBlock = 207,              // 83 not followed by a two-word block
    W208_ManufacturerFunction = 208,         // 55-62 in the ISO dialect: meaning depends on the manufacturer
    W209_ZeroFeed = 209,                     // 39+0: no usable feed
    W210_RapidWhileCutting = 210,            // motion with rapid traverse on and a cutting tool on
    W211_ToolOnAtEnd = 211,                  // program ends with a cutting or marking tool on
    W212_BurnerCountNotBeforeSpacing = 212,  // 135 not immediately before 136 (Woyda)
    W213_MacroOnlyFunction = 213,            // 67/68 loops exist only in Woyda macro files
    W214_UnclosedOptionalIgnore = 214,       // 100 without 101
    W215_ZeroOffsetInIncremental = 215,      // 83 while 81 is in force: takes effect with the next absolute move
    E216_FunctionValueRange = 216,           // a machine function's value outside the range the function allows

    // --- geometry ---
    E301_ArcEndNotOnCircle = 301,      // |r_end - r_start| > arc_tolerance
    E302_ArcZeroRadius = 302,          // centre on the start point
    E303_ParabolaEndNotOnCurve = 303,  // end point off the parabola by more than arc_tolerance
    E304_ParabolaZeroCurvature = 304,  // radius of curvature at the vertex is zero
    W305_ParabolaDirection = 305,      // TC does not match the turning of the travelled piece
    E306_KerfRadiusNegative = 306,     // an arc whose radius would go negative under kerf offset
    E307_KerfGouge = 307,              // a concave corner the compensated torch cannot get into

    // --- machine / profile ---
    E401_LeavesTable = 401,   // motion beyond the profile's table travel limits
    E402_BadProfile = 402,    // a profile that cannot be read
    N403_OtherDialect = 403,  // the tape's evidence points to another dialect than the profile's

    // --- conversion (essi convert) ---
    W501_NoCounterpart = 501,    // a function the target has no word for: kept as a comment or left out
    W502_ParabolaAsArcs = 502,   // a parabola written as circular arcs within the chord tolerance
    W503_RoundedToUnit = 503,    // a coordinate not on the target's unit grid, rounded to it
    W504_ValueNotWritten = 504,  // a function's value the target cannot carry (or not exactly)

    // --- the cut plan (essi/plan.hpp) ---
    W601_ContourGap = 601,             // a cut stops short of closing its contour by a small gap
    E602_KerfIntoPart = 602,           // the kerf inside a part or outside a hole (the role is certain)
    N603_KerfInsideLoneContour = 603,  // a lone contour with the kerf inside: a plate hole, or a part too small
    W604_CutBeforeInside = 604,        // a contour cut before one inside it (a part before its holes)
    E605_PartsCollide = 605,           // two parts overlap or come closer than the kerf width
    E606_CutCrossesCutPart = 606,      // a cut crosses a part already cut free
    W607_SamePathTwice = 607,          // the same path cut twice
    W608_FeedOutOfRange = 608,         // a cut at a feed outside the profile's feed_range_mm_min
    W609_DwellTooLong = 609,           // a dwell longer than the profile's max_dwell_s
    W610_PierceWithoutLeadIn = 610,    // a contour pierced on its own line (profile lead_in_required)
    W611_CutLargerThanTable = 611,     // a cut larger than the table's travel
    N612_ContoursOverlap = 612,        // two contours of unknown role overlap: a collision if both are parts
    N613_PlateTooCrowded = 613,        // contours piled over each other: not every pair of them was compared
    N614_PlateSplit = 614,             // a plate too large to analyse whole: analysed in parts (kPlanMaxPlateMotions)
    N615_CutTooLong = 615,             // a cut of more points than the cut plan holds (kPlanMaxPlatePoints): left out
};

// Another place a diagnostic concerns: the other contour of a collision, the hole cut after its part, the block
// that set a feed (`related` in the JSON, SARIF relatedLocations, the viewer's and the SVG's marks).
struct RelatedLocation {
    std::uint32_t line = 0;      // its first line
    std::uint32_t end_line = 0;  // its last line (== line for one block)
    Msg msg = Msg::None;         // what is there ("the hole, cut after it"), with its arguments
    MessageArgs args;
};

// A diagnostic is kept compactly: its code, severity and position, the catalogue row of its message and the row's
// arguments (MessageArgs: one string, numbers as their text, short enough mostly to need no heap); the sentence
// itself is made only when it is shown (diagnostic_message). The cut plan's contour and point are kept in place;
// its other places and overlap polygons, which few diagnostics have, out of line.
struct Diagnostic {
    Severity severity = Severity::Error;
    bool has_at = false;  // (the cut plan's, below)
    DiagCode code = DiagCode::E101_InvalidCharacter;
    Msg msg = Msg::None;       // the catalogue row of the message (None: a free text, set_text)
    std::uint32_t line = 0;    // 1-based; 0 when the problem has no position (profile)
    std::uint32_t column = 0;  // 1-based byte column
    // The cut plan's diagnostics (6xx, essi/plan.hpp) concern a contour and a place on the drawing:
    std::uint32_t contour_first = 0, contour_last = 0;  // the lines of the contour concerned (0: none)
    Point at;                                           // where on the drawing (program mm, as the motions)
    MessageArgs args;  // the row's arguments; for a free text (msg None), the text itself

    Diagnostic() = default;
    Diagnostic(const Diagnostic& o);
    Diagnostic& operator=(const Diagnostic& o);
    Diagnostic(Diagnostic&&) noexcept = default;
    Diagnostic& operator=(Diagnostic&&) noexcept = default;
    ~Diagnostic() = default;

    // A message that is not in the catalogue, shown as it is in every language.
    void set_text(std::string text);
    // The other places it concerns (none for most).
    [[nodiscard]] const std::vector<RelatedLocation>& related() const;
    void add_related(RelatedLocation r);
    // A collision's overlapping area: the area inside every one of these polygons (program mm; none for most).
    [[nodiscard]] const std::vector<std::vector<Point>>& overlap() const;
    void set_overlap(std::vector<std::vector<Point>> polygons);

private:
    struct Places {
        std::vector<RelatedLocation> related;
        std::vector<std::vector<Point>> overlap;
    };
    std::unique_ptr<Places> places_;  // null while it has neither
};
// The related place's text in `lang`.
[[nodiscard]] std::string related_message(const RelatedLocation& r, Lang lang);

// A diagnostic whose message is the catalogue's `msg` with `args`.
[[nodiscard]] Diagnostic make_diagnostic(Severity severity, DiagCode code, std::uint32_t line, std::uint32_t column,
                                         Msg msg, MessageArgs args = {});
// The diagnostic's message in `lang` (its text as it is when it was not made from the catalogue): the one way a
// diagnostic's sentence is made, for every report, the viewer and the server.
[[nodiscard]] std::string diagnostic_message(const Diagnostic& d, Lang lang);

// "E101", "W109" ...
[[nodiscard]] std::string code_name(DiagCode code);
// The severity a code has by default (its letter).
[[nodiscard]] Severity default_severity(DiagCode code);
// "error", "warning", "note"
[[nodiscard]] std::string_view severity_name(Severity s);
// One sentence per code: what the rule checks (for SARIF rules, docs and the viewer).
[[nodiscard]] std::string_view code_summary(DiagCode code, Lang lang = Lang::En);
// Every code, in numeric order.
[[nodiscard]] std::vector<DiagCode> all_codes();

// Diagnostics as bytes (essi/wire.hpp), and read back: false when the bytes end before them.
void save_diagnostics(WireWriter& out, const std::vector<Diagnostic>& diagnostics);
[[nodiscard]] bool restore_diagnostics(WireReader& in, std::vector<Diagnostic>& diagnostics);

}  // namespace essi
