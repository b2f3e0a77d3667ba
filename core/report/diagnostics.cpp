// The one table of diagnostic codes: name, default severity and a one-line summary of the rule.
#include "essi/diagnostics.hpp"

#include <algorithm>
#include <array>

namespace essi {
namespace {

struct CodeRow {
    DiagCode code;
    std::string_view summary;
};

constexpr std::array kCodes = {
    CodeRow{DiagCode::E101_InvalidCharacter, "A block holds a character other than + - 0-9 outside a 3/4 ignore section."},
    CodeRow{DiagCode::E102_NonAsciiByte, "A byte outside ASCII (a UTF-8 BOM, national text) outside a 3/4 ignore section."},
    CodeRow{DiagCode::E103_FunctionCodeTooLong, "A machine function has more than 3 digits (ISO 6582 3.4.1)."},
    CodeRow{DiagCode::E104_NumberTooLarge, "A word has more than 9 digits."},
    CodeRow{DiagCode::E105_WordCount, "A block of signed words has a count other than 2 (line), 5 (arc) or 6 (parabola)."},
    CodeRow{DiagCode::E106_FunctionWordCount, "A machine function or head address is followed by 3, 4 or more than 6 signed words."},
    CodeRow{DiagCode::E107_UnclosedIgnore, "A 3 (ignore ON) has no 4 (ignore OFF) after it: the rest of the tape would be ignored."},
    CodeRow{DiagCode::E108_WhitespaceStrict, "A space or tab inside a block while the whitespace policy is strict."},
    CodeRow{DiagCode::W109_WhitespaceSkipped, "A space or tab inside a block; it was skipped."},
    CodeRow{DiagCode::W110_ContentAfterEnd, "Blocks after the end of the program; they are not executed."},
    CodeRow{DiagCode::W111_StrayIgnoreOff, "A 4 (ignore OFF) with no 3 (ignore ON) before it."},
    CodeRow{DiagCode::W112_MisplacedPercent, "A % mark in the middle of the program; it is ignored."},
    CodeRow{DiagCode::E113_EmptyTape, "The tape holds no block."},
    CodeRow{DiagCode::W114_NoProgramEnd, "The tape ends without an end of program code."},
    CodeRow{DiagCode::E119_EiaUnknownLetter, "An EIA block holds a letter or character that the dialect's EIA blocks do not have."},
    CodeRow{DiagCode::E120_EiaLetterOrder, "An EIA block has its letters out of the dialect's order (Woyda: N G X Y I J F M) or one letter twice."},
    CodeRow{DiagCode::E121_EiaFunctionsInBlock, "An EIA block holds more than one of G, M and F where the dialect allows only one (Woyda)."},
    CodeRow{DiagCode::E122_EiaBadNumber, "An EIA letter is not followed by a number, or the number is malformed or too large."},
    CodeRow{DiagCode::E123_EiaArcWithoutDirection, "An EIA block gives an arc centre (I, J) while neither G02 nor G03 is in force."},
    CodeRow{DiagCode::W124_EiaUnknownCode, "A G or M word that the dialect's EIA table does not have; it is ignored."},
    CodeRow{DiagCode::W125_EiaRounded, "EIA coordinates finer than the profile's unit; they were rounded to it."},
    CodeRow{DiagCode::E126_EiaUnclosedComment, "An EIA comment '(' is not closed by ')' on its line."},
    CodeRow{DiagCode::E216_FunctionValueRange, "A machine function's value is outside the range the function allows."},
    CodeRow{DiagCode::N403_OtherDialect, "The tape's evidence points to another dialect than the profile's (a note: --profile auto chooses by it)."},
    CodeRow{DiagCode::W501_NoCounterpart, "A machine function that the target format or dialect has no word for; it is kept as a comment (or left out)."},
    CodeRow{DiagCode::W502_ParabolaAsArcs, "A parabola written as circular arcs within the profile's chord tolerance (the target has no parabolas)."},
    CodeRow{DiagCode::W503_RoundedToUnit, "A coordinate not on the target's unit grid; it was rounded to the nearest unit."},
    CodeRow{DiagCode::W504_ValueNotWritten, "A function's value that the target cannot carry, or not exactly; it is left out or rounded."},
    CodeRow{DiagCode::E115_TooManyErrors, "Reading stopped after too many errors; the file is probably not an ESSI tape."},
    CodeRow{DiagCode::E116_MisplacedMark, "A % or / mark shares its block with other characters."},
    CodeRow{DiagCode::E117_TapeTooLarge, "The tape is larger than 4 GiB."},
    CodeRow{DiagCode::E118_FunctionValueSign, "A machine function's value is written after a '-'; it must follow a '+'."},
    CodeRow{DiagCode::W201_UnknownFunction, "An unassigned or unknown machine function; it is ignored."},
    CodeRow{DiagCode::W202_FunctionValueIgnored, "A value given to a machine function that takes none; the value is ignored."},
    CodeRow{DiagCode::E203_FunctionValueMissing, "A machine function that needs a value has none."},
    CodeRow{DiagCode::W204_KerfWhileCutting, "Kerf compensation switched on or off while a cutting tool is on."},
    CodeRow{DiagCode::W205_AddressOutside3Axis, "A head address used while the machine is not in 3-axis mode (19)."},
    CodeRow{DiagCode::E206_BadHeadAddress, "A head address other than 1 or 2."},
    CodeRow{DiagCode::E207_ZeroOffsetBlock, "A zero offset (83) not followed by a block of two signed words."},
    CodeRow{DiagCode::W208_ManufacturerFunction, "A machine function whose meaning the manufacturer specifies (ISO 6582 55-62); it is ignored."},
    CodeRow{DiagCode::W209_ZeroFeed, "A programmed feed of 0; the time estimate uses the profile's feed."},
    CodeRow{DiagCode::W210_RapidWhileCutting, "A motion at rapid traverse while a cutting tool is on."},
    CodeRow{DiagCode::W211_ToolOnAtEnd, "The program ends with a cutting or marking tool still on."},
    CodeRow{DiagCode::W212_BurnerCountNotBeforeSpacing, "A burner count (135) not immediately followed by a burner spacing (136)."},
    CodeRow{DiagCode::W213_MacroOnlyFunction, "A program loop function (67/68) that only macro files define; it is ignored."},
    CodeRow{DiagCode::W214_UnclosedOptionalIgnore, "An optional ignore ON (100) with no optional ignore OFF (101) after it."},
    CodeRow{DiagCode::W215_ZeroOffsetInIncremental, "A zero offset (83) while programming incrementally; it takes effect with the next absolute move."},
    CodeRow{DiagCode::E301_ArcEndNotOnCircle, "The end point of an arc is not on its circle within the arc tolerance."},
    CodeRow{DiagCode::E302_ArcZeroRadius, "An arc whose centre is its start point."},
    CodeRow{DiagCode::E303_ParabolaEndNotOnCurve, "The end point of a parabola is not on its curve within the arc tolerance."},
    CodeRow{DiagCode::E304_ParabolaZeroCurvature, "A parabola whose radius of curvature at the vertex is zero."},
    CodeRow{DiagCode::W305_ParabolaDirection, "A parabola's TC does not match the turning direction of the travelled piece."},
    CodeRow{DiagCode::E306_KerfRadiusNegative, "An arc whose radius would be zero or negative after the kerf offset."},
    CodeRow{DiagCode::E307_KerfGouge, "A concave corner the kerf-compensated torch cannot get into without cutting into the contour (a gouge)."},
    CodeRow{DiagCode::E401_LeavesTable, "A motion leaves the table travel limits of the machine profile."},
    CodeRow{DiagCode::E402_BadProfile, "A machine profile that cannot be read."},
};

const CodeRow* find_row(DiagCode code) {
    for (const auto& row : kCodes)
        if (row.code == code) return &row;
    return nullptr;
}

// Codes whose default severity is an error: the ones named E... in the enum.
bool is_error_code(DiagCode code) {
    switch (code) {
        case DiagCode::E101_InvalidCharacter: case DiagCode::E102_NonAsciiByte:
        case DiagCode::E103_FunctionCodeTooLong: case DiagCode::E104_NumberTooLarge:
        case DiagCode::E105_WordCount: case DiagCode::E106_FunctionWordCount:
        case DiagCode::E107_UnclosedIgnore: case DiagCode::E108_WhitespaceStrict:
        case DiagCode::E113_EmptyTape: case DiagCode::E115_TooManyErrors:
        case DiagCode::E116_MisplacedMark: case DiagCode::E117_TapeTooLarge:
        case DiagCode::E118_FunctionValueSign: case DiagCode::E119_EiaUnknownLetter:
        case DiagCode::E120_EiaLetterOrder: case DiagCode::E121_EiaFunctionsInBlock:
        case DiagCode::E122_EiaBadNumber: case DiagCode::E123_EiaArcWithoutDirection:
        case DiagCode::E126_EiaUnclosedComment: case DiagCode::E216_FunctionValueRange:
        case DiagCode::E203_FunctionValueMissing: case DiagCode::E206_BadHeadAddress:
        case DiagCode::E207_ZeroOffsetBlock: case DiagCode::E301_ArcEndNotOnCircle:
        case DiagCode::E302_ArcZeroRadius: case DiagCode::E303_ParabolaEndNotOnCurve:
        case DiagCode::E304_ParabolaZeroCurvature: case DiagCode::E306_KerfRadiusNegative: case DiagCode::E307_KerfGouge:
        case DiagCode::E401_LeavesTable: case DiagCode::E402_BadProfile:
            return true;
        default:
            return false;
    }
}

}  // namespace

namespace {
// Codes whose default severity is a note: the ones named N... in the enum.
bool is_note_code(DiagCode code) { return code == DiagCode::N403_OtherDialect; }
}  // namespace

std::string code_name(DiagCode code) {
    const int n = static_cast<int>(code);
    std::string s(1, is_error_code(code) ? 'E' : is_note_code(code) ? 'N' : 'W');
    s += std::to_string(n);
    return s;
}

Severity default_severity(DiagCode code) {
    return is_error_code(code) ? Severity::Error : is_note_code(code) ? Severity::Note : Severity::Warning;
}

std::string_view severity_name(Severity s) {
    switch (s) {
        case Severity::Note: return "note";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "error";
}

std::string_view code_summary(DiagCode code) {
    const CodeRow* row = find_row(code);
    return row ? row->summary : std::string_view{};
}

std::vector<DiagCode> all_codes() {
    std::vector<DiagCode> v;
    for (const auto& row : kCodes) v.push_back(row.code);
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace essi
