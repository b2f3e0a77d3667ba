// A plate's remnant (essi/parts.hpp, docs/semantics.md §9): the largest rectangle at the plate's far end in x that
// no part outline (with its kerf) reaches.
#pragma once

#include <optional>
#include <vector>

#include "essi/geom.hpp"
#include "essi/motion.hpp"

namespace essi::parts {

// `outlines`: the parts' outlines as polygons; `margin`: how far from them the rectangle stays (the kerf). None when
// the parts reach the far end along its whole height.
[[nodiscard]] std::optional<Box> remnant(const Box& plate, const std::vector<std::vector<Point>>& outlines,
                                         double margin);

}  // namespace essi::parts
