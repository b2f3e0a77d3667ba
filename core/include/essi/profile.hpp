// Machine + dialect profiles. Every choice ESSI leaves open (docs/semantics.md) is a setting here, with the
// default the semantics page gives. Profiles are JSON; the built-in ones are JSON files too
// (core/profile/builtin/: iso6582 (default), woyda, hypertherm, din66025), compiled in.
#pragma once

#include "essi/i18n.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/function_codes.hpp"
#include "essi/motion.hpp"

namespace essi {

// The machine function table a profile reads function codes with (core/interp/function_table.def).
enum class Dialect : std::uint8_t { Iso6582, Woyda, Hypertherm };
enum class WhitespacePolicy : std::uint8_t { Skip, Strict };
enum class KerfValueMeaning : std::uint8_t { Width, Offset };

// A program end marker: a function code (63, 64, 0, 99) or one of the characters '/' and '='.
struct EndCode {
    int function = -1;  // >= 0: a machine function
    char mark = 0;      // '/' or '=' when function < 0
    friend bool operator==(const EndCode&, const EndCode&) = default;
};

// An EIA (RS-274) word with a fixed meaning in a dialect: its letter and number ("M70", "G91").
struct EiaWord {
    char letter = 'M';
    int number = 0;
    friend bool operator==(const EiaWord&, const EiaWord&) = default;
};
// One row of a dialect's EIA table: the word and the ESSI machine function it stands for (docs/semantics.md §10).
struct EiaCode {
    EiaWord word;
    int function = 0;
    int value = -1;  // >= 0: the function's value the word stands for (Hypertherm M275 = 11+3)
    friend bool operator==(const EiaCode&, const EiaCode&) = default;
};

// How a dialect writes its EIA tapes (docs/semantics.md §10). G01, G02 and G03 mean the same everywhere; every
// other word is in `codes`, so that what differs between dialects is this data, not code.
struct EiaDialect {
    std::string letters = "NGXYIJFM";    // the address letters a block may hold, in their order
    bool strict_order = true;            // letters out of that order are an error (Woyda)
    bool one_function_per_block = true;  // at most one of G, M and F in a block (Woyda)
    int rapid_motion_g = -1;             // G number of a rapid motion mode (G00: modal until G01-G03); -1 none
    int position_preset_g = -1;          // G number that sets the current position (DIN G92 X Y); -1 none
    char dwell_letter = 'X';             // the letter of the dwell's time (G04 X)
    double dwell_unit_s = 0.001;         // the dwell's time unit (Woyda: milliseconds)
    std::vector<EiaWord> inch_words;     // words that switch coordinates to inches (G20, G70)
    std::vector<EiaWord> mm_words;       // words that switch them back to millimetres (G21, G71)
    std::vector<EiaCode> codes;          // EIA word <-> ESSI function; the first row of a function is its word
    friend bool operator==(const EiaDialect&, const EiaDialect&) = default;
};

struct TableLimits {
    double min_x_mm = 0, min_y_mm = 0, max_x_mm = 0, max_y_mm = 0;
};

// The plate's material (profile key `material`).
struct Material {
    std::string name;
    double thickness_mm = 0;
    double density_kg_m3 = 0;
    friend bool operator==(const Material&, const Material&) = default;
};
// The plate's size (profile key `plate_mm`: {"x": ..., "y": ...}).
struct PlateSize {
    double x_mm = 0, y_mm = 0;
    friend bool operator==(const PlateSize&, const PlateSize&) = default;
};
// What the machine, the pierces, the cut and the material cost (profile key `costs`, docs/semantics.md §9).
struct Costs {
    std::string currency;
    double machine_per_hour = 0;
    double per_pierce = 0;
    double per_m_cut = 0;
    double material_per_kg = 0;
    friend bool operator==(const Costs&, const Costs&) = default;
};
// How long an electrode lasts (profile key `consumables`); a life not given takes no part.
struct ElectrodeLife {
    std::optional<double> pierces;  // electrode_pierces
    std::optional<double> arc_s;    // electrode_arc_s
    friend bool operator==(const ElectrodeLife&, const ElectrodeLife&) = default;
};

// The default of Profile::max_per_code, and the largest value it takes (0: no limit).
constexpr std::size_t kDefaultMaxPerCode = 1000;
constexpr std::uint64_t kMaxPerCodeLimit = 1000000000;

struct Profile {
    std::string name = "iso6582";
    Dialect dialect = Dialect::Iso6582;

    // Reading
    double unit_mm = 0.1;  // one unit increment in mm (ISO A.6)
    WhitespacePolicy whitespace = WhitespacePolicy::Skip;
    std::vector<EndCode> end_codes = {{fn::kEndOfTape, 0}};
    bool end_at_data_end = true;  // the end of the data ends the program without a warning (ISO)

    // Geometry
    double arc_tolerance_units = 2.0;  // |r_end - r_start| allowed, in unit increments (§5)
    double chord_tolerance_mm = 0.01;  // flattening tolerance for previews and traces

    // Interpretation
    bool optional_ignore = false;     // 100/101 skip the blocks between them (panel switch)
    bool rapid_single_block = false;  // 5 lasts one block when the machine has no 6 (Annex B)
    KerfValueMeaning kerf_value = KerfValueMeaning::Width;
    double kerf_units = 20.0;      // kerf used by 29/30 without a value, in unit increments
    double default_dwell_s = 1.0;  // 41 without a value
    double dwell_unit_s = 1.0;     // the unit of 41+v in seconds (Hypertherm: 0.001, milliseconds)

    // Time estimate (§9)
    double feed_mm_min = 1000.0;    // cutting feed when the tape gives none (39+v)
    double rapid_mm_min = 10000.0;  // rapid traverse speed
    double pierce_time_s = 2.0;     // added once per pierce

    // Machine time (§9): the path acceleration (none: no machine time) and grbl's junction deviation
    std::optional<double> accel_mm_s2;
    double junction_deviation_mm = 0.01;

    // The plate and the costs (§9)
    std::optional<Material> material;
    std::optional<PlateSize> plate;  // plate_mm
    std::optional<Costs> costs;
    std::optional<ElectrodeLife> consumables;

    // EIA tapes (§10): the dialect's words and rules (default: the Woyda table)
    EiaDialect eia;

    // Multiple torches (§9): the direction the torches' copies lie in, from the first torch (a unit vector along
    // a machine axis; default +y, the transverse axis)
    Point torch_direction{0, 1};

    // Machine placement (§12): machine = zero offset + R(plate rotation) · program − tool offset
    std::map<std::string, Point> zero_offsets{{kDefaultZeroOffset, {}}};  // a G54-G59-like table, mm
    std::string zero_offset = kDefaultZeroOffset;                         // the active entry
    double plate_rotation_deg = 0;                                        // counter-clockwise about the program origin
    Point marker_offset;               // tool_offsets.marker: where the marker sits from the centre torch (11)
    Point powder_marker_offset;        // tool_offsets.powder_marker (114)
    std::optional<TableLimits> table;  // travel limits in machine mm; none = unlimited

    // The cut plan's checks (essi/plan.hpp, docs/diagnostics.md 6xx)
    double closure_gap_mm = 5.0;    // a cut ending this close to closing its contour: W601
    double feed_min_mm_min = 50.0;  // feed_range_mm_min: cutting feeds outside are W608
    double feed_max_mm_min = 15000.0;
    double max_dwell_s = 120.0;     // a longer dwell: W609
    bool lead_in_required = false;  // a contour pierced on its own line: W610

    // At most this many diagnostics of one code are listed, then one that says how many more (0: all;
    // essi/diagnostic_cap.hpp)
    std::size_t max_per_code = kDefaultMaxPerCode;

    static constexpr const char* kDefaultZeroOffset = "G54";
    // The active zero offset (the entry `zero_offset` names; parse_profile makes sure it exists).
    [[nodiscard]] Point active_zero_offset() const {
        const auto it = zero_offsets.find(zero_offset);
        return it == zero_offsets.end() ? Point{} : it->second;
    }
};

// Unit increments (the program's axes after 21-28, from the program start) to program millimetres: units x
// unit_mm (docs/semantics.md §3, §12). The one formula for the interpreter's positions and the viewer's motions;
// the machine's coordinates are the placement's (essi/placement.hpp).
[[nodiscard]] inline Point units_to_mm(const Profile& p, long long x, long long y) {
    return {static_cast<double>(x) * p.unit_mm, static_cast<double>(y) * p.unit_mm};
}
// The unit increments whose units_to_mm is exactly `mm`: false when there are none (a point that is not on the
// unit grid, or too far for a long long).
[[nodiscard]] bool mm_to_units(const Profile& p, Point mm, long long& x, long long& y);

// The profile's end codes in words, for messages: "63, 64 or /" (in the reader's language), "the end of the
// data" when there are none.
[[nodiscard]] MessageArgs::Arg end_codes_arg(const Profile& p);

// The built-in profiles by name ("iso6582", "woyda", "hypertherm", "din66025"); nullopt for other names.
[[nodiscard]] std::optional<Profile> builtin_profile(std::string_view name);
[[nodiscard]] std::vector<std::string> builtin_profile_names();
// The JSON text a built-in profile is made from (what users copy and edit); empty for other names.
[[nodiscard]] std::string_view builtin_profile_json(std::string_view name);

// Parses a profile from JSON text. Keys absent from the text keep the values of the profile named by its
// "base" key (default "iso6582"). Errors are returned as diagnostics (E402) with line 0, never thrown.
struct ProfileResult {
    std::optional<Profile> profile;
    std::vector<Diagnostic> diagnostics;
};
[[nodiscard]] ProfileResult parse_profile(std::string_view json_text);

// A profile's name is printed in every report and message and carried by share links: 1 to 64 bytes of valid UTF-8
// without control characters.
constexpr std::size_t kMaxProfileNameBytes = 64;
[[nodiscard]] bool is_valid_profile_name(std::string_view name);

// The profile as JSON text (every key), for `essi profile show` and round-trip tests.
[[nodiscard]] std::string profile_to_json(const Profile& profile);

}  // namespace essi
