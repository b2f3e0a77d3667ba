// Where a key of a profile's JSON text is, for the line and column of an E402 about it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace essi::profile_detail {

struct TextPosition {
    std::size_t line = 1, column = 1;  // 1-based; the column counts bytes
};

// The line and column of byte `offset` of `text` (lines end at '\n').
[[nodiscard]] TextPosition position_of(std::string_view text, std::size_t offset);

// Where the key `path` (a key of the top object, a key of its value, ...) is named in `text`, which is valid JSON:
// the byte offset of the opening quote of its last occurrence (the one a JSON parser keeps). When the object
// holds no such key, its parent's; nullopt when not even the first key is there.
[[nodiscard]] std::optional<std::size_t> key_offset(std::string_view text, const std::vector<std::string>& path);

}  // namespace essi::profile_detail
