// Compare mode (docs/viewer.md, "Compare two revisions"): a second tape (B) beside the loaded one (A), compared
// contour by contour by the core (essi/diff.hpp, as `essi diff`); B's contours are drawn over A's in their own
// colour and the differences are listed, each one click from its contour.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "essi/diff.hpp"

namespace essi::viewer {

struct Document;

struct Compare {
    std::string name;     // B's
    TapeContours a, b;    // with their paths
    TapeDiff diff;
    std::string summary;  // "2 same, 1 moved, ..." in English (state()); the window words it in the viewer's language
    // Each contour flattened for drawing (program mm): A's, B's.
    std::vector<std::vector<Point>> a_lines, b_lines;
};

// A compared with B (`bytes`, read with A's profile, or by its own evidence when A's is auto).
[[nodiscard]] std::unique_ptr<Compare> make_compare(const Document& a, bool auto_profile, std::string name,
                                                    const std::string& bytes);

}  // namespace essi::viewer
