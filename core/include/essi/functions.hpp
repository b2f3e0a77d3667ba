// The machine function table: what every ISO 6582 Annex B code (0-115) and every Woyda extension means,
// in words, for diagnostics, the trace and the viewer's block inspector. One table, one place: the codes in
// core/interp/function_table.def, their words in the message catalogue (core/i18n/messages/functions.def) in
// English, German and Chinese.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "essi/i18n.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"

namespace essi {

enum class FunctionValue : std::uint8_t {
    None,      // takes no value
    Optional,  // 39, 41, 29, 30: a value may follow
    Required,  // 135, 136
};

struct FunctionInfo {
    int code = 0;
    std::string_view name;         // "Oxygen ON" (English: text(name_msg, Lang::En))
    std::string_view explanation;  // "cutting oxygen on (tool 1)" (English: text(explanation_msg, Lang::En))
    FunctionValue value = FunctionValue::None;
    std::string_view value_unit;      // "mm/min", "s", "unit increments", "" (English: text(unit_msg, Lang::En))
    Msg name_msg = Msg::None;         // the name in the catalogue, for any language
    Msg explanation_msg = Msg::None;  // the explanation in the catalogue
    Msg unit_msg = Msg::None;         // the value's unit in the catalogue (Msg::None: no unit)
    bool assigned = true;             // false: 'Unassigned' in Annex B or unknown in the dialect
    bool manufacturer = false;        // 55-62 in ISO: specified by the manufacturer
    bool drawing_machine = false;     // 70-74, 76-79, 84-86, 89-90, 93-98: for drawing machines
};

// The values a function with a value allows (E216 beyond them), in the unit of `unit`: as written (mm/min,
// count), mm (the value is in unit increments: times unit_mm), or seconds (times the profile's dwell_unit_s).
enum class RangeUnit : std::uint8_t { AsWritten, Mm, Seconds };
struct FunctionValueRange {
    double min = 0, max = 0;
    RangeUnit unit = RangeUnit::AsWritten;
};
[[nodiscard]] std::optional<FunctionValueRange> function_value_range(int code);

// What a dialect's code does in ISO terms (ESSI_ACTS_AS in function_table.def): Hypertherm's 53 is ISO's 7.
struct FunctionAction {
    int action = 0;        // the ISO code it acts as, or an action of its own (>= fn::kFirstAction)
    int fixed_value = -1;  // >= 0: the value it acts with (Hypertherm 15 = 11+2); else its own value
};
// nullopt: the code means in `dialect` what it means in ISO 6582 (or nothing).
[[nodiscard]] std::optional<FunctionAction> function_action(int code, Dialect dialect);

// The meaning of `code` in `dialect`; nullopt for codes beyond the table (> 999 cannot be read anyway).
[[nodiscard]] std::optional<FunctionInfo> function_info(int code, Dialect dialect);

// A kerf value in words that say what it is, as the profile reads it (`kerf_value`): "kerf width 2 mm (the torch
// 1 mm to the side)" or "kerf offset 1 mm (a cut 2 mm wide)"; in `lang` (numbers as in English).
[[nodiscard]] std::string kerf_value_text(double value_mm, const Profile& profile, Lang lang = Lang::En);
// The torch's offset of a compensated motion in words: "torch 1.000 mm to the left (a cut 2.000 mm wide)".
[[nodiscard]] std::string kerf_offset_text(KerfSide side, double offset_mm, Lang lang = Lang::En);

// A sentence that says what a function block does, in `lang`: "function 29: Left kerf compensation ON, kerf
// width 3 mm (the torch 1.5 mm to the side): kerf compensation left of the direction of travel".
[[nodiscard]] std::string describe_function(int code, bool has_value, double value, const Profile& profile,
                                            Lang lang = Lang::En);

}  // namespace essi
