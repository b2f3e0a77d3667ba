// Phase 6, write: a tape's motion stream written in another format (docs/conversions.md). `essi convert` and
// `/api/convert` call convert_tape; the writers (core/write/, one file per target) are MotionSinks fed by the
// interpreter, so a conversion writes what the machine does: 21-28, 83 and 81/82 are applied (the output is in
// machine axes, incremental or absolute as asked), every other function is carried over by the target's table
// or kept as a comment and reported.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/dialect.hpp"
#include "essi/profile.hpp"

namespace essi {

enum class OutputFormat : std::uint8_t { Essi, Eia, Gcode };
inline constexpr OutputFormat kOutputFormats[] = {OutputFormat::Essi, OutputFormat::Eia, OutputFormat::Gcode};
[[nodiscard]] const char* output_format_name(OutputFormat f);  // "essi", "eia", "gcode"
// The format a name names (output_format_name's), nullopt for any other text.
[[nodiscard]] std::optional<OutputFormat> parse_output_format(std::string_view name);

struct ConvertOptions {
    OutputFormat to = OutputFormat::Essi;
    Profile target;         // the dialect written (units, end code, EIA table)
    bool absolute = false;  // 82 / G92 (Woyda) / G90 instead of incremental
    bool force = false;     // write a tape that has errors too (--force): what the machine would run of it
};

struct ConvertResult {
    std::string text;                     // the converted program (empty when refused)
    std::vector<Diagnostic> diagnostics;  // the source's check (as essi check has it) and the conversion's
                                          // warnings (W5xx), sorted
    bool refused = false;                 // the tape has errors and options.force was not given: nothing written
    [[nodiscard]] bool ok() const;        // no error
};

// Checks `bytes` as `source` says (check_tape: every rule, the kerf path and the cut plan included); when the tape
// has no error, or options.force, runs the program and writes it in options.to. Never throws.
[[nodiscard]] ConvertResult convert_tape(std::string_view bytes, const TapeSetup& source,
                                         const ConvertOptions& options);

}  // namespace essi
