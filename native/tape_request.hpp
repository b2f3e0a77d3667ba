// What the command line asks of a tape's reading: `--input essi|eia|auto` and `--profile NAME|FILE|auto`. The
// choice per tape (format from the content, dialect from the evidence) is the core's (essi/dialect.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "essi/dialect.hpp"

namespace essi::native {

struct TapeRequest {
    std::optional<InputFormat> input;  // nullopt: from the content (--input auto, the default)
    std::optional<Profile> profile;    // nullopt: from the evidence (--profile auto)
    std::string profile_name;          // what the reports call it: the profile's name or "auto"

    [[nodiscard]] TapeSetup setup(std::string_view bytes) const { return setup_tape(bytes, input, profile); }
};

// "essi", "eia" or "auto" (nullopt); false when the text is none of them.
[[nodiscard]] bool parse_input_format(std::string_view text, std::optional<InputFormat>& out);

}  // namespace essi::native
