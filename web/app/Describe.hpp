// A motion and a block in words, as the block inspector, the copied inspector text and state().inspector say them
// ("cut arc CCW r=50.0 mm, centre (10.0, 20.0), ..."), and the panels' words for kinds, curves and tools; in the
// viewer's language (the catalogue's rows, essi/i18n.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/Document.hpp"
#include "essi/i18n.hpp"

namespace essi::viewer {

// In words, for the block inspector: "cut arc CCW r=50.0 mm, centre (10.0, 20.0), sweep 90.0°, 78.5 mm".
[[nodiscard]] std::string describe_motion(const MotionRecord& m, Lang lang = Lang::En);
// The meaning of block i of `tape`: describe_function for function blocks, the kind for the others.
[[nodiscard]] std::string describe_block(const Tape& tape, std::size_t block_index, const Profile& profile,
                                         Lang lang = Lang::En);
// The words the panels use for a motion's kind ("cut"), its curve ("arc") and its tools ("oxygen+punch", "-" for
// none), in `lang` (English: the core's names, motion_kind_name and the rest).
[[nodiscard]] const char* motion_kind_text(MotionKind kind, Lang lang);
[[nodiscard]] const char* curve_kind_text(CurveKind curve, Lang lang);
[[nodiscard]] std::string tools_label(std::uint8_t tools, Lang lang);

// One sentence of the block inspector: about a block, a motion, or the torch's path where kerf compensation is on.
struct InspectorLine {
    enum class Of : std::uint8_t { Block, Motion, Torch } of;
    MotionKind kind;  // (a motion's)
    std::string text;
};
inline constexpr std::size_t kInspectorMotions = 8;
// The block inspector's sentences for one line of `doc`: its blocks, its motions (at most kInspectorMotions) and the
// torch's path where kerf compensation is on ("torch (kerf): ...").
[[nodiscard]] std::vector<InspectorLine> inspector_lines(const Document& doc, std::uint32_t line, Lang lang = Lang::En);

}  // namespace essi::viewer
