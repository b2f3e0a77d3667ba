// The motion stream's vocabulary (essi/motion.hpp): the record a UnitLine stands for, and the names of kinds,
// curves, kerf sides and tools that the trace, the reports and the viewer print.
#include "essi/motion.hpp"

#include <cstddef>
#include <vector>

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

void MotionBuffer::replay(MotionSink& sink) const {
    // (pointers held here: the sink's calls could change the vectors for all the compiler knows, so it would read
    // them from this object again at every item)
    const UnitLine* line = lines_.data();
    const MotionRecord* motion = motions_.data();
    const MachineEvent* event = events_.data();
    for (const Item *item = order_.data(), *end = item + order_.size(); item != end; ++item) {
        switch (*item) {
            case Item::Line: sink.on_line(*line++); break;
            case Item::Motion: sink.on_motion(*motion++); break;
            case Item::Event: sink.on_event(*event++); break;
        }
    }
}

void MotionBuffer::clear() {
    order_.clear();
    lines_.clear();
    motions_.clear();
    events_.clear();
}

std::size_t MotionBuffer::memory_bytes() const {
    return order_.capacity() * sizeof(Item) + lines_.capacity() * sizeof(UnitLine) +
           motions_.capacity() * sizeof(MotionRecord) + events_.capacity() * sizeof(MachineEvent);
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

namespace {
// Each tool bit: its name in the trace (an identifier) and in messages (the catalogue).
constexpr struct {
    std::uint8_t bit;
    const char* name;
    Msg word;
} kToolNames[] = {{kToolOxygen, "oxygen", Msg::ToolOxygen},
                  {kToolLeftBevel, "left-bevel", Msg::ToolLeftBevel},
                  {kToolRightBevel, "right-bevel", Msg::ToolRightBevel},
                  {kToolPlasma, "plasma", Msg::ToolPlasma},
                  {kToolPunch, "punch", Msg::ToolPunch},
                  {kToolLineMarker, "line-marker", Msg::ToolLineMarker},
                  {kToolFive, "tool5", Msg::ToolFive}};
}  // namespace

std::string tools_text(std::uint8_t tools) {
    std::string s;
    for (const auto& n : kToolNames) {
        if (!(tools & n.bit)) continue;
        if (!s.empty()) s += '+';
        s += n.name;
    }
    return s.empty() ? "-" : s;
}

MessageArgs::Arg tools_arg(std::uint8_t tools) {
    std::vector<Msg> words;
    for (const auto& n : kToolNames)
        if (tools & n.bit) words.push_back(n.word);
    return MessageArgs::Arg::combined(words);
}

void save_motion_record(WireWriter& out, const MotionRecord& r) {
    out.put_all(r.line, r.block, r.kind, r.curve, r.tools, r.head, r.kerf, r.ccw, r.start, r.end, r.centre, r.radius,
                r.end_radius, r.sweep, r.parabola, r.length_mm, r.feed_mm_min, r.kerf_mm, r.torches, r.torch_step);
}

bool restore_motion_record(WireReader& in, MotionRecord& r) {
    return in.get_all(r.line, r.block, r.kind, r.curve, r.tools, r.head, r.kerf, r.ccw, r.start, r.end, r.centre,
                      r.radius, r.end_radius, r.sweep, r.parabola, r.length_mm, r.feed_mm_min, r.kerf_mm, r.torches,
                      r.torch_step);
}

}  // namespace essi
