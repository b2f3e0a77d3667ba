// What the command line asks of a tape's reading: `--input essi|eia|auto` and `--profile NAME|FILE|auto`. The
// choice per tape (format from the content, dialect from the evidence) is the core's (essi/dialect.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "essi/dialect.hpp"

namespace essi::native {

struct TapeRequest {
    std::optional<InputFormat> input;         // nullopt: from the content (--input auto, the default)
    std::optional<Profile> profile;           // nullopt: from the evidence (--profile auto)
    std::string profile_name;                 // what the reports call it: the profile's name or "auto"
    std::optional<std::size_t> max_per_code;  // --max-per-code (the server's max_per_code): over the profile's

    [[nodiscard]] TapeSetup setup(std::string_view bytes) const {
        TapeSetup s = setup_tape(bytes, input, profile);
        if (max_per_code) s.profile.max_per_code = *max_per_code;
        return s;
    }
};

}  // namespace essi::native
