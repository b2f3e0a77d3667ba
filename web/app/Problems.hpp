// The diagnostics on the drawing (docs/viewer.md, "Problems on the drawing"): the mark under the mouse, what the
// problems-only view draws in full, and what a hovered or selected diagnostic highlights (its block and contour in
// its severity's colour, its related places lighter). Where a mark goes is the core's rule
// (essi/diagnostic_marks.hpp, through Document::place_diagnostics); the marks themselves are markers of the
// renderer (MarkerType::Error, Warning, Note), a constant size on the screen.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "app/Document.hpp"
#include "app/View.hpp"
#include "render/PathBuffers.hpp"
#include "render/Renderer.hpp"

namespace essi::viewer {

inline constexpr std::size_t kNoMark = ~std::size_t(0);
// A mark is under the mouse this far from its centre (window pixels): its radius and a little more.
inline constexpr double kMarkHitRadiusPx = Renderer::kMarkRadiusPx + 2;
// The highlights: the block and contour concerned, the related places (lighter, thinner), wider than a line.
inline constexpr float kContourHighlightAlpha = 0.85f, kContourHighlightExtraPx = 2.5f;
inline constexpr float kRelatedHighlightAlpha = 0.45f, kRelatedHighlightExtraPx = 1.5f;

// Where a mark is drawn (window pixels).
[[nodiscard]] Point mark_screen(const Document& doc, const View& view, const DiagnosticMark& mark);
// The marks (indices in doc.marks) within kMarkHitRadiusPx of (sx, sy), the nearest first.
[[nodiscard]] std::vector<std::size_t> marks_near(const Document& doc, const View& view, double sx, double sy);
// The nearest of them, or kNoMark.
[[nodiscard]] std::size_t mark_at(const Document& doc, const View& view, double sx, double sy);
// The diagnostics (indices in doc.diagnostics) the hovered mark and the selected line make active: the hovered one,
// and those of the selected line.
[[nodiscard]] std::vector<std::size_t> active_diagnostics(const Document& doc, std::size_t hovered_mark,
                                                          std::uint32_t selected_line);
// The segments of the motions the diagnostics concern (the problems-only view draws them in full).
[[nodiscard]] std::vector<SegmentRun> concerned_runs(const Document& doc, const PathBuffers& buffers);
// The highlights of the active diagnostics: their blocks and contours, their related places.
[[nodiscard]] std::vector<Highlight> diagnostic_highlights(const Document& doc, const PathBuffers& buffers,
                                                           const std::vector<std::size_t>& active);

}  // namespace essi::viewer
