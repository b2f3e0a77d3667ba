// The canonical motion stream: what the interpreter emits and every consumer (check, stats, trace,
// viewer, renderers) reads. Positions are machine coordinates in mm (after 21-28, 83 and the setup
// offset), before kerf compensation.
#pragma once

#include "essi/i18n.hpp"
#include "essi/wire.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace essi {

struct Point {
    double x = 0, y = 0;
    friend bool operator==(const Point&, const Point&) = default;
};
template <>
struct WireFloats<Point> : std::true_type {};

enum class MotionKind : std::uint8_t { Rapid, Travel, Cut, Mark };
enum class CurveKind : std::uint8_t { Line, Arc, Parabola };

// Tools as bits (ISO 6582 Annex B).
enum ToolBits : std::uint8_t {
    kToolOxygen = 1 << 0,      // 7/8   centre torch (tool 1)
    kToolLeftBevel = 1 << 1,   // 13/14
    kToolRightBevel = 1 << 2,  // 15/16
    kToolPlasma = 1 << 3,      // 53/54 (tool 3)
    kToolPunch = 1 << 4,       // 9/10  punch marking (tool 2)
    kToolLineMarker = 1 << 5,  // 110/111 line marking (tool 4)
    kToolFive = 1 << 6,        // 112/113 tool 5
};
constexpr std::uint8_t kCuttingTools = kToolOxygen | kToolLeftBevel | kToolRightBevel | kToolPlasma;
constexpr std::uint8_t kMarkingTools = kToolPunch | kToolLineMarker | kToolFive;

// A pierce: cutting starts, i.e. no cutting tool was on and one is now (docs/semantics.md §9).
[[nodiscard]] constexpr bool starts_cutting(std::uint8_t tools_before, std::uint8_t tools_after) {
    return (tools_before & kCuttingTools) == 0 && (tools_after & kCuttingTools) != 0;
}

enum class KerfSide : std::uint8_t { Off, Left, Right };

// A parabola as a parametric curve: P(t) = vertex + t*u + t^2/(2*p) * n, t in [t0, t1].
// u is the unit tangent at the vertex, n the unit axis direction towards the opening, p > 0.
struct ParabolaGeom {
    Point vertex;
    Point u;
    Point n;
    double p = 1;
    double t0 = 0, t1 = 0;
};
template <>
struct WireFloats<ParabolaGeom> : std::true_type {};

// One motion: a line, arc or parabola from `start` to `end` (the programmed end point, exactly).
struct MotionRecord {
    std::uint32_t line = 0;   // source line of the block
    std::uint32_t block = 0;  // index of the block in the Tape
    MotionKind kind = MotionKind::Travel;
    CurveKind curve = CurveKind::Line;
    std::uint8_t tools = 0;  // ToolBits on during the motion
    std::uint8_t head = 1;   // 1, or 2 for head 2 on a 3-axis machine
    KerfSide kerf = KerfSide::Off;
    bool ccw = false;  // arcs: direction in machine coordinates (after mirroring)
    Point start, end;
    Point centre;            // arcs
    double radius = 0;       // arcs: start radius (distance start-centre)
    double end_radius = 0;   // arcs: distance end-centre (differs within arc_tolerance)
    double sweep = 0;        // arcs: signed angle in radians, + = ccw; full circle = +-2*pi
    ParabolaGeom parabola;   // parabolas
    double length_mm = 0;    // closed-form length
    double feed_mm_min = 0;  // speed used for the time estimate (rapid speed for rapids)
    double kerf_mm = 0;      // kerf offset (half width) in force, 0 when off
    // Multiple torches (Woyda 135+n, 136+d): a cut is made `torches` times, copy k offset by k x torch_step (mm);
    // 1 for every motion that is not a cut.
    std::uint8_t torches = 1;
    Point torch_step;
};

// A record as bytes (essi/wire.hpp), and read back: false when the bytes end before it.
void save_motion_record(WireWriter& out, const MotionRecord& r);
[[nodiscard]] bool restore_motion_record(WireReader& in, MotionRecord& r);

// Where copy k of a motion cut by several torches lies: the motion moved by k x step.
[[nodiscard]] constexpr Point torch_copy(Point p, Point step, int k) { return {p.x + k * step.x, p.y + k * step.y}; }

// Everything that is not a motion but changes the machine or the estimate.
enum class EventKind : std::uint8_t {
    Function,    // a machine function took effect (code, value)
    Dwell,       // seconds in `value`
    Stop,        // 0 programmed stop / 102 optional stop
    End,         // end of program (63, 64, '/', ...)
    ZeroOffset,  // 83: new origin in `x`, `y` (mm, machine)
};

struct MachineEvent {
    std::uint32_t line = 0;
    std::uint32_t block = 0;
    EventKind kind = EventKind::Function;
    std::uint16_t code = 0;  // the machine function
    bool has_value = false;
    double value = 0;     // the function's value as written (unit increments, mm/min, s ...)
    double x = 0, y = 0;  // ZeroOffset: the new origin
    std::uint8_t tools_after = 0;
    std::uint8_t torches_after = 1;  // torches cutting after the event (a pierce pierces with each)
};

// A straight motion of head 1, what most of a tape is, as the interpreter has it: its points in mm and as
// the whole unit increments they are made from (machine axes: mm = units x Profile::unit_mm + the setup
// offset). The interpreter hands these to MotionSink::on_line without making their MotionRecord when it
// checks a tape for one more sink (TapeChecker's `also`); record_of makes the record they stand for.
struct UnitLine {
    std::uint32_t line = 0, block = 0;
    MotionKind kind = MotionKind::Travel;
    std::uint8_t tools = 0;
    KerfSide kerf = KerfSide::Off;
    long long start_x = 0, start_y = 0, end_x = 0, end_y = 0;  // unit increments
    Point start, end;                                          // mm
    double length_mm = 0;
    double feed_mm_min = 0;
    double kerf_mm = 0;
};
// The MotionRecord of a straight motion (the one the interpreter emits for it, exactly).
[[nodiscard]] MotionRecord record_of(const UnitLine& line);

// The interpreter's output. Implementations: stats (report), trace printer, viewer buffers, tests.
class MotionSink {
public:
    virtual ~MotionSink() = default;
    virtual void on_motion(const MotionRecord& record) = 0;
    virtual void on_event(const MachineEvent& /*event*/) {}
    // A straight motion of head 1 (see UnitLine). A sink that keeps motions in units overrides it; by default
    // it is the record, to on_motion.
    virtual void on_line(const UnitLine& line) { on_motion(record_of(line)); }
};

// A stretch of the motion stream kept to be passed on later, in order, maybe on another thread (the pipelined
// check hands the interpreter's stream for the cut plan to the reading thread this way). Its lines stay UnitLines.
class MotionBuffer final : public MotionSink {
public:
    void on_motion(const MotionRecord& m) override {
        order_.push_back(Item::Motion);
        motions_.push_back(m);
    }
    void on_event(const MachineEvent& e) override {
        order_.push_back(Item::Event);
        events_.push_back(e);
    }
    void on_line(const UnitLine& l) override {
        order_.push_back(Item::Line);
        lines_.push_back(l);
    }
    // What was kept, to `sink`, in the order it came.
    void replay(MotionSink& sink) const;
    // Empty again (its room kept for the next stretch).
    void clear();
    [[nodiscard]] bool empty() const { return order_.empty(); }
    [[nodiscard]] std::size_t size() const { return order_.size(); }
    // The room it holds (capacity), in bytes.
    [[nodiscard]] std::size_t memory_bytes() const;

private:
    enum class Item : std::uint8_t { Line, Motion, Event };
    std::vector<Item> order_;
    std::vector<UnitLine> lines_;
    std::vector<MotionRecord> motions_;
    std::vector<MachineEvent> events_;
};

[[nodiscard]] const char* motion_kind_name(MotionKind k);  // "rapid", "travel", "cut", "mark"
[[nodiscard]] const char* curve_kind_name(CurveKind k);    // "line", "arc", "parabola"
[[nodiscard]] const char* kerf_side_name(KerfSide k);      // "off", "left", "right"
[[nodiscard]] std::string tools_text(std::uint8_t tools);  // "oxygen+punch", "-" for none
// The tools as a message argument, in the reader's language ("oxygen+punch", "Sauerstoff+Körner").
[[nodiscard]] MessageArgs::Arg tools_arg(std::uint8_t tools);

}  // namespace essi
