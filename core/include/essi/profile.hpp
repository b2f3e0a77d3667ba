// Machine + dialect profiles. Every choice ESSI leaves open (docs/semantics.md) is a setting here, with the
// default the semantics page gives. Profiles are JSON; two are built in: "iso6582" (default) and "woyda".
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/function_codes.hpp"
#include "essi/motion.hpp"

namespace essi {

enum class Dialect : std::uint8_t { Iso6582, Woyda };
enum class WhitespacePolicy : std::uint8_t { Skip, Strict };
enum class KerfValueMeaning : std::uint8_t { Width, Offset };

// A program end marker: a function code (63, 64, 0, 99) or one of the characters '/' and '='.
struct EndCode {
    int function = -1;   // >= 0: a machine function
    char mark = 0;       // '/' or '=' when function < 0
    friend bool operator==(const EndCode&, const EndCode&) = default;
};

struct TableLimits {
    double min_x_mm = 0, min_y_mm = 0, max_x_mm = 0, max_y_mm = 0;
};

struct Profile {
    std::string name = "iso6582";
    Dialect dialect = Dialect::Iso6582;

    // Reading
    double unit_mm = 0.1;                       // one unit increment in mm (ISO A.6)
    WhitespacePolicy whitespace = WhitespacePolicy::Skip;
    std::vector<EndCode> end_codes = {{fn::kCancelFunctions, 0}, {fn::kEndOfTape, 0}, {-1, '/'}};

    // Geometry
    double arc_tolerance_units = 2.0;           // |r_end - r_start| allowed, in unit increments (§5)
    double chord_tolerance_mm = 0.01;           // flattening tolerance for previews and traces

    // Interpretation
    bool optional_ignore = false;               // 100/101 skip the blocks between them (panel switch)
    bool rapid_single_block = false;            // 5 lasts one block when the machine has no 6 (Annex B)
    KerfValueMeaning kerf_value = KerfValueMeaning::Width;
    double kerf_units = 20.0;                   // kerf used by 29/30 without a value, in unit increments
    double default_dwell_s = 1.0;               // 41 without a value

    // Time estimate (§9)
    double feed_mm_min = 1000.0;                // cutting feed when the tape gives none (39+v)
    double rapid_mm_min = 10000.0;              // rapid traverse speed
    double pierce_time_s = 2.0;                 // added once per pierce

    // Machine placement (§11)
    double setup_offset_x_mm = 0, setup_offset_y_mm = 0;  // setup zero offset (G54-like)
    std::optional<TableLimits> table;           // travel limits; none = unlimited
};

// Unit increments (machine axes, from the program start) to machine millimetres: units x unit_mm + the setup
// offset (docs/semantics.md §3, §11). The one formula for the interpreter's positions and the viewer's motions.
[[nodiscard]] inline Point units_to_mm(const Profile& p, long long x, long long y) {
    return {static_cast<double>(x) * p.unit_mm + p.setup_offset_x_mm, static_cast<double>(y) * p.unit_mm + p.setup_offset_y_mm};
}
// The unit increments whose units_to_mm is exactly `mm`: false when there are none (a point that is not on the
// unit grid, or too far for a long long).
[[nodiscard]] bool mm_to_units(const Profile& p, Point mm, long long& x, long long& y);

// The built-in profiles by name ("iso6582", "woyda"); nullopt for other names.
[[nodiscard]] std::optional<Profile> builtin_profile(std::string_view name);
[[nodiscard]] std::vector<std::string> builtin_profile_names();

// Parses a profile from JSON text. Keys absent from the text keep the values of the profile named by its
// "base" key (default "iso6582"). Errors are returned as diagnostics (E402) with line 0, never thrown.
struct ProfileResult {
    std::optional<Profile> profile;
    std::vector<Diagnostic> diagnostics;
};
[[nodiscard]] ProfileResult parse_profile(std::string_view json_text);

// The profile as JSON text (every key), for `essi profile show` and round-trip tests.
[[nodiscard]] std::string profile_to_json(const Profile& profile);

}  // namespace essi
