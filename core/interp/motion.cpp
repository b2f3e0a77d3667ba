// The motion stream's vocabulary (essi/motion.hpp): the record a UnitLine stands for, and the names of kinds,
// curves, kerf sides and tools that the trace, the reports and the viewer print.
#include "essi/motion.hpp"

#include <cstddef>

namespace essi {

namespace {

// names[e], or "?" for a value beyond the table.
template <class Enum, std::size_t N>
const char* name_in(Enum e, const char* const (&names)[N]) {
    const auto i = static_cast<std::size_t>(e);
    return i < N ? names[i] : "?";
}

}  // namespace

MotionRecord record_of(const UnitLine& l) {
    MotionRecord m;
    m.line = l.line;
    m.block = l.block;
    m.kind = l.kind;
    m.curve = CurveKind::Line;
    m.tools = l.tools;
    m.head = 1;
    m.kerf = l.kerf;
    m.start = l.start;
    m.end = l.end;
    m.length_mm = l.length_mm;
    m.feed_mm_min = l.feed_mm_min;
    m.kerf_mm = l.kerf_mm;
    return m;
}

const char* motion_kind_name(MotionKind k) {
    static constexpr const char* kNames[] = {"rapid", "travel", "cut", "mark"};  // MotionKind's order
    return name_in(k, kNames);
}

const char* curve_kind_name(CurveKind k) {
    static constexpr const char* kNames[] = {"line", "arc", "parabola"};
    return name_in(k, kNames);
}

const char* kerf_side_name(KerfSide k) {
    static constexpr const char* kNames[] = {"off", "left", "right"};
    return name_in(k, kNames);
}

std::string tools_text(std::uint8_t tools) {
    static constexpr struct {
        std::uint8_t bit;
        const char* name;
    } kNames[] = {{kToolOxygen, "oxygen"},   {kToolLeftBevel, "left-bevel"}, {kToolRightBevel, "right-bevel"},
                  {kToolPlasma, "plasma"},   {kToolPunch, "punch"},          {kToolLineMarker, "line-marker"},
                  {kToolFive, "tool5"}};
    std::string s;
    for (const auto& n : kNames) {
        if (!(tools & n.bit)) continue;
        if (!s.empty()) s += '+';
        s += n.name;
    }
    return s.empty() ? "-" : s;
}

}  // namespace essi
