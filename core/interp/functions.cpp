// What every machine function means, per dialect (essi/functions.hpp): one table, ISO 6582 Annex B and the Woyda
// NBS300/400 extensions.
#include "essi/functions.hpp"

#include "essi/function_codes.hpp"
#include "essi/text.hpp"

#include <cstdio>

namespace essi {
namespace {

FunctionInfo row(int code, std::string_view name, std::string_view explanation) {
    FunctionInfo f;
    f.code = code;
    f.name = name;
    f.explanation = explanation;
    return f;
}

FunctionInfo unassigned(int code) {
    FunctionInfo f = row(code, "Unassigned", "not assigned by ISO 6582; a controller ignores it");
    f.assigned = false;
    return f;
}

// One row of function_table.def.
struct FunctionRow {
    int code;
    Dialect dialect;
    std::string_view name;
    std::string_view explanation;
    FunctionValue value;
    std::string_view value_unit;
};

// One ESSI_ACTS_AS row of function_table.def.
struct ActionRow {
    int code;
    Dialect dialect;
    FunctionAction action;
};

constexpr FunctionRow kFunctionRows[] = {
#define ESSI_FUNCTION(code, dialect, name, explanation, value, unit) \
    {code, Dialect::dialect, name, explanation, FunctionValue::value, unit},
#define ESSI_ACTS_AS(code, dialect, action, action_value)
#include "function_table.def"
#undef ESSI_ACTS_AS
#undef ESSI_FUNCTION
};

constexpr ActionRow kActionRows[] = {
#define ESSI_FUNCTION(code, dialect, name, explanation, value, unit)
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
    f.value_unit = r.value_unit;
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
        FunctionInfo f = row(code, "Manufacturer function", "specified by the flame cutter manufacturer (ISO 6582 55-62)");
        f.manufacturer = true;
        return f;
    }
    const bool drawing = (code >= 70 && code <= 74) || (code >= 76 && code <= 79) || (code >= 84 && code <= 86) ||
                         (code >= 89 && code <= 90) || (code >= 93 && code <= 98);
    if (drawing) {
        FunctionInfo f = row(code, "Drawing machine function", "for NC drawing machines; a cutting machine ignores it");
        f.drawing_machine = true;
        return f;
    }
    return unassigned(code);
}

// The ranges of the values functions take (E216): wide enough for any machine, narrow enough to catch a value
// in the wrong unit (a feed in mm/s, a kerf in micrometres).
struct RangeRow {
    int code;
    FunctionValueRange range;
};
constexpr RangeRow kValueRanges[] = {
    {fn::kFeed, {0, 100000, RangeUnit::AsWritten}},  // mm/min (0: W209, the profile's feed)
    {fn::kDwell, {0, 3600, RangeUnit::Seconds}},  // s (the value times the profile's dwell_unit_s)
    {fn::kKerfLeft, {0, 100, RangeUnit::Mm}},             // mm
    {fn::kKerfRight, {0, 100, RangeUnit::Mm}},
    {fn::kWoydaBurnerCount, {1, 32, RangeUnit::AsWritten}},     // burners
    {fn::kWoydaBurnerSpacing, {0, 100000, RangeUnit::Mm}},  // mm
    {fn::kHyperthermKerfValue, {0, 100, RangeUnit::Mm}},    // mm
    {fn::kPunchMarkingOffsetOn, {1, 8, RangeUnit::AsWritten}},    // Hypertherm 11+n: marker 1-8
    {fn::kToolOffsetOff, {1, 8, RangeUnit::AsWritten}},
    {fn::kHyperthermGoHome, {1, 4, RangeUnit::AsWritten}},        // Hypertherm 79+n: home position 1-4
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
            FunctionInfo f = row(code, "Unknown", "not in this dialect's code table: its control refuses it");
            f.assigned = false;
            return f;
        }
    }
    if (code > fn::kLastIsoCode) {
        FunctionInfo f = row(code, "Unknown", "not a function of ISO 6582 (0-115) or of this dialect");
        f.assigned = false;
        return f;
    }
    return iso_row(code);
}

std::string kerf_value_text(double value_mm, const Profile& profile) {
    char buf[96];
    if (profile.kerf_value == KerfValueMeaning::Width)
        std::snprintf(buf, sizeof buf, "kerf width %.4g mm (the torch %.4g mm to the side)", value_mm, value_mm / 2);
    else
        std::snprintf(buf, sizeof buf, "kerf offset %.4g mm (a cut %.4g mm wide)", value_mm, value_mm * 2);
    return buf;
}

std::string kerf_offset_text(KerfSide side, double offset_mm) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "torch %.3f mm to the %s (a cut %.3f mm wide)", offset_mm, kerf_side_name(side),
                  offset_mm * 2);
    return buf;
}

std::string describe_function(int code, bool has_value, double value, const Profile& profile) {
    const auto info = function_info(code, profile.dialect);
    std::string s = "function " + std::to_string(code) + ": ";
    if (!info) return s + "not a machine function";
    s += info->name;
    if (!info->assigned) s += " (ignored)";
    char buf[64];
    if (has_value) {
        switch (code) {
            case fn::kKerfLeft:
            case fn::kKerfRight: s += ", " + kerf_value_text(value * profile.unit_mm, profile); break;
            case fn::kFeed: s += ", " + number_text(value) + " mm/min"; break;
            case fn::kDwell: s += ", " + number_text(value * profile.dwell_unit_s) + " s"; break;
            case fn::kHyperthermKerfValue: s += ", " + kerf_value_text(value * profile.unit_mm, profile); break;
            case fn::kWoydaBurnerSpacing: {
                std::snprintf(buf, sizeof buf, ", %.4g mm", value * profile.unit_mm);
                s += buf;
                break;
            }
            default: s += ", value " + number_text(value); break;
        }
    } else if (code == fn::kKerfLeft || code == fn::kKerfRight) {
        s += ", the profile's " + kerf_value_text(profile.kerf_units * profile.unit_mm, profile);
    }
    s += ": ";
    s += info->explanation;
    return s;
}

}  // namespace essi
