// The machine function table (ISO 6582 Annex B, Woyda NBS300/400 extensions). Names follow the standard;
// explanations are the sentence a machine operator would use.
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

FunctionInfo with_value(FunctionInfo f, FunctionValue v, std::string_view unit) {
    f.value = v;
    f.value_unit = unit;
    return f;
}

FunctionInfo unassigned(int code) {
    FunctionInfo f = row(code, "Unassigned", "not assigned by ISO 6582; a controller ignores it");
    f.assigned = false;
    return f;
}

FunctionInfo iso_row(int code) {
    switch (code) {
        case 0: return row(0, "Programmed stop", "the machine stops until the operator restarts it");
        case 1: return row(1, "Address of head No. 1", "on a 3-axis machine (19), data with this address goes to head 1");
        case 2: return row(2, "Address of head No. 2", "on a 3-axis machine (19), data with this address goes to head 2");
        case 3: return row(3, "Ignore ON", "the following lines up to a 4 are ignored (comments, part data)");
        case 4: return row(4, "Ignore OFF", "ends the ignored section opened by 3");
        case 5: return row(5, "Rapid traverse ON", "moves at rapid traverse speed until 6");
        case 6: return row(6, "Rapid traverse OFF", "ends rapid traverse");
        case 7: return row(7, "Oxygen ON", "cutting oxygen on at the centre torch (tool 1): cutting starts");
        case 8: return row(8, "Oxygen OFF", "cutting oxygen off at the centre torch (tool 1)");
        case 9: return row(9, "Punch marking ON", "punch marking tool on (tool 2)");
        case 10: return row(10, "Punch marking OFF", "punch marking tool off (tool 2)");
        case 11: return row(11, "Punch marking offset ON", "moves the punch marker (tool 2) to the centre torch's position");
        case 12: return row(12, "Tool offset OFF", "moves the centre torch (tool 1) back to its position");
        case 13: return row(13, "Left bevel torch ON", "cutting oxygen on at the left bevel torch");
        case 14: return row(14, "Left bevel torch OFF", "cutting oxygen off at the left bevel torch");
        case 15: return row(15, "Right bevel torch ON", "cutting oxygen on at the right bevel torch");
        case 16: return row(16, "Right bevel torch OFF", "cutting oxygen off at the right bevel torch");
        case 17: return row(17, "Acceleration control", "decelerate and accelerate at every block end until 18");
        case 18: return row(18, "Acceleration control OFF", "cancels 17");
        case 19: return row(19, "3-axis control", "3-axis mode: motion blocks may carry head addresses 1 and 2");
        case 20: return row(20, "2-axis control", "2-axis mode");
        case 21: return row(21, "+X +Y (normal)", "tape X/Y map to machine +x/+y");
        case 22: return row(22, "+X -Y (mirror)", "machine x = +X, y = -Y; arcs change direction");
        case 23: return row(23, "-X -Y (rotate 180)", "machine x = -X, y = -Y");
        case 24: return row(24, "-X +Y (mirror)", "machine x = -X, y = +Y; arcs change direction");
        case 25: return row(25, "-Y -X (mirror)", "machine x = -Y, y = -X; arcs change direction");
        case 26: return row(26, "+Y -X (rotate -90)", "machine x = +Y, y = -X");
        case 27: return row(27, "+Y +X (mirror)", "machine x = +Y, y = +X; arcs change direction");
        case 28: return row(28, "-Y +X (rotate +90)", "machine x = -Y, y = +X");
        case 29: return with_value(row(29, "Left kerf compensation ON", "kerf compensation left of the direction of travel"),
                                   FunctionValue::Optional, "unit increments");
        case 30: return with_value(row(30, "Right kerf compensation ON", "kerf compensation right of the direction of travel"),
                                   FunctionValue::Optional, "unit increments");
        case 31: return row(31, "Left hand (portal side)", "selects the heads on the portal side");
        case 32: return row(32, "Right hand (cantilever) side", "selects the heads on the cantilever side");
        case 33: return row(33, "Master head set I (inside)", "selects master head set I");
        case 34: return row(34, "Master head set II (outside)", "selects master head set II");
        case 35: return row(35, "Slave head set I (inside)", "selects slave head set I");
        case 36: return row(36, "Slave head set II (outside)", "selects slave head set II");
        case 38: return row(38, "Kerf compensation OFF", "cancels 29 and 30");
        // 39 and 41 carry a value in the Woyda extension that every dialect here accepts (docs/semantics.md §2).
        case 39: return with_value(row(39, "Programmed feed", "sets the cutting feed"), FunctionValue::Optional, "mm/min");
        case 41: return with_value(row(41, "Dwell", "waits, to improve corners of thick plates"), FunctionValue::Optional, "s");
        case 42: return row(42, "Burner bridge", "burners off for a fixed distance along the next contour, then on again");
        case 45: return row(45, "Torch head lower", "automatic height sensing on, torch heads lowered");
        case 46: return row(46, "Torch head raise", "automatic height sensing off, torch heads raised");
        case 48: return row(48, "Torch head hold", "automatic height sensing off, torch heads held at their height");
        case 49: return row(49, "Preheat ON", "preheat flame on");
        case 50: return row(50, "Preheat OFF", "preheat flame off");
        case 51: return row(51, "Rotary control ON", "bevel torches turn to stay at right angles to the path");
        case 52: return row(52, "Rotary control OFF", "cancels 51");
        case 53: return row(53, "Plasma ON", "plasma torch on (tool 3): cutting starts");
        case 54: return row(54, "Plasma OFF", "plasma torch off (tool 3)");
        case 63: return row(63, "Zero auxiliary function", "all stored machine functions are cancelled: end of program");
        case 64: return row(64, "End of tape", "all stored machine functions are cancelled and the tape rewinds: end of program");
        case 81: return row(81, "Incremental mode", "dimensions are relative to the start of each block");
        case 82: return row(82, "Absolute mode", "dimensions are absolute coordinates");
        case 83: return row(83, "Zero offset", "the next two-word block gives the new origin of absolute coordinates");
        case 100: return row(100, "Optional ignore ON", "blocks up to 101 are skipped when the panel switch is on");
        case 101: return row(101, "Optional ignore OFF", "ends the optional ignore section");
        case 102: return row(102, "Optional stop", "stops here when the panel switch is on");
        case 105: return row(105, "Zero position No. 1", "moves the machine to start position 1");
        case 106: return row(106, "Zero position No. 2", "moves the machine to start position 2");
        case 107: return row(107, "Zero position No. 3", "moves the machine to start position 3");
        case 110: return row(110, "Line marking ON", "line marking tool on (tool 4)");
        case 111: return row(111, "Line marking OFF", "line marking tool off (tool 4)");
        case 112: return row(112, "Tool No. 5 ON", "tool 5 on (marking)");
        case 113: return row(113, "Tool No. 5 OFF", "tool 5 off");
        case 114: return row(114, "Line marking offset ON", "moves the line marker (tool 4) to the previous tool's position");
        case 115: return row(115, "Tool No. 5 offset ON", "moves tool 5 to the previous tool's position");
        default: break;
    }
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

// Woyda NBS300/400 functions that differ from or extend ISO 6582.
std::optional<FunctionInfo> woyda_row(int code) {
    switch (code) {
        case 43: return row(43, "Cutting oxygen OFF", "cutting oxygen off; the preheat stays on (Woyda)");
        case 62: return row(62, "Program zero", "returns on a straight line to the program's start point (Woyda)");
        case 66: return row(66, "Repeat start", "blocks before 66 run only on the first pass of an automatic repeat (Woyda)");
        case 67: return row(67, "End of program loop", "defined only in Woyda macro files");
        case 68: return row(68, "Start of program loop", "defined only in Woyda macro files");
        case 135: return with_value(row(135, "Burner count", "number of burners to use; must stand right before 136 (Woyda)"),
                                    FunctionValue::Required, "burners");
        case 136: return with_value(row(136, "Burner spacing", "distance between the active burner carriages (Woyda)"),
                                    FunctionValue::Required, "unit increments");
        default: return std::nullopt;
    }
}

}  // namespace

std::optional<FunctionInfo> function_info(int code, Dialect dialect) {
    if (code < 0 || code >= fn::kCodeCount) return std::nullopt;
    if (dialect == Dialect::Woyda) {
        if (auto w = woyda_row(code)) return w;
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
