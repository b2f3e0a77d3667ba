// A tape's drawing as DXF (R12 ASCII, AC1009), for CAD: `essi render --format dxf` and the viewer's download.
// Layers CUT, MARK, TRAVEL (rapid and other travel) and DIAGNOSTICS (a point and a short text "E301 line 12"
// where each diagnostic's line moves to); LINE and ARC entities in mm (docs/cli.md, "DXF").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "essi/dialect.hpp"
#include "essi/diagnostics.hpp"

namespace essi {

struct DxfResult {
    std::string text;
    std::vector<Diagnostic> diagnostics;  // the tape's check (sorted)
};

// Lines as LINE; arcs as ARC (counter-clockwise from the start angle to the end angle, as DXF draws them: a
// clockwise arc is written from its end to its start; a full circle as two half arcs); parabolas flattened into
// LINEs within the profile's chord tolerance; a cut made by several torches once per torch.
[[nodiscard]] DxfResult render_dxf(std::string_view bytes, const TapeSetup& setup);

}  // namespace essi
