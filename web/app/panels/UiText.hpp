// Text and colour helpers of the panels.
#pragma once

#include <imgui.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

#include "app/Format.hpp"
#include "essi/diagnostics.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

// "1:02:03" (hours, minutes, seconds).
[[nodiscard]] std::string hms(double seconds);
// A file size as people read it: "840 bytes", "12.4 KB", "133.5 MB".
[[nodiscard]] std::string size_text(std::size_t bytes);
// Printable form of a source line (binary files must not break the text renderer).
[[nodiscard]] std::string printable(std::string_view s, std::size_t max = 400);
// A progress (0..1) as shown: in steps of 2 %, so that a frame whose panels did not change is not drawn again
// (App::render); on a CPU renderer every frame drawn is time the browser's compositor takes from the work.
[[nodiscard]] float stepped(float progress);

// After an item: the next one, `width` wide, on the same line when it fits in the window's width, else below.
void same_line_if_fits(float width);
// Text in the disabled colour, wrapped at the window's edge (hints in a narrow panel, any language).
void hint_wrapped(const char* text);
// Where a tooltip's text wraps (its window's x): at 32 ems, or narrower to stay inside a narrow screen.
[[nodiscard]] float tooltip_wrap_x();
// A tooltip of one text, wrapped at tooltip_wrap_x.
void wrapped_tooltip(const std::string& text);

[[nodiscard]] ImVec4 severity_color(Severity s);
[[nodiscard]] inline ImVec4 to_vec4(const Rgba& c) { return ImVec4(c.r, c.g, c.b, c.a); }
[[nodiscard]] inline ImVec4 opaque(const Rgba& c) { return ImVec4(c.r, c.g, c.b, 1); }
[[nodiscard]] inline ImU32 to_u32(const Rgba& c) { return ImGui::ColorConvertFloat4ToU32(to_vec4(c)); }

// Colours of the panels' text.
inline constexpr Rgba kOkColor = {0.5f, 0.9f, 0.5f, 1};     // "ok", "No problems found."
inline constexpr Rgba kMessageColor = {0.6f, 0.85f, 1, 1};  // toolbar messages, the Help window's keys
inline constexpr Rgba kLineNumberColor = {0.5f, 0.5f, 0.55f, 1};

}  // namespace essi::viewer
