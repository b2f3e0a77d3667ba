// The viewer's colours, in one place: motion kinds, markers, the selection, the background and the grid. The
// renderer's programs, the level of detail, the panels' legends and state().kind_colors all read them here.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "essi/diagnostics.hpp"
#include "essi/motion.hpp"

namespace essi::viewer {

struct Rgba {
    float r, g, b, a;
    bool operator==(const Rgba&) const = default;
};

inline constexpr std::size_t kMotionKinds = 4;  // MotionKind: Rapid, Travel, Cut, Mark
inline constexpr int kAllKindsMask = (1 << kMotionKinds) - 1;
[[nodiscard]] constexpr int kind_bit(MotionKind k) { return 1 << static_cast<int>(k); }

// Colours by MotionKind: rapid, travel, cut, mark (also used by the UI legend and the e2e test).
inline constexpr std::array<Rgba, kMotionKinds> kKindColors = {{
    {0.42f, 0.55f, 0.75f, 0.75f},  // rapid: blue-grey
    {0.55f, 0.62f, 0.70f, 0.75f},  // travel: grey
    {1.00f, 0.55f, 0.10f, 1.00f},  // cut: orange #ff8c1a
    {0.85f, 0.35f, 0.95f, 1.00f},  // mark: violet
}};
[[nodiscard]] constexpr const Rgba& kind_color(MotionKind k) { return kKindColors[static_cast<std::size_t>(k)]; }

// The kerf layers (docs/semantics.md §8), segments of the path program after the motion kinds: the compensated
// torch path (kind kKerfPathKind) and the band of the cut's width along it (kinds kKerfBandKind + k: the band of
// width DrawOptions::kerf_band_mm[k], k < kKerfBandWidths; a tape with more widths draws the rest as the last).
inline constexpr std::uint8_t kKerfPathKind = 4, kKerfBandKind = 5;
inline constexpr std::size_t kKerfBandWidths = 8;
inline constexpr std::size_t kPathColors = 6;  // the path program's colours: the motion kinds, kerf path, kerf band
inline constexpr int kKerfPathBit = 1 << kKerfPathKind, kKerfBandBit = 1 << kKerfBandKind;
inline constexpr int kAllPathMask = kAllKindsMask | kKerfPathBit | kKerfBandBit;
inline constexpr std::array<Rgba, kPathColors> kPathColorTable = {{
    kKindColors[0],
    kKindColors[1],
    kKindColors[2],
    kKindColors[3],
    {0.30f, 0.95f, 0.45f, 1.00f},  // kerf path: green, the torch's path
    {1.00f, 0.55f, 0.10f, 0.28f},  // kerf band: the cut's colour, translucent
}};

// Colour by (app/ColourBy.hpp): a cut's segments in colour bin b are of kind kColourByCutKind + b, a mark's of
// kColourByMarkKind + b; the bins are the ramp's colours, low to high.
inline constexpr std::size_t kColourBins = 16;
inline constexpr std::uint8_t kColourByCutKind = kKerfBandKind + kKerfBandWidths;
inline constexpr std::uint8_t kColourByMarkKind = kColourByCutKind + kColourBins;
// The ramp: "turbo" from blue to red, its darkest ends left out (bright on the dark and the light theme).
inline constexpr std::array<Rgba, kColourBins> kColourRamp = {{
    {0.27f, 0.40f, 0.92f, 1.00f},
    {0.21f, 0.55f, 0.98f, 1.00f},
    {0.16f, 0.69f, 0.92f, 1.00f},
    {0.15f, 0.81f, 0.80f, 1.00f},
    {0.19f, 0.91f, 0.67f, 1.00f},
    {0.29f, 0.97f, 0.53f, 1.00f},
    {0.43f, 0.99f, 0.41f, 1.00f},
    {0.60f, 0.98f, 0.31f, 1.00f},
    {0.76f, 0.93f, 0.24f, 1.00f},
    {0.90f, 0.84f, 0.19f, 1.00f},
    {1.00f, 0.72f, 0.15f, 1.00f},
    {1.00f, 0.58f, 0.13f, 1.00f},
    {0.99f, 0.43f, 0.10f, 1.00f},
    {0.90f, 0.28f, 0.07f, 1.00f},
    {0.76f, 0.15f, 0.04f, 1.00f},
    {0.63f, 0.07f, 0.00f, 1.00f},
}};

// The point markers (the marker program's `type`, a texel's third value): pierces, the start point, the playback
// tool, and a mark per diagnostic in its severity's colour (Error, Warning, Note: the diagnostics' marks).
enum class MarkerType { Pierce = 0, Start = 1, Tool = 2, Error = 3, Warning = 4, Note = 5 };
inline constexpr std::size_t kMarkerTypes = 6;
// Marker masks (DrawOptions::marker_mask, the shader's u_type_mask): a bit per MarkerType.
[[nodiscard]] constexpr int marker_bit(MarkerType t) { return 1 << static_cast<int>(t); }
inline constexpr int kAllMarkersMask = (1 << kMarkerTypes) - 1;
inline constexpr int kDiagnosticMarkersMask =
    marker_bit(MarkerType::Error) | marker_bit(MarkerType::Warning) | marker_bit(MarkerType::Note);
[[nodiscard]] constexpr MarkerType severity_marker(Severity s) {
    return s == Severity::Error ? MarkerType::Error : s == Severity::Warning ? MarkerType::Warning : MarkerType::Note;
}

// Colours by MarkerType. The severities' are the problems list's (severity_color).
inline constexpr std::array<Rgba, kMarkerTypes> kMarkerColors = {{
    {1.0f, 0.25f, 0.2f, 1.0f},  // pierce: red ring (and the pierce cells of the level of detail)
    {0.3f, 0.95f, 0.4f, 1.0f},  // start: green disc
    {1.0f, 1.0f, 1.0f, 1.0f},   // tool: white ring + cross
    {1.0f, 0.4f, 0.35f, 1.0f},  // error: a disc with a cross
    {1.0f, 0.8f, 0.3f, 1.0f},   // warning: a disc
    {0.6f, 0.8f, 1.0f, 1.0f},   // note: a ring
}};
[[nodiscard]] constexpr const Rgba& marker_color(MarkerType t) { return kMarkerColors[static_cast<std::size_t>(t)]; }
[[nodiscard]] constexpr const Rgba& severity_rgba(Severity s) { return marker_color(severity_marker(s)); }

inline constexpr Rgba kBackground = {0.11f, 0.12f, 0.14f, 1.f};  // (the dark theme's)
inline constexpr Rgba kSelectionColor = {0.25f, 0.95f, 1.0f, 1.f};
// The grid's lines (the grid program).
inline constexpr Rgba kGridMinor = {0.5f, 0.55f, 0.6f, 0.10f};
inline constexpr Rgba kGridMajor = {0.5f, 0.55f, 0.6f, 0.25f};
inline constexpr Rgba kGridAxis = {0.6f, 0.8f, 0.6f, 0.45f};

// The colours a theme changes (docs/viewer.md, "Themes"): the drawing's background, the grid, the playback tool's
// marker and the overlays' text; the paths keep their colours (they read on both).
struct Theme {
    bool light = false;
    Rgba background, grid_minor, grid_major, grid_axis, tool;
    Rgba label, scale_bar;  // grid labels, the scale bar
};
inline constexpr Theme kDarkTheme = {false,
                                     kBackground,
                                     kGridMinor,
                                     kGridMajor,
                                     kGridAxis,
                                     kMarkerColors[2],
                                     {0.59f, 0.63f, 0.67f, 0.63f},
                                     {0.9f, 0.9f, 0.9f, 0.86f}};
inline constexpr Theme kLightTheme = {true,
                                      {0.97f, 0.97f, 0.96f, 1.f},
                                      {0.15f, 0.2f, 0.25f, 0.10f},
                                      {0.15f, 0.2f, 0.25f, 0.25f},
                                      {0.2f, 0.5f, 0.2f, 0.5f},
                                      {0.1f, 0.1f, 0.12f, 1.f},
                                      {0.25f, 0.28f, 0.32f, 0.8f},
                                      {0.1f, 0.1f, 0.12f, 0.9f}};

}  // namespace essi::viewer
