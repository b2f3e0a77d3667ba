// Phase 2, interp: the machine. Walks the blocks, keeps the state and emits the motion stream.
// Positions are kept in integer unit increments (machine axes, relative to the program start), so
// arcs and lines end exactly where the tape says and nothing drifts over millions of blocks.
#include "essi/interp.hpp"
#include "essi/placement.hpp"

#include <array>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "essi/function_codes.hpp"
#include "essi/functions.hpp"
#include "essi/geom.hpp"
#include "essi/stats.hpp"
#include "essi/text.hpp"

namespace essi {
namespace {

struct IPoint {
    long long x = 0, y = 0;
};

constexpr int kHeads = 2;

// An arc's radii and sweep from its start, end and centre in the tape frame (unit increments): one
// formula for measure_motions (incremental, start (0,0)) and the interpreter (any mode).
MotionMeasure measure_arc(IPoint s, IPoint e, IPoint c, bool tape_ccw) {
    return essi::measure_arc(s.x, s.y, e.x, e.y, c.x, c.y, tape_ccw);
}

// The blocks measure_motions measures: arcs (a line's length is one square root, parabolas are rare: the
// interpreter works those out).
bool has_measure(const Block& b) { return b.kind == BlockKind::Motion && b.word_count() == 5; }

// The function table flattened to one byte of flags per code, once per dialect and process: half the blocks of a
// tape are functions, and a short tape (a server request, a fuzz input) must not pay for searching the table.
constexpr int kFunctionCodes = fn::kCodeCount;
enum : std::uint8_t {
    kAssigned = 1,
    kManufacturer = 2,
    kTakesNoValue = 4,
    kNeedsValue = 8,
    kHasRange = 16,
    kActsAs = 32
};
using FunctionFlags = std::array<std::uint8_t, kFunctionCodes>;

FunctionFlags flatten_functions(Dialect dialect) {
    FunctionFlags flags{};
    for (int code = 0; code < kFunctionCodes; ++code) {
        const auto info = function_info(code, dialect);
        std::uint8_t f = 0;
        if (info && info->assigned) f |= kAssigned;
        if (info && info->manufacturer) f |= kManufacturer;
        if (info && info->value == FunctionValue::None) f |= kTakesNoValue;
        if (info && info->value == FunctionValue::Required) f |= kNeedsValue;
        if (function_value_range(code)) f |= kHasRange;
        if (function_action(code, dialect)) f |= kActsAs;
        flags[code] = f;
    }
    return flags;
}

// Each dialect's table made the first time it is asked for (a process checks with one dialect, mostly).
const FunctionFlags& function_flags_of(Dialect dialect) {
    switch (dialect) {
        case Dialect::Woyda: {
            static const FunctionFlags woyda = flatten_functions(Dialect::Woyda);
            return woyda;
        }
        case Dialect::Hypertherm: {
            static const FunctionFlags hypertherm = flatten_functions(Dialect::Hypertherm);
            return hypertherm;
        }
        case Dialect::Iso6582: break;
    }
    static const FunctionFlags iso = flatten_functions(Dialect::Iso6582);
    return iso;
}

}  // namespace

namespace detail {

class Machine {
public:
    // The sinks, chosen by the caller: either one `sink` that gets everything through its virtual calls, or the
    // statistics (fed directly, their calls inlined) and, when given, one more sink `also`.
    Machine(std::string_view source, const Profile& profile, MotionSink* sink, StatsSink* stats, MotionSink* also,
            std::vector<Diagnostic>& diagnostics)
        : source_(source), profile_(profile), sink_(sink), stats_(stats), also_(stats ? also : nullptr),
          diags_(diagnostics), function_flags_(function_flags_of(profile.dialect)) {
        feed_mm_min_ = profile_.feed_mm_min;
        kerf_units_ = profile_.kerf_units;
        set_torches(1);
    }

    void run(const Tape& chunk, std::span<const MotionMeasure> measures);
    void finish();
    void send_also_to(MotionSink& also) {
        if (also_) also_ = &also;
    }

private:
    void function(const Block& b, std::size_t index, bool has_value, double value);
    void perform(const Block& b, int code, std::size_t index, bool has_value, double value);
    [[gnu::noinline]] void act_as(const Block& b, std::size_t index, bool has_value, double value);
    [[gnu::noinline]] bool admit_function(const Block& b, bool& has_value, double value);
    bool value_in_range(const Block& b, double value);
    void set_kerf(const Block& b, KerfSide side, bool has_value, double value);
    [[gnu::noinline]] void set_feed(const Block& b, bool has_value, double value);
    [[gnu::noinline]] void zero_offset(const Block& b);
    [[gnu::noinline]] void return_to_zero(const Block& b, std::size_t index);
    [[nodiscard]] std::uint8_t function_flags(int code) const {
        return code < kFunctionCodes ? function_flags_[code] : 0;
    }
    // `pre`: the block's MotionMeasure when it was worked out ahead (arcs), else null.
    void motion(const Block& b, std::size_t index, std::span<const std::int32_t> w, const MotionMeasure* pre);
    [[gnu::noinline]] bool zero_offset_motion(const Block& b, std::size_t index, std::span<const std::int32_t> w);
    void curve_motion(const Block& b, std::size_t index, std::span<const std::int32_t> w, const MotionMeasure* pre);
    void emit(MotionRecord& m, const Block& b, std::size_t index);
    struct MotionState {
        MotionKind kind;
        double feed_mm_min;  // the speed of the time estimate
    };
    [[nodiscard]] MotionState begin_motion(const Block& b);
    [[nodiscard]] MotionKind motion_kind() const;
    [[nodiscard]] double motion_feed() const;
    [[nodiscard]] KerfSide motion_kerf() const;
    void after_motion(const Block& b);
    // Diagnostics that build their message: out of line, so the hot functions stay small.
    [[gnu::cold, gnu::noinline]] void warn_rapid_while_cutting(const Block& b);
    [[gnu::cold, gnu::noinline]] void warn_macro_only(const Block& b);
    [[gnu::cold, gnu::noinline]] void warn_bad_head(const Block& b);
    [[gnu::cold, gnu::noinline]] void warn_address_outside_3_axis(const Block& b);
    [[gnu::cold, gnu::noinline]] void warn_arc_zero_radius(const Block& b);
    [[gnu::cold, gnu::noinline]] void warn_arc_off_circle(const Block& b, double r0_units, double r1_units);
    [[gnu::cold, gnu::noinline]] void warn_kerf_radius(const Block& b, double radius_mm);
    [[gnu::cold, gnu::noinline]] void warn_kerf_while_cutting(const Block& b, KerfSide side);
    [[gnu::noinline]] bool parabola_motion(MotionRecord& m, const Block& b, std::span<const std::int32_t> w, IPoint s_t,
                                           IPoint e_t, IPoint base);
    void event(const Block& b, std::size_t index, EventKind kind, bool has_value = false, double value = 0);
    void send_event(const Block& b, std::size_t index, EventKind kind, bool has_value, double value);
    [[gnu::noinline]] void send_timed_event(const Block& b, std::size_t index, EventKind kind, bool has_value,
                                            double value);
    [[nodiscard]] MachineEvent make_event(const Block& b, std::size_t index, EventKind kind, bool has_value,
                                          double value) const;
    void warn(DiagCode code, const Block& b, Msg msg, MessageArgs args = {}) {
        diags_.push_back(
            make_diagnostic(default_severity(code), code, b.line, column_of(source_, b.offset), msg, std::move(args)));
    }
    [[nodiscard]] Point to_mm(IPoint p) const { return units_to_mm(profile_, p.x, p.y); }
    void set_mapping(const AxisMapping& mapping) {
        mapping_ = mapping;
        mirrors_ = mapping.mirrors();
    }
    [[nodiscard]] IPoint map(long long X, long long Y) const {
        return {mapping_.xx * X + mapping_.xy * Y, mapping_.yx * X + mapping_.yy * Y};
    }
    void set_tools(std::uint8_t tools) { tools_ = tools; }
    void check_table(const MotionRecord& m, const Block& b);
    void check_table_box(const Box& box, const Block& b, Msg what);

    // The function's name in the reader's language (a message argument).
    [[nodiscard]] MessageArgs::Arg function_name(int code) const {
        const auto info = function_info(code, profile_.dialect);
        return info && info->name_msg != Msg::None ? MessageArgs::Arg(info->name_msg) : MessageArgs::Arg("?");
    }

    std::string_view source_;
    const Profile& profile_;
    // The one sink of interpret() (a trace, a test): everything through its virtual calls. Null when checking.
    MotionSink* const sink_;
    // The statistics of a check: called directly, their calls inlined. Null when there is one `sink_`.
    StatsSink* const stats_;
    // The statistics follow the machine time or the consumables (StatsSink::timed): they get every event.
    const bool timed_stats_ = stats_ != nullptr && stats_->timed();
    // The one more sink of a check (the viewer's document): given the lines of head 1 as UnitLines.
    MotionSink* also_;
    std::vector<Diagnostic>& diags_;
    const FunctionFlags& function_flags_;
    // A motion or an event to the sinks: the statistics, then the one more sink; or the one sink.
    template <class Item>
    void send(const Item& item) {
        if (stats_) {
            deliver(*stats_, item);
            if (also_) deliver(*also_, item);
        } else {
            deliver(*sink_, item);
        }
    }
    static void deliver(StatsSink& s, const MotionRecord& m) { s.on_motion(m); }
    static void deliver(StatsSink& s, const MachineEvent& e) { s.on_event(e); }
    static void deliver(MotionSink& s, const MotionRecord& m) { s.on_motion(m); }
    static void deliver(MotionSink& s, const MachineEvent& e) { s.on_event(e); }

    // Machine state
    IPoint pos_[kHeads];                   // per head, machine axes, unit increments
    IPoint origin_;                        // origin of absolute coordinates (83), program axes
    const Placement placement_{profile_};  // the program on the machine (§12)
    Point tool_offset_;                    // where the tool in use sits from the centre torch (11, 114; 12 cancels)
    AxisMapping mapping_;                  // 21-28
    bool mirrors_ = false;                 // mapping_.mirrors(), kept with it (asked for every motion)
    bool absolute_ = false;                // 82
    bool zero_offset_pending_ = false;
    std::optional<Block> zero_offset_block_;
    std::uint8_t tools_ = 0;
    bool rapid_ = false;
    bool rapid_one_block_ = false;  // profile.rapid_single_block: 5 lasts one motion
    KerfSide kerf_ = KerfSide::Off;
    double kerf_offset_mm_ = 0;
    double kerf_units_ = 0;  // what 29/30 without a value use: the profile's kerf, or Hypertherm's 40+v
    double feed_mm_min_ = 0;
    bool three_axis_ = false;
    bool skipping_ = false;  // inside 100 ... 101 with optional ignore on
    std::optional<Block> open_optional_;
    std::optional<Block> burner_count_;  // a 135 waiting for its 136
    double burner_count_value_ = 1;      // its value
    std::uint8_t torches_ = 1;           // torches cutting (135 + 136): each cut is made this many times
    // A check whose straight lines go to the statistics directly, without a record: no table to check and one
    // torch (several torches copy the cuts: their records carry the copies). One test per line.
    // ... and no kerf compensation on or still open (those lines are pieces of the compensated path, §8).
    bool lines_direct_ = false;
    bool travel_direct_ = false;  // the same with several torches: the lines that cut nothing
    bool kerf_open_ = false;      // the statistics' compensated path has a piece open
    void set_torches(std::uint8_t n) {
        torches_ = n;
        update_direct_paths();
    }
    void set_kerf_side(KerfSide side) {
        kerf_ = side;
        update_direct_paths();
    }
    void update_direct_paths() {
        travel_direct_ = stats_ && !profile_.table && kerf_ == KerfSide::Off && !kerf_open_;
        lines_direct_ = travel_direct_ && torches_ == 1;
    }
    [[gnu::noinline]] void after_kerf_record(const Block& b);
    void select_tool_offset(const Block& b, int code);
    Point torch_step_;          // mm between neighbouring torches (136, along profile.torch_direction)
    bool inside_table_ = true;  // the carriage is on the table (the last motion ended on it)
    std::optional<Block> last_block_;
    bool ended_ = false;
    std::uint8_t tools_before_end_ = 0;  // tools on when the end code was reached
    MotionRecord record_;
};

void Machine::run(const Tape& chunk, std::span<const MotionMeasure> measures) {
    const MotionMeasure* measure = measures.empty() ? nullptr : measures.data();  // the next one, walking along
    const std::int32_t* words = chunk.all_words().data();                         // the words of block k, walking along
    const std::size_t end = chunk.end_block();
    const std::size_t base = chunk.first_block();
    const Block* last = nullptr;  // kept as last_block_ when the chunk is done (the chunk's memory goes)
    const Block* const blocks = chunk.blocks().data();
    for (std::size_t k = 0; k < end && !ended_; ++k) {
        const Block& b = blocks[k];
        const std::span<const std::int32_t> w(words, static_cast<std::size_t>(b.word_count()));
        words += b.word_count();
        const std::size_t i = base + k;  // the block's index in the whole tape
        const MotionMeasure* pre = nullptr;
        if (measure != nullptr && has_measure(b)) pre = measure++;
        // The common case first: a motion or a function, nothing pending, not the end.
        if (!burner_count_ && !skipping_ && !b.ends_program()) {
            if (b.kind == BlockKind::Motion) {
                last = &b;
                motion(b, i, w, pre);
                continue;
            }
            if (b.kind == BlockKind::Function) {
                last = &b;
                function(b, i, false, 0);
                continue;
            }
        }
        if (b.kind == BlockKind::Comment || b.kind == BlockKind::Percent) continue;
        last = &b;
        if (burner_count_ &&
            !(b.has_code() && b.code == fn::kWoydaBurnerSpacing && b.kind == BlockKind::FunctionValue)) {
            warn(DiagCode::W212_BurnerCountNotBeforeSpacing, *burner_count_, Msg::InterpBurnerCountNotNext);
            burner_count_.reset();
        }
        const bool is_end = b.ends_program();  // the end still ends a skipped section
        if (skipping_ && !is_end && !(b.kind == BlockKind::Function && b.code == fn::kOptionalIgnoreOff)) continue;
        switch (b.kind) {
            case BlockKind::Invalid: zero_offset_pending_ = false; break;
            case BlockKind::EndMark:
                event(b, i, EventKind::End);
                ended_ = true;
                break;
            case BlockKind::Function:
                if (is_end) {
                    // The end code recognised by the reader (63, 64, ... per the dialect).
                    event(b, i, EventKind::End);
                    ended_ = true;
                    break;
                }
                function(b, i, false, 0);
                break;
            case BlockKind::FunctionValue: function(b, i, true, b.function_value(w[0])); break;
            case BlockKind::Motion: motion(b, i, w, pre); break;
            case BlockKind::Comment:
            case BlockKind::Percent: break;
        }
    }
    if (last) last_block_ = *last;
}

// The checks that need the whole program: things opened and never closed, the state at the end.
void Machine::finish() {
    if (stats_) stats_->finish();
    if (zero_offset_pending_ && zero_offset_block_) {
        warn(DiagCode::E207_ZeroOffsetBlock, *zero_offset_block_, Msg::InterpZeroOffsetAtEnd);
    }
    if (open_optional_) {
        warn(DiagCode::W214_UnclosedOptionalIgnore, *open_optional_, Msg::InterpUnclosedOptionalIgnore);
    }
    if (burner_count_) {
        warn(DiagCode::W212_BurnerCountNotBeforeSpacing, *burner_count_, Msg::InterpBurnerCountAtEnd);
    }
    // The tools in force just before the end code (63/64 switches them off as part of ending).
    const std::uint8_t tools_at_end = ended_ ? tools_before_end_ : tools_;
    if (last_block_ && (tools_at_end & (kCuttingTools | kMarkingTools))) {
        warn(DiagCode::W211_ToolOnAtEnd, *last_block_, Msg::InterpToolOnAtEnd, {tools_arg(tools_at_end)});
    }
}

// Inlined into function(): every function block ends here.
[[gnu::always_inline]] inline void Machine::event(const Block& b, std::size_t index, EventKind kind, bool has_value,
                                                  double value) {
    if (kind == EventKind::End) {
        tools_before_end_ = tools_;
        tools_ = 0;
    }
    if (stats_) {  // the statistics: what they count, without making the event
        stats_->count_event(kind, value, tools_, torches_);
        if (also_ == nullptr && !timed_stats_) return;
    }
    send_event(b, index, kind, has_value, value);
}

// The event of a function block, as the sinks get it.
inline MachineEvent Machine::make_event(const Block& b, std::size_t index, EventKind kind, bool has_value,
                                        double value) const {
    MachineEvent e;
    e.line = b.line;
    e.block = static_cast<std::uint32_t>(index);
    e.kind = kind;
    e.code = b.has_code() ? b.code : 0;
    e.has_value = has_value;
    e.value = value;
    e.tools_after = tools_;
    e.torches_after = torches_;
    return e;
}

void Machine::send_event(const Block& b, std::size_t index, EventKind kind, bool has_value, double value) {
    if (timed_stats_) [[unlikely]]
        return send_timed_event(b, index, kind, has_value, value);
    deliver(stats_ ? *also_ : *sink_, make_event(b, index, kind, has_value, value));  // (the statistics counted it)
}

// An event when the statistics follow the machine time: to them as well (out of send_event's way).
void Machine::send_timed_event(const Block& b, std::size_t index, EventKind kind, bool has_value, double value) {
    const MachineEvent e = make_event(b, index, kind, has_value, value);
    stats_->time_event(e);
    if (also_) deliver(*also_, e);
}

// The checks a function block must pass before it takes effect (rarely failed: kept out of the common path).
// Returns false when the block is ignored; may clear `has_value` (a value the function does not take).
bool Machine::admit_function(const Block& b, bool& has_value, double value) {
    const int code = b.code;
    if (zero_offset_pending_) {
        warn(DiagCode::E207_ZeroOffsetBlock, *zero_offset_block_, Msg::InterpZeroOffsetThenFunction, {code, b.line});
        zero_offset_pending_ = false;
    }
    const std::uint8_t flags = function_flags(code);
    if (!(flags & kAssigned)) {
        if (code > fn::kLastIsoCode)
            warn(DiagCode::W201_UnknownFunction, b, Msg::InterpFunctionNotDefined, {code, profile_.name});
        else warn(DiagCode::W201_UnknownFunction, b, Msg::InterpFunctionUnassigned, {code});
        return false;
    }
    if (flags & kManufacturer) {
        warn(DiagCode::W208_ManufacturerFunction, b, Msg::InterpManufacturerFunction, {code});
        return false;
    }
    if (has_value && (flags & kTakesNoValue)) {
        warn(DiagCode::W202_FunctionValueIgnored, b, Msg::InterpValueIgnored,
             {code, function_name(code), number_text(value)});
        has_value = false;
    }
    if (!has_value && (flags & kNeedsValue)) {
        warn(DiagCode::E203_FunctionValueMissing, b, Msg::InterpValueMissing, {code, function_name(code)});
        return false;
    }
    return true;
}

bool Machine::value_in_range(const Block& b, double value) {
    const auto range = function_value_range(b.code);
    if (!range) return true;
    const double scale = range->unit == RangeUnit::Mm        ? profile_.unit_mm
                         : range->unit == RangeUnit::Seconds ? profile_.dwell_unit_s
                                                             : 1.0;
    if (value * scale >= range->min && value * scale <= range->max) return true;
    const auto info = function_info(b.code, profile_.dialect);
    const char* scaled_unit = range->unit == RangeUnit::Mm ? "mm" : "s";
    if (scale != 1.0) {
        warn(DiagCode::E216_FunctionValueRange, b, Msg::InterpValueOutsideScaled,
             {number_text(value), b.code, function_name(b.code), number_text(range->min), number_text(range->max),
              scaled_unit, number_text(value * scale), number_text(scale)});
        return false;
    }
    warn(DiagCode::E216_FunctionValueRange, b, Msg::InterpValueOutside,
         {number_text(value), b.code, function_name(b.code), number_text(range->min), number_text(range->max),
          range->unit != RangeUnit::AsWritten   ? MessageArgs::Arg(scaled_unit)
          : info && info->unit_msg != Msg::None ? MessageArgs::Arg(info->unit_msg)
                                                : MessageArgs::Arg("")});
    return false;
}

void Machine::warn_kerf_while_cutting(const Block& b, KerfSide side) {
    warn(DiagCode::W204_KerfWhileCutting, b, Msg::InterpKerfWhileCutting,
         {side == KerfSide::Off ? Msg::WordOff : Msg::WordOn});
}

void Machine::set_kerf(const Block& b, KerfSide side, bool has_value, double value) {
    if (tools_ & kCuttingTools) [[unlikely]]
        warn_kerf_while_cutting(b, side);
    set_kerf_side(side);
    if (side == KerfSide::Off) {
        kerf_offset_mm_ = 0;
        return;
    }
    const double units = has_value ? value : kerf_units_;
    const double mm = units * profile_.unit_mm;
    kerf_offset_mm_ = profile_.kerf_value == KerfValueMeaning::Width ? mm / 2 : mm;
}

void Machine::set_feed(const Block& b, bool has_value, double value) {
    if (has_value && value <= 0) {
        warn(DiagCode::W209_ZeroFeed, b, Msg::InterpZeroFeed,
             {number_text(value), static_cast<long long>(profile_.feed_mm_min)});
        feed_mm_min_ = profile_.feed_mm_min;
    } else {
        feed_mm_min_ = has_value ? value : profile_.feed_mm_min;
    }
}

void Machine::zero_offset(const Block& b) {
    zero_offset_pending_ = true;
    zero_offset_block_ = b;
    if (!absolute_) {
        warn(DiagCode::W215_ZeroOffsetInIncremental, b, Msg::InterpZeroOffsetIncremental);
    }
}

// Woyda 62: return to the program's zero point, a motion of its own.
void Machine::return_to_zero(const Block& b, std::size_t index) {
    event(b, index, EventKind::Function);
    MotionRecord m;
    m.curve = CurveKind::Line;
    m.start = to_mm(pos_[0]);
    m.length_mm = units_length(pos_[0].x, pos_[0].y) * profile_.unit_mm;
    pos_[0] = IPoint{};
    m.end = to_mm(pos_[0]);
    emit(m, b, index);
}

void Machine::warn_macro_only(const Block& b) {
    warn(DiagCode::W213_MacroOnlyFunction, b, Msg::InterpMacroOnly, {b.code, function_name(b.code)});
}

// Inlined into run(): half the blocks of a tape are functions (a call and its frame cost more than most of them).
[[gnu::always_inline]] inline void Machine::function(const Block& b, std::size_t index, bool has_value, double value) {
    const int code = b.code;
    // One test for the common case: nothing pending, an assigned function with a value only if it takes one, that
    // means in this dialect what it means in ISO.
    const std::uint8_t refused = kManufacturer | kActsAs | (has_value ? kTakesNoValue : kNeedsValue);
    if (zero_offset_pending_ || (function_flags(code) & (kAssigned | refused)) != kAssigned) [[unlikely]] {
        if (!admit_function(b, has_value, value)) return;
        if (function_flags(code) & kActsAs) return act_as(b, index, has_value, value);
    }
    if (has_value && (function_flags(code) & kHasRange) && !value_in_range(b, value)) [[unlikely]]
        return;
    perform(b, code, index, has_value, value);
}

// A dialect's code that stands for another (function_table.def, ESSI_ACTS_AS: Hypertherm's 53 is ISO's 7): it
// runs as that code with its value, and its event carries that code (an action of its own keeps the block's).
void Machine::act_as(const Block& b, std::size_t index, bool has_value, double value) {
    const FunctionAction a = *function_action(b.code, profile_.dialect);
    Block acted = b;
    if (a.action < fn::kFirstAction) acted.code = static_cast<std::uint16_t>(a.action);
    if (a.fixed_value >= 0) {
        has_value = true;
        value = a.fixed_value;
    }
    if (has_value && function_value_range(a.action) && !value_in_range(acted, value)) return;
    perform(acted, a.action, index, has_value, value);
}

// What a function does to the machine, and its event.
[[gnu::always_inline]] inline void Machine::perform(const Block& b, int code, std::size_t index, bool has_value,
                                                    double value) {
    double event_value = value;
    EventKind kind = EventKind::Function;
    const auto tool = [&](std::uint8_t bit, bool on) { set_tools(on ? (tools_ | bit) : (tools_ & ~bit)); };

    switch (code) {
        case fn::kProgramStop:
        case fn::kOptionalStop: kind = EventKind::Stop; break;
        case fn::kRapidOn:
            rapid_ = true;
            rapid_one_block_ = profile_.rapid_single_block;
            break;
        case fn::kRapidOff: rapid_ = false; break;
        case fn::kOxygenOn: tool(kToolOxygen, true); break;
        case fn::kOxygenOff: tool(kToolOxygen, false); break;
        case fn::kPunchMarkingOn: tool(kToolPunch, true); break;
        case fn::kPunchMarkingOff: tool(kToolPunch, false); break;
        case fn::kLeftBevelOn: tool(kToolLeftBevel, true); break;
        case fn::kLeftBevelOff: tool(kToolLeftBevel, false); break;
        case fn::kRightBevelOn: tool(kToolRightBevel, true); break;
        case fn::kRightBevelOff: tool(kToolRightBevel, false); break;
        case fn::kThreeAxisOn: three_axis_ = true; break;
        case fn::kTwoAxisOn: three_axis_ = false; break;
        case fn::kKerfLeft: set_kerf(b, KerfSide::Left, has_value, value); break;
        case fn::kKerfRight: set_kerf(b, KerfSide::Right, has_value, value); break;
        case fn::kKerfOff: set_kerf(b, KerfSide::Off, has_value, value); break;
        case fn::kFeed:
            set_feed(b, has_value, value);
            event_value = feed_mm_min_;
            has_value = true;
            break;
        case fn::kDwell:
            kind = EventKind::Dwell;
            event_value = has_value ? value * profile_.dwell_unit_s : profile_.default_dwell_s;
            has_value = true;
            break;
        case fn::kWoydaOxygenOff: tool(kToolOxygen, false); break;  // (the preheat stays)
        case fn::kPlasmaOn: tool(kToolPlasma, true); break;
        case fn::kPlasmaOff: tool(kToolPlasma, false); break;
        case fn::kPunchMarkingOffsetOn:
        case fn::kLineMarkingOffsetOn:
        case fn::kToolOffsetOff: select_tool_offset(b, code); break;
        case fn::kResetFunctions:  // (Hypertherm 63)
            set_tools(0);
            set_kerf_side(KerfSide::Off);
            kerf_offset_mm_ = 0;
            break;
        case fn::kHyperthermKerfValue: kerf_units_ = value; break;
        case fn::kCancelFunctions:
        case fn::kEndOfTape:  // not an end code in this profile: cancels the stored functions (ISO Annex B)
            select_tool_offset(b, code);
            set_tools(0);
            rapid_ = false;
            set_kerf_side(KerfSide::Off);
            kerf_offset_mm_ = 0;
            set_mapping(axis_mapping(fn::kAxesNormal));
            absolute_ = false;
            set_torches(1);
            break;
        case fn::kWoydaLoopEnd:
        case fn::kWoydaLoopStart: warn_macro_only(b); return;
        case fn::kIncremental: absolute_ = false; break;
        case fn::kAbsolute: absolute_ = true; break;
        case fn::kZeroOffset: zero_offset(b); break;
        case fn::kOptionalIgnoreOn:
            open_optional_ = b;
            skipping_ = profile_.optional_ignore;
            break;
        case fn::kOptionalIgnoreOff:
            open_optional_.reset();
            skipping_ = false;
            break;
        case fn::kLineMarkingOn: tool(kToolLineMarker, true); break;
        case fn::kLineMarkingOff: tool(kToolLineMarker, false); break;
        case fn::kToolFiveOn: tool(kToolFive, true); break;
        case fn::kToolFiveOff: tool(kToolFive, false); break;
        case fn::kWoydaProgramZero:  // (only a dialect whose table assigns 62 gets here: ISO's 62 is W208 above)
            return_to_zero(b, index);
            return;
        case fn::kWoydaBurnerCount:
            burner_count_ = b;
            burner_count_value_ = value;
            break;
        case fn::kWoydaBurnerSpacing:
            // (a 136 without its 135 got W212 in run(): the count stays)
            if (burner_count_) set_torches(static_cast<std::uint8_t>(burner_count_value_));
            torch_step_ = {profile_.torch_direction.x * value * profile_.unit_mm,
                           profile_.torch_direction.y * value * profile_.unit_mm};
            burner_count_.reset();
            break;
        default:
            if (code >= fn::kAxesNormal && code <= fn::kAxesMappingLast) set_mapping(axis_mapping(code));
            break;  // state-only functions: the event says what happened
    }
    event(b, index, kind, has_value, event_value);
}

void Machine::warn_rapid_while_cutting(const Block& b) {
    warn(DiagCode::W210_RapidWhileCutting, b, Msg::InterpRapidWhileCutting, {tools_arg(tools_ & kCuttingTools)});
}

[[gnu::always_inline]] inline void Machine::emit(MotionRecord& m, const Block& b, std::size_t index) {
    const MotionState state = begin_motion(b);
    m.line = b.line;
    m.block = static_cast<std::uint32_t>(index);
    m.tools = tools_;
    m.kind = state.kind;
    m.feed_mm_min = state.feed_mm_min;
    m.kerf = motion_kerf();
    m.kerf_mm = kerf_offset_mm_;
    // Several torches copy the cuts only (a travel is the carriage's, once)
    m.torches = 1;
    m.torch_step = {};
    if (torches_ > 1 && m.kind == MotionKind::Cut) [[unlikely]] {
        m.torches = torches_;
        m.torch_step = torch_step_;
    }
    if (profile_.table) check_table(m, b);
    send(m);
    if (stats_ && (m.kerf != KerfSide::Off || kerf_open_) &&
        (kerf_open_ != stats_->kerf_open() || stats_->has_gouges())) [[unlikely]]
        after_kerf_record(b);
}

// A record of the compensated path went to the statistics: the gouge its corner made, if any, and whether a
// piece is still open (while one is, lines come as records).
void Machine::after_kerf_record(const Block& b) {
    for (KerfGouge& g : stats_->take_gouges()) warn(DiagCode::E307_KerfGouge, b, g.msg, std::move(g.args));
    if (kerf_open_ != stats_->kerf_open()) {
        kerf_open_ = stats_->kerf_open();
        update_direct_paths();
    }
}

// What the machine's state makes of the motion of `b`, and what the motion does to the state: every motion,
// with its record (emit) or without (a checked straight line), passes here once.
[[gnu::always_inline]] inline Machine::MotionState Machine::begin_motion(const Block& b) {
    const MotionState state{motion_kind(), motion_feed()};
    after_motion(b);
    return state;
}

// What the tools and rapid make of a motion, and the speed its time is estimated at.
inline MotionKind Machine::motion_kind() const {
    if (tools_ & kCuttingTools) return MotionKind::Cut;
    if (tools_ & kMarkingTools) return MotionKind::Mark;
    return rapid_ ? MotionKind::Rapid : MotionKind::Travel;
}
inline double Machine::motion_feed() const { return rapid_ ? profile_.rapid_mm_min : feed_mm_min_; }
// The side of the path the kerf is on, in machine coordinates (a mirror 21-28 swaps it).
inline KerfSide Machine::motion_kerf() const {
    if (kerf_ == KerfSide::Off || !mirrors_) return kerf_;
    return kerf_ == KerfSide::Left ? KerfSide::Right : KerfSide::Left;
}

// After every motion: a rapid while cutting is warned about; a one-block rapid (profile) ends.
inline void Machine::after_motion(const Block& b) {
    if (rapid_ && (tools_ & kCuttingTools)) [[unlikely]]
        warn_rapid_while_cutting(b);
    if (rapid_one_block_) {
        rapid_ = false;
        rapid_one_block_ = false;
    }
}

// 11, 114, 12 (and a 63 that cancels): the tool offset changes and the carriage moves by it at once, so that the
// tool is over the contour (§12); a carriage that leaves the table there is E401 at this block.
void Machine::select_tool_offset(const Block& b, int code) {
    const Point next = tool_offset_after(profile_, code, tool_offset_);
    if (next == tool_offset_) return;
    tool_offset_ = next;
    if (stats_) stats_->set_tool_offset(next);
    if (!profile_.table) return;
    const Point at = placement_.machine(to_mm(pos_[0]), tool_offset_);
    check_table_box(Box::of(at, at), b, Msg::InterpToolOffsetOffTable);
}

namespace {
// Whether the table's travel holds the whole box.
bool table_holds(const TableLimits& t, const Box& box) {
    return box.min_x >= t.min_x_mm && box.max_x <= t.max_x_mm && box.min_y >= t.min_y_mm && box.max_y <= t.max_y_mm;
}
}  // namespace

void Machine::check_table(const MotionRecord& m, const Block& b) {
    if (!profile_.table) return;
    // Most motions lie well inside the table: a box that holds the whole motion (a line's ends; an arc's ends and
    // its whole circle) inside the table settles it without the exact box (an arc's extremes, a parabola's). On a
    // plate that is not turned, Placement::moved takes a program box to the machine exactly.
    if (inside_table_ && m.curve != CurveKind::Parabola && !placement_.turns()) {
        Box hull = Box::of(m.start, m.end);
        if (m.curve == CurveKind::Arc) {
            const double r = std::max(m.radius, m.end_radius);
            hull.add(Point{m.centre.x - r, m.centre.y - r});
            hull.add(Point{m.centre.x + r, m.centre.y + r});
        }
        if (table_holds(*profile_.table, placement_.moved(hull, tool_offset_))) return;
    }
    check_table_box(placement_.machine_box(m, tool_offset_), b, Msg::InterpMotionOffTable);
    // The carriage is on the table again once a motion ends on it (its box need not be), so that the next motion
    // that leaves it is reported too.
    if (!inside_table_) {
        const Point end = placement_.machine(m.end, tool_offset_);
        inside_table_ = table_holds(*profile_.table, Box::of(end, end));
    }
}

// E401 at the block that leaves the table (its machine box not on it) while the carriage was on it.
void Machine::check_table_box(const Box& box, const Block& b, Msg what) {
    const TableLimits& t = *profile_.table;
    const bool inside = table_holds(t, box);
    if (!inside && inside_table_) {
        warn(DiagCode::E401_LeavesTable, b, Msg::InterpLeavesTable,
             {what, mm_text(box.min_x), mm_text(box.max_x), mm_text(box.min_y), mm_text(box.max_y), mm_text(t.min_x_mm),
              mm_text(t.max_x_mm), mm_text(t.min_y_mm), mm_text(t.max_y_mm)});
    }
    inside_table_ = inside;
}

// The block after 83 (zero offset): its two words are the new origin. Returns true when the block was that
// origin; false (after E207 when it is not a block of two words) when it is an ordinary motion.
bool Machine::zero_offset_motion(const Block& b, std::size_t index, std::span<const std::int32_t> w) {
    zero_offset_pending_ = false;
    if (w.size() == 2 && !b.has_address()) {
        const IPoint d = map(w[0], w[1]);
        origin_.x += d.x;
        origin_.y += d.y;
        MachineEvent e;
        e.line = b.line;
        e.block = static_cast<std::uint32_t>(index);
        e.kind = EventKind::ZeroOffset;
        e.code = fn::kZeroOffset;
        const Point o = to_mm(origin_);
        e.x = o.x;
        e.y = o.y;
        e.tools_after = tools_;
        send(e);
        return true;
    }
    warn(DiagCode::E207_ZeroOffsetBlock, *zero_offset_block_, Msg::InterpZeroOffsetWordCount, {b.line, w.size()});
    return false;
}

// Inlined into run(): half the blocks of a tape come here.
[[gnu::always_inline]] inline void Machine::motion(const Block& b, std::size_t index, std::span<const std::int32_t> w,
                                                   const MotionMeasure* pre) {
    if (absolute_) pre = nullptr;  // worked out for an incremental start
    if (zero_offset_pending_ && zero_offset_motion(b, index, w)) return;
    if (w.size() == 2 && !b.has_address()) {
        // The common case first: a straight line of head 1 (what the general path below does for it).
        IPoint& cur = pos_[0];
        const IPoint base = absolute_ ? origin_ : cur;
        const IPoint d = map(w[0], w[1]);
        const IPoint end{base.x + d.x, base.y + d.y};
        const double length_mm = units_length(end.x - cur.x, end.y - cur.y) * profile_.unit_mm;
        if (lines_direct_ || (travel_direct_ && (tools_ & kCuttingTools) == 0)) {
            // Checked: what the statistics count of a line (StatsSink::add_line, as on_motion does for its
            // record), without making the record; the one more sink's UnitLine.
            const MotionState state = begin_motion(b);
            const Point start_mm = to_mm(cur), end_mm = to_mm(end);
            stats_->add_line(state.kind, /*head*/ 1, start_mm, end_mm, length_mm, state.feed_mm_min, b.line);
            if (also_) {
                UnitLine l;
                l.line = b.line;
                l.block = static_cast<std::uint32_t>(index);
                l.kind = state.kind;
                l.tools = tools_;
                l.kerf = motion_kerf();
                l.start_x = cur.x;
                l.start_y = cur.y;
                l.end_x = end.x;
                l.end_y = end.y;
                l.start = start_mm;
                l.end = end_mm;
                l.length_mm = length_mm;
                l.feed_mm_min = state.feed_mm_min;
                l.kerf_mm = kerf_offset_mm_;
                also_->on_line(l);
            }
            cur = end;
            return;
        }
        MotionRecord& m = record_;
        m.head = 1;
        m.curve = CurveKind::Line;
        m.ccw = false;
        m.centre = {};
        m.radius = m.end_radius = m.sweep = 0;
        m.start = to_mm(cur);
        m.end = to_mm(end);
        m.length_mm = length_mm;
        cur = end;
        emit(m, b, index);
        return;
    }
    curve_motion(b, index, w, pre);
}

// Every other motion: head addresses, absolute mode, arcs, parabolas.
void Machine::curve_motion(const Block& b, std::size_t index, std::span<const std::int32_t> w,
                           const MotionMeasure* pre) {
    int head = 1;
    if (b.has_address()) {
        if (b.code != fn::kHeadOne && b.code != fn::kHeadTwo) {
            warn_bad_head(b);
            return;
        }
        head = b.code;
        if (!three_axis_) warn_address_outside_3_axis(b);
    }
    IPoint& cur = pos_[head - 1];
    // The block's frame: machine = base + M * tape. Incremental: base is the start, the start is tape (0,0).
    // Absolute: base is the origin of absolute coordinates, the start is M^T (current - origin).
    const IPoint base = absolute_ ? origin_ : cur;
    IPoint s_t{0, 0};
    if (absolute_) {
        const long long dx = cur.x - origin_.x, dy = cur.y - origin_.y;
        s_t = {mapping_.xx * dx + mapping_.yx * dy, mapping_.xy * dx + mapping_.yy * dy};
    }
    const IPoint e_t{w[0], w[1]};
    const IPoint d_end = map(e_t.x, e_t.y);
    const IPoint end{base.x + d_end.x, base.y + d_end.y};

    // One record reused for every motion: a fresh zeroed record per block costs more than the motion.
    MotionRecord& m = record_;
    m.head = static_cast<std::uint8_t>(head);
    m.ccw = false;
    m.centre = {};
    m.radius = m.end_radius = m.sweep = 0;
    m.start = to_mm(cur);
    m.end = to_mm(end);
    const double unit = profile_.unit_mm;
    const double tol_units = profile_.arc_tolerance_units;

    // Lines, and curves that fall back to a line: the straight length (a square root, only when needed).
    const auto line_length_mm = [&] { return units_length(end.x - cur.x, end.y - cur.y) * unit; };
    if (w.size() == 2) {
        m.curve = CurveKind::Line;
        m.length_mm = line_length_mm();
    } else if (w.size() == 5) {
        const IPoint c_t{w[2], w[3]};
        const IPoint d_c = map(c_t.x, c_t.y);
        const IPoint centre{base.x + d_c.x, base.y + d_c.y};
        const MotionMeasure arc = pre ? *pre : measure_arc(s_t, e_t, c_t, b.tc_positive());
        const double r0 = arc.r0, r1 = arc.r1;
        if (r0 == 0) {
            warn_arc_zero_radius(b);
            m.curve = CurveKind::Line;
            m.length_mm = line_length_mm();
        } else {
            if (std::abs(r1 - r0) > tol_units) warn_arc_off_circle(b, r0, r1);
            m.curve = CurveKind::Arc;
            m.centre = to_mm(centre);
            m.ccw = b.tc_positive() != mirrors_;
            m.radius = r0 * unit;
            m.end_radius = r1 * unit;
            m.sweep = mirrors_ ? -arc.sweep : arc.sweep;  // a mirror turns the sense
            m.length_mm = m.radius * std::abs(m.sweep);
            if (kerf_ != KerfSide::Off) {
                // Kerf side relative to the programmed contour: a ccw arc has its centre on the left.
                const bool inside = (kerf_ == KerfSide::Left) == b.tc_positive();
                if (inside && m.radius - kerf_offset_mm_ <= 0) warn_kerf_radius(b, m.radius);
            }
        }
    } else if (!parabola_motion(m, b, w, s_t, e_t, base)) {  // 6 words: parabola (§6)
        m.curve = CurveKind::Line;
        m.length_mm = line_length_mm();
    }
    cur = end;
    emit(m, b, index);
}

// A parabola block (6 words) into `m`: worked out in the tape frame (start s_t, end e_t) and mapped like every
// point. Rare: out of the arcs' way. Returns false (after E304) when it has no curvature: a straight line then.
bool Machine::parabola_motion(MotionRecord& m, const Block& b, std::span<const std::int32_t> w, IPoint s_t, IPoint e_t,
                              IPoint base) {
    const double unit = profile_.unit_mm;
    const double tol_units = profile_.arc_tolerance_units;
    const double XP = w[2], YP = w[3];
    const bool axis_parallel_y = b.tp_positive();
    const double p_signed = axis_parallel_y ? YP : XP;
    if (p_signed == 0) {
        warn(DiagCode::E304_ParabolaZeroCurvature, b, Msg::GeomParabolaZeroCurvature, {axis_parallel_y ? "YP" : "XP"});
        return false;
    }
    const auto to_point = [](IPoint q) { return Point{static_cast<double>(q.x), static_cast<double>(q.y)}; };
    const ParabolaPiece piece = parabola_from_words(to_point(s_t), to_point(e_t), XP, YP, axis_parallel_y, absolute_);
    const ParabolaGeom& g = piece.curve;  // tape frame, units
    if (std::abs(piece.residual) > tol_units) {
        warn(DiagCode::E303_ParabolaEndNotOnCurve, b, Msg::GeomParabolaOffCurve,
             {mm_text(std::abs(piece.residual) * unit), mm_text(tol_units * unit)});
    }
    if (g.t1 != g.t0) {
        const bool ccw = parabola_turns_ccw(g);
        if (ccw != b.tc_positive()) {
            warn(DiagCode::W305_ParabolaDirection, b, Msg::GeomParabolaDirection,
                 {b.tc_positive() ? Msg::WordCounterClockwisePlus : Msg::WordClockwiseMinus,
                  ccw ? Msg::WordCounterClockwise : Msg::WordClockwise, ccw ? "+" : "-"});
        }
    }
    // Map to machine millimetres.
    const Point bm = to_mm(base);
    const Point v = mapping_.apply(g.vertex.x, g.vertex.y);
    m.parabola.vertex = {bm.x + v.x * unit, bm.y + v.y * unit};
    m.parabola.u = mapping_.apply(g.u.x, g.u.y);
    m.parabola.n = mapping_.apply(g.n.x, g.n.y);
    m.parabola.p = g.p * unit;
    m.parabola.t0 = g.t0 * unit;
    m.parabola.t1 = g.t1 * unit;
    m.curve = CurveKind::Parabola;
    m.ccw = b.tc_positive() != mirrors_;
    m.length_mm = parabola_length(m.parabola);
    return true;
}

void Machine::warn_bad_head(const Block& b) { warn(DiagCode::E206_BadHeadAddress, b, Msg::InterpBadHead, {b.code}); }

void Machine::warn_address_outside_3_axis(const Block& b) {
    warn(DiagCode::W205_AddressOutside3Axis, b, Msg::InterpAddressOutside3Axis, {b.code});
}

void Machine::warn_arc_zero_radius(const Block& b) { warn(DiagCode::E302_ArcZeroRadius, b, Msg::GeomArcZeroRadius); }

void Machine::warn_arc_off_circle(const Block& b, double r0_units, double r1_units) {
    const double unit = profile_.unit_mm;
    warn(DiagCode::E301_ArcEndNotOnCircle, b, Msg::GeomArcOffCircle,
         {mm_text(r0_units * unit), mm_text(r1_units * unit), mm_text(std::abs(r1_units - r0_units) * unit),
          mm_text(profile_.arc_tolerance_units * unit)});
}

void Machine::warn_kerf_radius(const Block& b, double radius_mm) {
    warn(DiagCode::E306_KerfRadiusNegative, b, Msg::GeomKerfRadius, {mm_text(kerf_offset_mm_), mm_text(radius_mm)});
}

}  // namespace detail

AxisMapping axis_mapping(int function_code) {
    switch (function_code) {
        case 22: return {1, 0, 0, -1};
        case 23: return {-1, 0, 0, -1};
        case 24: return {-1, 0, 0, 1};
        case 25: return {0, -1, -1, 0};
        case 26: return {0, 1, -1, 0};
        case 27: return {0, 1, 1, 0};
        case 28: return {0, -1, 1, 0};
        default: return {1, 0, 0, 1};
    }
}

Interpreter::Interpreter(std::string_view source, const Profile& profile, MotionSink& sink,
                         std::vector<Diagnostic>& diagnostics)
    : machine_(std::make_unique<detail::Machine>(source, profile, &sink, nullptr, nullptr, diagnostics)) {}
Interpreter::Interpreter(std::string_view source, const Profile& profile, StatsSink& stats, MotionSink* also,
                         std::vector<Diagnostic>& diagnostics)
    : machine_(std::make_unique<detail::Machine>(source, profile, nullptr, &stats, also, diagnostics)) {}
Interpreter::~Interpreter() = default;
void Interpreter::run(const Tape& chunk, std::span<const MotionMeasure> measures) { machine_->run(chunk, measures); }

double units_length(long long dx, long long dy) {
    const auto x = static_cast<double>(dx), y = static_cast<double>(dy);
    return std::sqrt(x * x + y * y);
}

MotionMeasure measure_arc(long long sx, long long sy, long long ex, long long ey, long long cx, long long cy,
                          bool ccw) {
    MotionMeasure a;
    a.r0 = units_length(sx - cx, sy - cy);
    a.r1 = units_length(ex - cx, ey - cy);
    const auto point = [](long long x, long long y) { return Point{static_cast<double>(x), static_cast<double>(y)}; };
    a.sweep = arc_sweep(point(sx, sy), point(ex, ey), point(cx, cy), ccw, sx == ex && sy == ey);
    return a;
}

void measure_motions(const Tape& chunk, std::vector<MotionMeasure>& out) {
    out.clear();
    // Local pointers and the word count read once: nothing reloads them after each push_back.
    const std::int32_t* w = chunk.all_words().data();
    const Block* const blocks = chunk.blocks().data();
    const Block* const end = blocks + chunk.end_block();
    for (const Block* b = blocks; b != end; ++b) {
        const int words = b->word_count();
        if (has_measure(*b)) out.push_back(measure_arc({0, 0}, {w[0], w[1]}, {w[2], w[3]}, b->tc_positive()));
        w += words;
    }
}
void Interpreter::finish() { machine_->finish(); }
void Interpreter::send_also_to(MotionSink& also) { machine_->send_also_to(also); }

void interpret(const Tape& tape, std::string_view source, const Profile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diagnostics) {
    Interpreter interpreter(source, profile, sink, diagnostics);
    interpreter.run(tape);
    interpreter.finish();
}

}  // namespace essi
