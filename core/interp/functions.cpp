// What every machine function means, per dialect (essi/functions.hpp): one table, ISO 6582 Annex B and the Woyda
// NBS300/400 extensions. The table (function_table.def) holds the codes; their names, explanations and the
// sentences built here are rows of the message catalogue (core/i18n/messages/functions.def).
#include "essi/functions.hpp"

#include "essi/function_codes.hpp"
#include "essi/text.hpp"

#include <cstdio>

namespace essi {
namespace {

// A function's name and explanation: the catalogue's rows, and their English texts for the callers that
// read FunctionInfo::name and explanation.
FunctionInfo row(int code, Msg name, Msg explanation) {
    FunctionInfo f;
    f.code = code;
    f.name_msg = name;
    f.explanation_msg = explanation;
    f.name = text(name, Lang::En);
    f.explanation = text(explanation, Lang::En);
    return f;
}

FunctionInfo unassigned(int code) {
    FunctionInfo f = row(code, Msg::FnUnassignedName, Msg::FnUnassignedText);
    f.assigned = false;
    return f;
}

// One row of function_table.def.
struct FunctionRow {
    int code;
    Dialect dialect;
    Msg name;
    Msg explanation;
    FunctionValue value;
    Msg value_unit;  // Msg::None: no unit
};

// One ESSI_ACTS_AS row of function_table.def.
struct ActionRow {
    int code;
    Dialect dialect;
    FunctionAction action;
};

constexpr FunctionRow kFunctionRows[] = {
// A row's stem S names the catalogue's S##Name and S##Text (functions.def); its unit is a catalogue row or None.
#define ESSI_FUNCTION(code, dialect, text, value, unit) \
    {code, Dialect::dialect, Msg::text##Name, Msg::text##Text, FunctionValue::value, Msg::unit},
#define ESSI_ACTS_AS(code, dialect, action, action_value)
#include "function_table.def"
#undef ESSI_ACTS_AS
#undef ESSI_FUNCTION
};

constexpr ActionRow kActionRows[] = {
#define ESSI_FUNCTION(code, dialect, text, value, unit)
#define ESSI_ACTS_AS(code, dialect, action, action_value) \
    {code, Dialect::dialect, FunctionAction{action, action_value}},
#include "function_table.def"
#undef ESSI_ACTS_AS
#undef ESSI_FUNCTION
};

// Dialects whose controls know only the codes of their own table (and refuse the others): ISO's rows are not
// read for them.
constexpr Dialect kCompleteTables[] = {Dialect::Hypertherm};

bool has_complete_table(Dialect dialect) {
    for (Dialect d : kCompleteTables)
        if (d == dialect) return true;
    return false;
}

FunctionInfo info_of(const FunctionRow& r) {
    FunctionInfo f = row(r.code, r.name, r.explanation);
    f.value = r.value;
    f.unit_msg = r.value_unit;
    f.value_unit = text(r.value_unit, Lang::En);
    return f;
}

// The table's row for `code` in `dialect`, or null.
const FunctionRow* find_row(int code, Dialect dialect) {
    for (const FunctionRow& r : kFunctionRows)
        if (r.code == code && r.dialect == dialect) return &r;
    return nullptr;
}

FunctionInfo iso_row(int code) {
    if (const FunctionRow* r = find_row(code, Dialect::Iso6582)) return info_of(*r);
    if (code >= 55 && code <= 62) {
        FunctionInfo f = row(code, Msg::FnManufacturerName, Msg::FnManufacturerText);
        f.manufacturer = true;
        return f;
    }
    const bool drawing = (code >= 70 && code <= 74) || (code >= 76 && code <= 79) || (code >= 84 && code <= 86) ||
                         (code >= 89 && code <= 90) || (code >= 93 && code <= 98);
    if (drawing) {
        FunctionInfo f = row(code, Msg::FnDrawingMachineName, Msg::FnDrawingMachineText);
        f.drawing_machine = true;
        return f;
    }
    return unassigned(code);
}

// A value as printf's %.4g writes it (400 bytes hold any double).
std::string g4_text(double v) {
    char buf[400];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// The ranges of the values functions take (E216): wide enough for any machine, narrow enough to catch a value
// in the wrong unit (a feed in mm/s, a kerf in micrometres).
struct RangeRow {
    int code;
    FunctionValueRange range;
};
constexpr RangeRow kValueRanges[] = {
    {fn::kFeed, {0, 100000, RangeUnit::AsWritten}},  // mm/min (0: W209, the profile's feed)
    {fn::kDwell, {0, 3600, RangeUnit::Seconds}},     // s (the value times the profile's dwell_unit_s)
    {fn::kKerfLeft, {0, 100, RangeUnit::Mm}},        // mm
    {fn::kKerfRight, {0, 100, RangeUnit::Mm}},
    {fn::kWoydaBurnerCount, {1, 32, RangeUnit::AsWritten}},     // burners
    {fn::kWoydaBurnerSpacing, {0, 100000, RangeUnit::Mm}},      // mm
    {fn::kHyperthermKerfValue, {0, 100, RangeUnit::Mm}},        // mm
    {fn::kPunchMarkingOffsetOn, {1, 8, RangeUnit::AsWritten}},  // Hypertherm 11+n: marker 1-8
    {fn::kToolOffsetOff, {1, 8, RangeUnit::AsWritten}},
    {fn::kHyperthermGoHome, {1, 4, RangeUnit::AsWritten}},              // Hypertherm 79+n: home position 1-4
    {fn::kHyperthermRepeatPointer, {1, 100000, RangeUnit::AsWritten}},  // Hypertherm 97+v: passes of a subroutine loop
};

}  // namespace

std::optional<FunctionValueRange> function_value_range(int code) {
    for (const RangeRow& r : kValueRanges)
        if (r.code == code) return r.range;
    return std::nullopt;
}

std::optional<FunctionAction> function_action(int code, Dialect dialect) {
    for (const ActionRow& r : kActionRows)
        if (r.code == code && r.dialect == dialect) return r.action;
    return std::nullopt;
}

std::optional<FunctionInfo> function_info(int code, Dialect dialect) {
    if (code < 0 || code >= fn::kCodeCount) return std::nullopt;
    if (dialect != Dialect::Iso6582) {
        if (const FunctionRow* r = find_row(code, dialect)) return info_of(*r);
        if (has_complete_table(dialect)) {
            FunctionInfo f = row(code, Msg::FnUnknownName, Msg::FnUnknownNotInTableText);
            f.assigned = false;
            return f;
        }
    }
    if (code > fn::kLastIsoCode) {
        FunctionInfo f = row(code, Msg::FnUnknownName, Msg::FnUnknownBeyondIsoText);
        f.assigned = false;
        return f;
    }
    return iso_row(code);
}

// The sentences below are the catalogue's; their numbers are formatted as they always were, the same in every
// language (a point for the decimals).
std::string kerf_value_text(double value_mm, const Profile& profile, Lang lang) {
    const bool width = profile.kerf_value == KerfValueMeaning::Width;
    return format_message(width ? Msg::FnKerfWidth : Msg::FnKerfOffset, lang,
                          {g4_text(value_mm), g4_text(width ? value_mm / 2 : value_mm * 2)});
}

std::string kerf_offset_text(KerfSide side, double offset_mm, Lang lang) {
    const Msg sentence = side == KerfSide::Left    ? Msg::FnKerfTorchLeft
                         : side == KerfSide::Right ? Msg::FnKerfTorchRight
                                                   : Msg::FnKerfTorchOff;
    return format_message(sentence, lang, {mm_text(offset_mm), mm_text(offset_mm * 2)});
}

std::string describe_function(int code, bool has_value, double value, const Profile& profile, Lang lang) {
    const auto info = function_info(code, profile.dialect);
    if (!info) return format_message(Msg::FnDescribeNotAFunction, lang, {code});
    std::string name(text(info->name_msg, lang));
    if (!info->assigned) name = format_message(Msg::FnDescribeIgnored, lang, {name});
    // What the value says, with its separator (", 2 mm"), or nothing.
    std::string detail;
    if (has_value) {
        switch (code) {
            case fn::kKerfLeft:
            case fn::kKerfRight:
            case fn::kHyperthermKerfValue:
                detail = format_message(Msg::FnDescribeKerf, lang,
                                        {kerf_value_text(value * profile.unit_mm, profile, lang)});
                break;
            case fn::kFeed: detail = format_message(Msg::FnDescribeFeed, lang, {number_text(value)}); break;
            case fn::kDwell:
                detail = format_message(Msg::FnDescribeDwell, lang, {number_text(value * profile.dwell_unit_s)});
                break;
            case fn::kWoydaBurnerSpacing:
                detail = format_message(Msg::FnDescribeLength, lang, {g4_text(value * profile.unit_mm)});
                break;
            default: detail = format_message(Msg::FnDescribeValue, lang, {number_text(value)}); break;
        }
    } else if (code == fn::kKerfLeft || code == fn::kKerfRight) {
        detail = format_message(Msg::FnDescribeProfileKerf, lang,
                                {kerf_value_text(profile.kerf_units * profile.unit_mm, profile, lang)});
    }
    return format_message(Msg::FnDescribe, lang, {code, name, detail, text(info->explanation_msg, lang)});
}

}  // namespace essi
