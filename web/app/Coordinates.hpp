// The coordinates the viewer shows its numbers and its grid in (docs/viewer.md, "Coordinates"): the tape's
// program coordinates, or the machine's: where the contours lie on the table, the placement of docs/semantics.md
// §12 (essi::Placement: zero offset + R(plate rotation) · program) without a tool offset.
#pragma once

#include <optional>

#include "app/View.hpp"
#include "essi/placement.hpp"
#include "essi/profile.hpp"

namespace essi::viewer {

class Coordinates {
public:
    Coordinates() = default;                                                          // program coordinates
    explicit Coordinates(const Profile& profile) : placement_(Placement(profile)) {}  // machine coordinates

    [[nodiscard]] bool machine() const { return placement_.has_value(); }
    [[nodiscard]] const char* name() const { return machine() ? "machine" : "program"; }
    // A program position (mm, absolute) as shown, and back.
    [[nodiscard]] Point shown(Point program) const { return placement_ ? placement_->machine(program) : program; }
    [[nodiscard]] Point program(Point shown) const { return placement_ ? placement_->program(shown) : shown; }
    // A program direction as shown (a difference of two positions: the plate's rotation only).
    [[nodiscard]] Point shown_direction(Point v) const { return placement_ ? placement_->turn(v) : v; }
    // The rotation from program to shown axes (View::plate).
    [[nodiscard]] Rotation plate() const {
        const Point u = shown_direction({1, 0});
        return {u.x, u.y};
    }

private:
    std::optional<Placement> placement_;
};

}  // namespace essi::viewer
