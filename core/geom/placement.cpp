// The placement of the program on the machine (essi/placement.hpp).
#include "essi/placement.hpp"

#include <cmath>

#include "essi/function_codes.hpp"

namespace essi {

Placement::Placement(const Profile& profile) : zero_(profile.active_zero_offset()) {
    const double a = profile.plate_rotation_deg * kPi / 180;
    turns_ = std::fmod(profile.plate_rotation_deg, 360.0) != 0;
    c_ = turns_ ? std::cos(a) : 1;
    s_ = turns_ ? std::sin(a) : 0;
}

MotionRecord Placement::machine(const MotionRecord& m, Point tool_offset) const {
    MotionRecord r = m;
    r.start = machine(m.start, tool_offset);
    r.end = machine(m.end, tool_offset);
    r.centre = machine(m.centre, tool_offset);
    r.parabola.vertex = machine(m.parabola.vertex, tool_offset);
    r.parabola.u = turn(m.parabola.u);
    r.parabola.n = turn(m.parabola.n);
    r.torch_step = turn(m.torch_step);
    return r;  // (a turn keeps sweeps, senses and lengths)
}

Box Placement::machine_box(const MotionRecord& m, Point tool_offset) const {
    if (!turns_) return moved(bounding_box(m), tool_offset);
    return bounding_box(machine(m, tool_offset));
}

void MachineSink::on_event(const MachineEvent& e) {
    MachineEvent placed = e;
    if (e.kind == EventKind::Function) tool_offset_ = tool_offset_after(profile_, e.code, tool_offset_);
    if (e.kind == EventKind::ZeroOffset) {
        const Point o = placement_.machine(Point{e.x, e.y}, tool_offset_);
        placed.x = o.x;
        placed.y = o.y;
    }
    out_.on_event(placed);
}

Point tool_offset_after(const Profile& profile, int code, Point current) {
    switch (code) {
        case fn::kPunchMarkingOffsetOn: return profile.marker_offset;
        case fn::kLineMarkingOffsetOn: return profile.powder_marker_offset;
        case fn::kToolOffsetOff:
        case fn::kCancelFunctions:
        case fn::kEndOfTape: return {};  // (63/64 that cancel the stored functions)
        default: return current;
    }
}

}  // namespace essi
