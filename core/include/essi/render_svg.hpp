// `essi render`: a tape as an SVG picture (preview next to a CI failure). Cut, mark, travel and rapid motion in
// their colours, pierce markers, every diagnostic marked where it is (essi/diagnostic_marks.hpp: a mark of a
// constant size in the SVG's pixels, its message as a tooltip, its contour and related places highlighted, a
// collision's overlapping area filled), and a legend with the file name and the key numbers (cut length, pierces,
// time). Machine y points up (the SVG is flipped).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/report.hpp"

namespace essi {

// The colours (also used by the tests and docs/cli.md).
constexpr std::string_view kSvgCutColor = "#d62728";
constexpr std::string_view kSvgMarkColor = "#1f77b4";
constexpr std::string_view kSvgTravelColor = "#7f7f7f";
constexpr std::string_view kSvgRapidColor = "#bcbd22";
constexpr std::string_view kSvgPierceColor = "#ff7f0e";
constexpr std::string_view kSvgErrorColor = "#e000e0";
constexpr std::string_view kSvgWarningColor = "#e6a100";
constexpr std::string_view kSvgNoteColor = "#17becf";
constexpr std::string_view kSvgKerfColor = "#2ca02c";      // the compensated torch path (kerf layer)
constexpr std::string_view kSvgKerfBandColor = "#d62728";  // the cut's real width, translucent
constexpr std::string_view kSvgRemnantColor = "#9467bd";   // a plate's remnant (and the plate's outline)

struct RenderOptions {
    std::string title;        // shown in the legend (the file name)
    double width_px = 1200;   // the SVG's width attribute; height follows the aspect ratio
    bool show_travel = true;  // travel and rapid motion
    // A part of the drawing (program mm): the picture shows this box (the viewer's view), the legend below it;
    // none: the whole tape with a margin.
    std::optional<Box> view;
    // Draw the marks of these diagnostics instead of the check's (a list made elsewhere; the tests).
    std::optional<std::vector<Diagnostic>> diagnostics;
    // The problems only: everything not concerned by a diagnostic drawn faint (kSvgDimOpacity).
    bool problems_only = false;
    // Each plate (essi/parts.hpp: plate_mm, or its parts' box) outlined and its remnant drawn: the parts list made
    // for it (RenderResult::result.parts).
    bool remnant = false;
};

// The marks' radius in the SVG's pixels (its width attribute): the same size at any extent.
constexpr double kSvgMarkRadiusPx = 6;
// The opacity of what no diagnostic concerns, with RenderOptions::problems_only.
constexpr double kSvgDimOpacity = 0.2;

struct RenderResult {
    std::string svg;
    CheckResult result;  // the check of the tape (diagnostics, stats)
};

// Checks the tape and draws it. Arcs and parabolas are flattened to polylines within a tolerance of
// 1/4000 of the drawing's extent (at least the profile's chord tolerance).
[[nodiscard]] RenderResult render_svg(std::string_view bytes, const Profile& profile, const RenderOptions& options,
                                      InputFormat format = InputFormat::Essi);

}  // namespace essi
