// Compare mode (docs/viewer.md, "Compare two revisions"): a second tape (B) beside the loaded one (A), compared
// contour by contour by the core (essi/diff.hpp, as `essi diff`); B's contours are drawn over A's in their own
// colour and the differences are listed, each one click from its contour.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "essi/diff.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer {

struct Document;

struct Compare {
    std::string name;   // B's
    TapeContours a, b;  // with their paths
    TapeDiff diff;
    std::string summary;  // "2 same, 1 moved, ..." in English (state()); the window words it in the viewer's language
    // Each contour flattened for drawing (program mm): A's, B's.
    std::vector<std::vector<Point>> a_lines, b_lines;
};

// Contours are kept flattened within this for drawing (mm): a hair at any useful zoom; closer, the contours in view
// are flattened again (flatten_contour) within kCompareMaxSagittaPx.
constexpr double kCompareChordMm = 0.05;
constexpr double kCompareMaxSagittaPx = 0.5;
// Contour `c` flattened within `chord_mm` into `out` (emptied first; program mm).
void flatten_contour(const DiffContour& c, double chord_mm, std::vector<Point>& out);

// A compared with B (`bytes`, read with A's profile, or by its own evidence when A's is auto).
[[nodiscard]] std::unique_ptr<Compare> make_compare(const Document& a, bool auto_profile, std::string name,
                                                    const std::string& bytes);

// The mode: the next tape opened (dropped, Open..., essikit.compare) is compared with the one shown instead of
// replacing it; the comparison stays until the mode is left or another tape is loaded.
class CompareMode {
public:
    CompareMode(Navigation& navigation, Notices& notices, UiFonts& fonts)
        : navigation_(navigation), notices_(notices), fonts_(fonts) {}

    // The next tape opened is B (`a`: the tape shown; none: a message that one must be loaded first).
    void begin(const Document* a);
    // A compared with B (`bytes`: read with A's profile, or by its own evidence when A's is auto).
    void compare_with(const Document* a, bool auto_profile, std::string name, const std::string& bytes);
    void end();
    // Another tape is loaded: the comparison was of the one before.
    void forget() { compare_.reset(); }
    [[nodiscard]] const Compare* result() const { return compare_.get(); }
    [[nodiscard]] bool pending() const { return next_; }
    // Shows a difference: A's contour's lines selected (when A has it), the view on A's and B's contours together.
    void show_difference(const ContourDiff& d);

private:
    Navigation& navigation_;
    Notices& notices_;
    UiFonts& fonts_;
    std::unique_ptr<Compare> compare_;  // the other revision and the differences
    bool next_ = false;                 // the next tape opened is the other revision
};

}  // namespace essi::viewer
