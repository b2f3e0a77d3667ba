// Phase 3, geom: where the program lies on the machine (docs/semantics.md §12, the ISG chain):
//
//   machine = zero offset + R(plate rotation) · program − tool offset
//
// `program` is a motion stream position (83 origin and the 21-28 mapping applied, in mm); the zero offset is the
// profile's active `zero_offsets` entry; R turns counter-clockwise by `plate_rotation_deg` about the program
// origin; the tool offset is where the tool in use sits from the centre torch (11 the marker's, 114 the powder
// marker's, 12 none): the carriage moves by minus it so that the tool is over the contour.
#pragma once

#include <array>

#include "essi/geom.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"

namespace essi {

class Placement {
public:
    explicit Placement(const Profile& profile);

    [[nodiscard]] Point machine(Point program, Point tool_offset = {}) const {
        return {zero_.x + c_ * program.x - s_ * program.y - tool_offset.x,
                zero_.y + s_ * program.x + c_ * program.y - tool_offset.y};
    }
    // A machine position in program coordinates (no tool offset): R(-plate rotation) · (machine - zero offset).
    [[nodiscard]] Point program(Point machine) const {
        const double x = machine.x - zero_.x, y = machine.y - zero_.y;
        return {c_ * x + s_ * y, -s_ * x + c_ * y};
    }
    // The table's corners (machine coordinates, counter-clockwise from its minimum) in program coordinates.
    [[nodiscard]] std::array<Point, 4> table_in_program(const TableLimits& t) const {
        return {program({t.min_x_mm, t.min_y_mm}), program({t.max_x_mm, t.min_y_mm}), program({t.max_x_mm, t.max_y_mm}),
                program({t.min_x_mm, t.max_y_mm})};
    }
    // The whole motion in machine coordinates (points, centre, parabola and torch step turned and moved).
    [[nodiscard]] MotionRecord machine(const MotionRecord& m, Point tool_offset) const;
    // The exact machine box of a motion.
    [[nodiscard]] Box machine_box(const MotionRecord& m, Point tool_offset) const;
    // A box in program coordinates moved to the machine: exact only when the plate is not turned. (Inline: the
    // interpreter's table check asks it for every motion.)
    [[nodiscard]] Box moved(const Box& program, Point tool_offset) const {
        if (program.empty) return program;
        const double dx = zero_.x - tool_offset.x, dy = zero_.y - tool_offset.y;
        return {program.min_x + dx, program.min_y + dy, program.max_x + dx, program.max_y + dy, false};
    }
    [[nodiscard]] bool turns() const { return turns_; }
    [[nodiscard]] Point zero_offset() const { return zero_; }
    // A program direction in machine axes: R(plate rotation) · v.
    [[nodiscard]] Point turn(Point v) const { return {c_ * v.x - s_ * v.y, s_ * v.x + c_ * v.y}; }

private:
    Point zero_;
    double c_ = 1, s_ = 0;
    bool turns_ = false;
};

// A MotionSink that passes what it gets to `out` in machine coordinates (`essi trace --machine`): it follows the
// tool offset functions itself (their events).
class MachineSink final : public MotionSink {
public:
    MachineSink(MotionSink& out, const Profile& profile) : out_(out), profile_(profile), placement_(profile) {}
    void on_motion(const MotionRecord& m) override { out_.on_motion(placement_.machine(m, tool_offset_)); }
    void on_event(const MachineEvent& e) override;

private:
    MotionSink& out_;
    const Profile& profile_;
    Placement placement_;
    Point tool_offset_;
};

// The tool offset in force after machine function `code` (11: the marker's, 114: the powder marker's, 12 and a 63
// that cancels the stored functions: none); `current` for any other code.
[[nodiscard]] Point tool_offset_after(const Profile& profile, int code, Point current);

}  // namespace essi
