// The one table of diagnostic codes: name, default severity and a one-line summary of the rule (its texts in
// core/i18n/messages/codes.def).
#include "essi/diagnostics.hpp"

#include <algorithm>
#include <array>

namespace essi {
namespace {

struct CodeRow {
    DiagCode code;
    Msg summary;  // core/i18n/messages/codes.def
};

constexpr std::array kCodes = {
    CodeRow{DiagCode::E101_InvalidCharacter, Msg::CodeE101},
    CodeRow{DiagCode::E102_NonAsciiByte, Msg::CodeE102},
    CodeRow{DiagCode::E103_FunctionCodeTooLong, Msg::CodeE103},
    CodeRow{DiagCode::E104_NumberTooLarge, Msg::CodeE104},
    CodeRow{DiagCode::E105_WordCount, Msg::CodeE105},
    CodeRow{DiagCode::E106_FunctionWordCount, Msg::CodeE106},
    CodeRow{DiagCode::E107_UnclosedIgnore, Msg::CodeE107},
    CodeRow{DiagCode::E108_WhitespaceStrict, Msg::CodeE108},
    CodeRow{DiagCode::W109_WhitespaceSkipped, Msg::CodeW109},
    CodeRow{DiagCode::W110_ContentAfterEnd, Msg::CodeW110},
    CodeRow{DiagCode::W111_StrayIgnoreOff, Msg::CodeW111},
    CodeRow{DiagCode::W112_MisplacedPercent, Msg::CodeW112},
    CodeRow{DiagCode::E113_EmptyTape, Msg::CodeE113},
    CodeRow{DiagCode::W114_NoProgramEnd, Msg::CodeW114},
    CodeRow{DiagCode::E119_EiaUnknownLetter, Msg::CodeE119},
    CodeRow{DiagCode::E120_EiaLetterOrder, Msg::CodeE120},
    CodeRow{DiagCode::E121_EiaFunctionsInBlock, Msg::CodeE121},
    CodeRow{DiagCode::E122_EiaBadNumber, Msg::CodeE122},
    CodeRow{DiagCode::E123_EiaArcWithoutDirection, Msg::CodeE123},
    CodeRow{DiagCode::W124_EiaUnknownCode, Msg::CodeW124},
    CodeRow{DiagCode::W125_EiaRounded, Msg::CodeW125},
    CodeRow{DiagCode::E126_EiaUnclosedComment, Msg::CodeE126},
    CodeRow{DiagCode::E216_FunctionValueRange, Msg::CodeE216},
    CodeRow{DiagCode::N403_OtherDialect, Msg::CodeN403},
    CodeRow{DiagCode::W501_NoCounterpart, Msg::CodeW501},
    CodeRow{DiagCode::W502_ParabolaAsArcs, Msg::CodeW502},
    CodeRow{DiagCode::W503_RoundedToUnit, Msg::CodeW503},
    CodeRow{DiagCode::W504_ValueNotWritten, Msg::CodeW504},
    CodeRow{DiagCode::W601_ContourGap, Msg::CodeW601},
    CodeRow{DiagCode::E602_KerfIntoPart, Msg::CodeE602},
    CodeRow{DiagCode::N603_KerfInsideLoneContour, Msg::CodeN603},
    CodeRow{DiagCode::W604_CutBeforeInside, Msg::CodeW604},
    CodeRow{DiagCode::E605_PartsCollide, Msg::CodeE605},
    CodeRow{DiagCode::E606_CutCrossesCutPart, Msg::CodeE606},
    CodeRow{DiagCode::W607_SamePathTwice, Msg::CodeW607},
    CodeRow{DiagCode::W608_FeedOutOfRange, Msg::CodeW608},
    CodeRow{DiagCode::W609_DwellTooLong, Msg::CodeW609},
    CodeRow{DiagCode::W610_PierceWithoutLeadIn, Msg::CodeW610},
    CodeRow{DiagCode::W611_CutLargerThanTable, Msg::CodeW611},
    CodeRow{DiagCode::N612_ContoursOverlap, Msg::CodeN612},
    CodeRow{DiagCode::N613_PlateTooCrowded, Msg::CodeN613},
    CodeRow{DiagCode::N614_PlateSplit, Msg::CodeN614},
    CodeRow{DiagCode::N615_CutTooLong, Msg::CodeN615},
    CodeRow{DiagCode::E115_TooManyErrors, Msg::CodeE115},
    CodeRow{DiagCode::E116_MisplacedMark, Msg::CodeE116},
    CodeRow{DiagCode::E117_TapeTooLarge, Msg::CodeE117},
    CodeRow{DiagCode::E118_FunctionValueSign, Msg::CodeE118},
    CodeRow{DiagCode::W201_UnknownFunction, Msg::CodeW201},
    CodeRow{DiagCode::W202_FunctionValueIgnored, Msg::CodeW202},
    CodeRow{DiagCode::E203_FunctionValueMissing, Msg::CodeE203},
    CodeRow{DiagCode::W204_KerfWhileCutting, Msg::CodeW204},
    CodeRow{DiagCode::W205_AddressOutside3Axis, Msg::CodeW205},
    CodeRow{DiagCode::E206_BadHeadAddress, Msg::CodeE206},
    CodeRow{DiagCode::E207_ZeroOffsetBlock, Msg::CodeE207},
    CodeRow{DiagCode::W208_ManufacturerFunction, Msg::CodeW208},
    CodeRow{DiagCode::W209_ZeroFeed, Msg::CodeW209},
    CodeRow{DiagCode::W210_RapidWhileCutting, Msg::CodeW210},
    CodeRow{DiagCode::W211_ToolOnAtEnd, Msg::CodeW211},
    CodeRow{DiagCode::W212_BurnerCountNotBeforeSpacing, Msg::CodeW212},
    CodeRow{DiagCode::W213_MacroOnlyFunction, Msg::CodeW213},
    CodeRow{DiagCode::W214_UnclosedOptionalIgnore, Msg::CodeW214},
    CodeRow{DiagCode::W215_ZeroOffsetInIncremental, Msg::CodeW215},
    CodeRow{DiagCode::E301_ArcEndNotOnCircle, Msg::CodeE301},
    CodeRow{DiagCode::E302_ArcZeroRadius, Msg::CodeE302},
    CodeRow{DiagCode::E303_ParabolaEndNotOnCurve, Msg::CodeE303},
    CodeRow{DiagCode::E304_ParabolaZeroCurvature, Msg::CodeE304},
    CodeRow{DiagCode::W305_ParabolaDirection, Msg::CodeW305},
    CodeRow{DiagCode::E306_KerfRadiusNegative, Msg::CodeE306},
    CodeRow{DiagCode::E307_KerfGouge, Msg::CodeE307},
    CodeRow{DiagCode::E401_LeavesTable, Msg::CodeE401},
    CodeRow{DiagCode::E402_BadProfile, Msg::CodeE402},
};

const CodeRow* find_row(DiagCode code) {
    for (const auto& row : kCodes)
        if (row.code == code) return &row;
    return nullptr;
}

// Codes whose default severity is an error: the ones named E... in the enum.
bool is_error_code(DiagCode code) {
    switch (code) {
        case DiagCode::E101_InvalidCharacter:
        case DiagCode::E102_NonAsciiByte:
        case DiagCode::E103_FunctionCodeTooLong:
        case DiagCode::E104_NumberTooLarge:
        case DiagCode::E105_WordCount:
        case DiagCode::E106_FunctionWordCount:
        case DiagCode::E107_UnclosedIgnore:
        case DiagCode::E108_WhitespaceStrict:
        case DiagCode::E113_EmptyTape:
        case DiagCode::E115_TooManyErrors:
        case DiagCode::E116_MisplacedMark:
        case DiagCode::E117_TapeTooLarge:
        case DiagCode::E118_FunctionValueSign:
        case DiagCode::E119_EiaUnknownLetter:
        case DiagCode::E120_EiaLetterOrder:
        case DiagCode::E121_EiaFunctionsInBlock:
        case DiagCode::E122_EiaBadNumber:
        case DiagCode::E123_EiaArcWithoutDirection:
        case DiagCode::E126_EiaUnclosedComment:
        case DiagCode::E216_FunctionValueRange:
        case DiagCode::E203_FunctionValueMissing:
        case DiagCode::E206_BadHeadAddress:
        case DiagCode::E207_ZeroOffsetBlock:
        case DiagCode::E301_ArcEndNotOnCircle:
        case DiagCode::E302_ArcZeroRadius:
        case DiagCode::E303_ParabolaEndNotOnCurve:
        case DiagCode::E304_ParabolaZeroCurvature:
        case DiagCode::E306_KerfRadiusNegative:
        case DiagCode::E307_KerfGouge:
        case DiagCode::E401_LeavesTable:
        case DiagCode::E402_BadProfile:
        case DiagCode::E602_KerfIntoPart:
        case DiagCode::E605_PartsCollide:
        case DiagCode::E606_CutCrossesCutPart: return true;
        default: return false;
    }
}

}  // namespace

namespace {
// Codes whose default severity is a note: the ones named N... in the enum.
bool is_note_code(DiagCode code) {
    return code == DiagCode::N403_OtherDialect || code == DiagCode::N603_KerfInsideLoneContour ||
           code == DiagCode::N612_ContoursOverlap || code == DiagCode::N613_PlateTooCrowded ||
           code == DiagCode::N614_PlateSplit || code == DiagCode::N615_CutTooLong;
}
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

std::string_view code_summary(DiagCode code, Lang lang) {
    const CodeRow* row = find_row(code);
    return row ? text(row->summary, lang) : std::string_view{};
}

Diagnostic make_diagnostic(Severity severity, DiagCode code, std::uint32_t line, std::uint32_t column, Msg msg,
                           MessageArgs args) {
    Diagnostic d;
    d.severity = severity;
    d.code = code;
    d.line = line;
    d.column = column;
    d.msg = msg;
    d.args = std::move(args);
    return d;
}

std::string diagnostic_message(const Diagnostic& d, Lang lang) {
    if (d.msg == Msg::None) return d.args.packed();
    return format_message(d.msg, lang, d.args);
}

Diagnostic::Diagnostic(const Diagnostic& o)
    : severity(o.severity), has_at(o.has_at), code(o.code), msg(o.msg), line(o.line), column(o.column),
      contour_first(o.contour_first), contour_last(o.contour_last), at(o.at), args(o.args),
      places_(o.places_ ? std::make_unique<Places>(*o.places_) : nullptr) {}

Diagnostic& Diagnostic::operator=(const Diagnostic& o) {
    if (this != &o) *this = Diagnostic(o);
    return *this;
}

void Diagnostic::set_text(std::string text) {
    msg = Msg::None;
    args = MessageArgs::from_packed(std::move(text));
}

const std::vector<RelatedLocation>& Diagnostic::related() const {
    static const std::vector<RelatedLocation> none;
    return places_ ? places_->related : none;
}

const std::vector<std::vector<Point>>& Diagnostic::overlap() const {
    static const std::vector<std::vector<Point>> none;
    return places_ ? places_->overlap : none;
}

void Diagnostic::add_related(RelatedLocation r) {
    if (!places_) places_ = std::make_unique<Places>();
    places_->related.push_back(std::move(r));
}

void Diagnostic::set_overlap(std::vector<std::vector<Point>> polygons) {
    if (!places_) places_ = std::make_unique<Places>();
    places_->overlap = std::move(polygons);
}

std::string related_message(const RelatedLocation& r, Lang lang) { return format_message(r.msg, lang, r.args); }

std::vector<DiagCode> all_codes() {
    std::vector<DiagCode> v;
    for (const auto& row : kCodes) v.push_back(row.code);
    std::sort(v.begin(), v.end());
    return v;
}

namespace {

// The fewest bytes a saved diagnostic takes (its fixed members and three counts).
constexpr std::size_t kSavedDiagnosticMinBytes = 5 * sizeof(std::uint32_t) + 3 * sizeof(std::uint64_t);

void save_diagnostic(WireWriter& out, const Diagnostic& d) {
    out.put_all(d.severity, d.has_at, d.code, d.msg, d.line, d.column, d.contour_first, d.contour_last, d.at);
    out.put_string(d.args.packed());
    out.put_items(d.related(), [&](const RelatedLocation& r) {
        out.put_all(r.line, r.end_line, r.msg);
        out.put_string(r.args.packed());
    });
    out.put_items(d.overlap(), [&](const std::vector<Point>& polygon) { out.put_vector(polygon); });
}

bool restore_diagnostic(WireReader& in, Diagnostic& d) {
    std::string packed;
    if (!in.get_all(d.severity, d.has_at, d.code, d.msg, d.line, d.column, d.contour_first, d.contour_last, d.at) ||
        !in.get_string(packed))
        return false;
    d.args = MessageArgs::from_packed(std::move(packed));
    std::vector<RelatedLocation> related;
    if (!in.get_items(related, 2 * sizeof(std::uint32_t) + sizeof(Msg) + sizeof(std::uint64_t),
                      [&](RelatedLocation& r) {
                          if (!in.get_all(r.line, r.end_line, r.msg) || !in.get_string(packed)) return false;
                          r.args = MessageArgs::from_packed(std::move(packed));
                          return true;
                      }))
        return false;
    for (RelatedLocation& r : related) d.add_related(std::move(r));
    std::vector<std::vector<Point>> overlap;
    if (!in.get_items(overlap, sizeof(std::uint64_t), [&](std::vector<Point>& p) { return in.get_vector(p); }))
        return false;
    if (!overlap.empty()) d.set_overlap(std::move(overlap));
    return true;
}

}  // namespace

void save_diagnostics(WireWriter& out, const std::vector<Diagnostic>& diagnostics) {
    out.put_items(diagnostics, [&](const Diagnostic& d) { save_diagnostic(out, d); });
}

bool restore_diagnostics(WireReader& in, std::vector<Diagnostic>& diagnostics) {
    return in.get_items(diagnostics, kSavedDiagnosticMinBytes,
                        [&](Diagnostic& d) { return restore_diagnostic(in, d); });
}

}  // namespace essi
