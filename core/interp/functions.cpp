// What every machine function means, per dialect (essi/functions.hpp): one table, ISO 6582 Annex B and the Woyda
// NBS300/400 extensions.
#include "essi/functions.hpp"

#include "essi/function_codes.hpp"

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

// Every function of ISO 6582 Annex B that has a meaning of its own (55-62, the drawing-machine codes and the
// unassigned ones are worked out in function_info), then the Woyda NBS300/400 functions that differ from or
// extend it. Names follow the standard; explanations are the sentence a machine operator would use.
struct FunctionRow {
    int code;
    Dialect dialect;
    std::string_view name;
    std::string_view explanation;
    FunctionValue value = FunctionValue::None;
    std::string_view value_unit = "";
};

constexpr FunctionRow kFunctionRows[] = {
    {0, Dialect::Iso6582, "Programmed stop", "the machine stops until the operator restarts it"},
    {1, Dialect::Iso6582, "Address of head No. 1", "on a 3-axis machine (19), data with this address goes to head 1"},
    {2, Dialect::Iso6582, "Address of head No. 2", "on a 3-axis machine (19), data with this address goes to head 2"},
    {3, Dialect::Iso6582, "Ignore ON", "the following lines up to a 4 are ignored (comments, part data)"},
    {4, Dialect::Iso6582, "Ignore OFF", "ends the ignored section opened by 3"},
    {5, Dialect::Iso6582, "Rapid traverse ON", "moves at rapid traverse speed until 6"},
    {6, Dialect::Iso6582, "Rapid traverse OFF", "ends rapid traverse"},
    {7, Dialect::Iso6582, "Oxygen ON", "cutting oxygen on at the centre torch (tool 1): cutting starts"},
    {8, Dialect::Iso6582, "Oxygen OFF", "cutting oxygen off at the centre torch (tool 1)"},
    {9, Dialect::Iso6582, "Punch marking ON", "punch marking tool on (tool 2)"},
    {10, Dialect::Iso6582, "Punch marking OFF", "punch marking tool off (tool 2)"},
    {11, Dialect::Iso6582, "Punch marking offset ON", "moves the punch marker (tool 2) to the centre torch's position"},
    {12, Dialect::Iso6582, "Tool offset OFF", "moves the centre torch (tool 1) back to its position"},
    {13, Dialect::Iso6582, "Left bevel torch ON", "cutting oxygen on at the left bevel torch"},
    {14, Dialect::Iso6582, "Left bevel torch OFF", "cutting oxygen off at the left bevel torch"},
    {15, Dialect::Iso6582, "Right bevel torch ON", "cutting oxygen on at the right bevel torch"},
    {16, Dialect::Iso6582, "Right bevel torch OFF", "cutting oxygen off at the right bevel torch"},
    {17, Dialect::Iso6582, "Acceleration control", "decelerate and accelerate at every block end until 18"},
    {18, Dialect::Iso6582, "Acceleration control OFF", "cancels 17"},
    {19, Dialect::Iso6582, "3-axis control", "3-axis mode: motion blocks may carry head addresses 1 and 2"},
    {20, Dialect::Iso6582, "2-axis control", "2-axis mode"},
    {21, Dialect::Iso6582, "+X +Y (normal)", "tape X/Y map to machine +x/+y"},
    {22, Dialect::Iso6582, "+X -Y (mirror)", "machine x = +X, y = -Y; arcs change direction"},
    {23, Dialect::Iso6582, "-X -Y (rotate 180)", "machine x = -X, y = -Y"},
    {24, Dialect::Iso6582, "-X +Y (mirror)", "machine x = -X, y = +Y; arcs change direction"},
    {25, Dialect::Iso6582, "-Y -X (mirror)", "machine x = -Y, y = -X; arcs change direction"},
    {26, Dialect::Iso6582, "+Y -X (rotate -90)", "machine x = +Y, y = -X"},
    {27, Dialect::Iso6582, "+Y +X (mirror)", "machine x = +Y, y = +X; arcs change direction"},
    {28, Dialect::Iso6582, "-Y +X (rotate +90)", "machine x = -Y, y = +X"},
    {29, Dialect::Iso6582, "Left kerf compensation ON", "kerf compensation left of the direction of travel",
      FunctionValue::Optional, "unit increments"},
    {30, Dialect::Iso6582, "Right kerf compensation ON", "kerf compensation right of the direction of travel",
      FunctionValue::Optional, "unit increments"},
    {31, Dialect::Iso6582, "Left hand (portal side)", "selects the heads on the portal side"},
    {32, Dialect::Iso6582, "Right hand (cantilever) side", "selects the heads on the cantilever side"},
    {33, Dialect::Iso6582, "Master head set I (inside)", "selects master head set I"},
    {34, Dialect::Iso6582, "Master head set II (outside)", "selects master head set II"},
    {35, Dialect::Iso6582, "Slave head set I (inside)", "selects slave head set I"},
    {36, Dialect::Iso6582, "Slave head set II (outside)", "selects slave head set II"},
    {38, Dialect::Iso6582, "Kerf compensation OFF", "cancels 29 and 30"},
    // 39 and 41 carry a value in the Woyda extension that every dialect here accepts (docs/semantics.md §2).
    {39, Dialect::Iso6582, "Programmed feed", "sets the cutting feed", FunctionValue::Optional, "mm/min"},
    {41, Dialect::Iso6582, "Dwell", "waits, to improve corners of thick plates", FunctionValue::Optional, "s"},
    {42, Dialect::Iso6582, "Burner bridge", "burners off for a fixed distance along the next contour, then on again"},
    {45, Dialect::Iso6582, "Torch head lower", "automatic height sensing on, torch heads lowered"},
    {46, Dialect::Iso6582, "Torch head raise", "automatic height sensing off, torch heads raised"},
    {48, Dialect::Iso6582, "Torch head hold", "automatic height sensing off, torch heads held at their height"},
    {49, Dialect::Iso6582, "Preheat ON", "preheat flame on"},
    {50, Dialect::Iso6582, "Preheat OFF", "preheat flame off"},
    {51, Dialect::Iso6582, "Rotary control ON", "bevel torches turn to stay at right angles to the path"},
    {52, Dialect::Iso6582, "Rotary control OFF", "cancels 51"},
    {53, Dialect::Iso6582, "Plasma ON", "plasma torch on (tool 3): cutting starts"},
    {54, Dialect::Iso6582, "Plasma OFF", "plasma torch off (tool 3)"},
    {63, Dialect::Iso6582, "Zero auxiliary function", "all stored machine functions are cancelled: end of program"},
    {64, Dialect::Iso6582, "End of tape", "all stored machine functions are cancelled and the tape rewinds: end of program"},
    {81, Dialect::Iso6582, "Incremental mode", "dimensions are relative to the start of each block"},
    {82, Dialect::Iso6582, "Absolute mode", "dimensions are absolute coordinates"},
    {83, Dialect::Iso6582, "Zero offset", "the next two-word block gives the new origin of absolute coordinates"},
    {100, Dialect::Iso6582, "Optional ignore ON", "blocks up to 101 are skipped when the panel switch is on"},
    {101, Dialect::Iso6582, "Optional ignore OFF", "ends the optional ignore section"},
    {102, Dialect::Iso6582, "Optional stop", "stops here when the panel switch is on"},
    {105, Dialect::Iso6582, "Zero position No. 1", "moves the machine to start position 1"},
    {106, Dialect::Iso6582, "Zero position No. 2", "moves the machine to start position 2"},
    {107, Dialect::Iso6582, "Zero position No. 3", "moves the machine to start position 3"},
    {110, Dialect::Iso6582, "Line marking ON", "line marking tool on (tool 4)"},
    {111, Dialect::Iso6582, "Line marking OFF", "line marking tool off (tool 4)"},
    {112, Dialect::Iso6582, "Tool No. 5 ON", "tool 5 on (marking)"},
    {113, Dialect::Iso6582, "Tool No. 5 OFF", "tool 5 off"},
    {114, Dialect::Iso6582, "Line marking offset ON", "moves the line marker (tool 4) to the previous tool's position"},
    {115, Dialect::Iso6582, "Tool No. 5 offset ON", "moves tool 5 to the previous tool's position"},
    // Woyda NBS300/400
    {43, Dialect::Woyda, "Cutting oxygen OFF", "cutting oxygen off; the preheat stays on (Woyda)"},
    {62, Dialect::Woyda, "Program zero", "returns on a straight line to the program's start point (Woyda)"},
    {66, Dialect::Woyda, "Repeat start", "blocks before 66 run only on the first pass of an automatic repeat (Woyda)"},
    {67, Dialect::Woyda, "End of program loop", "defined only in Woyda macro files"},
    {68, Dialect::Woyda, "Start of program loop", "defined only in Woyda macro files"},
    {135, Dialect::Woyda, "Burner count", "number of burners to use; must stand right before 136 (Woyda)",
      FunctionValue::Required, "burners"},
    {136, Dialect::Woyda, "Burner spacing", "distance between the active burner carriages (Woyda)",
      FunctionValue::Required, "unit increments"},
};

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

}  // namespace

std::optional<FunctionInfo> function_info(int code, Dialect dialect) {
    if (code < 0 || code >= fn::kCodeCount) return std::nullopt;
    if (dialect != Dialect::Iso6582) {
        if (const FunctionRow* r = find_row(code, dialect)) return info_of(*r);
    }
    if (code > fn::kLastIsoCode) {
        FunctionInfo f = row(code, "Unknown", "not a function of ISO 6582 (0-115) or of this dialect");
        f.assigned = false;
        return f;
    }
    return iso_row(code);
}

std::string describe_function(int code, bool has_value, long value, const Profile& profile) {
    const auto info = function_info(code, profile.dialect);
    std::string s = "function " + std::to_string(code) + ": ";
    if (!info) return s + "not a machine function";
    s += info->name;
    if (!info->assigned) s += " (ignored)";
    char buf[64];
    if (has_value) {
        switch (code) {
            case fn::kKerfLeft:
            case fn::kKerfRight: {
                const double width = value * profile.unit_mm;
                std::snprintf(buf, sizeof buf, ", %.3g mm", width);
                s += buf;
                break;
            }
            case fn::kFeed: s += ", " + std::to_string(value) + " mm/min"; break;
            case fn::kDwell: s += ", " + std::to_string(value) + " s"; break;
            case fn::kWoydaBurnerSpacing: {
                std::snprintf(buf, sizeof buf, ", %.4g mm", value * profile.unit_mm);
                s += buf;
                break;
            }
            default: s += ", value " + std::to_string(value); break;
        }
    } else if (code == fn::kKerfLeft || code == fn::kKerfRight) {
        std::snprintf(buf, sizeof buf, ", %.3g mm (profile kerf)", profile.kerf_units * profile.unit_mm);
        s += buf;
    }
    s += ": ";
    s += info->explanation;
    return s;
}

}  // namespace essi
