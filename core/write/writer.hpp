// The writers' common part (core/write/, internal): the motion stream in, the target's text out. A writer gets
// lines and arcs (parabolas arrive as arcs: parabola_arcs), the functions the interpreter ran, and the end; it
// works in the target profile's unit increments, from the program's start point (the source's setup offset
// taken off), so that an incremental output never drifts from rounding.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/function_codes.hpp"
#include "essi/motion.hpp"
#include "essi/write.hpp"

namespace essi::detail {

// A point in the target's unit increments.
struct Units {
    long long x = 0, y = 0;
    friend bool operator==(const Units&, const Units&) = default;
};

class ProgramWriter : public MotionSink {
public:
    ProgramWriter(const Profile& source, const ConvertOptions& options, std::vector<Diagnostic>& diagnostics);
    void on_motion(const MotionRecord& m) final;
    void on_event(const MachineEvent& e) final;
    // The whole text, once the stream is done.
    [[nodiscard]] virtual std::string finish() = 0;

protected:
    virtual void line(const MotionRecord& m, Units end) = 0;
    virtual void arc(const MotionRecord& m, Units end, Units centre) = 0;  // centre in absolute units
    virtual void function(const MachineEvent& e) = 0;
    virtual void end(const MachineEvent& e) = 0;
    virtual void comment(const std::string& text) = 0;

    // The functions a conversion does not write: their effect is in the coordinates (21-28 mapping, 81/82 mode,
    // 83 origin) or in the motion itself (5/6 where the target's motions say rapid).
    [[nodiscard]] static bool applied_in_geometry(int code);
    // A function that is no end in the source but one of the target's end codes (63 from ISO to Woyda).
    [[nodiscard]] bool would_end_program(const MachineEvent& e) const;
    void warn(DiagCode code, std::uint32_t line, Msg msg, MessageArgs args = {});
    // W501 for function `code` at `line`, with its name from the source dialect; the comment text "ESSI 45:
    // Torch head lower".
    std::string no_counterpart(const MachineEvent& e, std::string_view target);
    // Where the current motion's head is (each head keeps its own position: docs/semantics.md §2).
    [[nodiscard]] Units position() const { return pos_[head_]; }
    // The current motion is head 2's (a 3-axis tape, ISO 3.2).
    [[nodiscard]] bool head_two() const { return head_ == 1; }
    // Whether the target has head addresses (ESSI's leading 1 or 2): else head 2's motions are left out, with W501.
    [[nodiscard]] virtual bool writes_head_addresses() const { return false; }

    const Profile& source_;
    const ConvertOptions& options_;
    std::string out_;

public:
    // After the stream: the end of the program when the source ended at the end of its data (ISO), and W503 once
    // for the program, with the count, at the first rounded coordinate's line.
    void close();

private:
    Units to_units(Point mm, std::uint32_t line);
    std::vector<Diagnostic>& diagnostics_;
    Units pos_[2] = {};               // where each head's last motion ended (target units)
    int head_ = 0;                    // the current motion's head: 0 head 1, 1 head 2
    bool head_two_left_out_ = false;  // head 2's motions were left out (one W501)
    std::size_t rounded_ = 0;         // coordinates rounded to the target's unit
    std::uint32_t rounded_line_ = 0;  // the first one's line
    bool ended_ = false;              // the end of the program was written
    std::uint32_t last_line_ = 0;
    // A function that cancels in the source but ends the program in the target (ISO 63 -> Woyda): nothing when
    // the program ends right after it (as real tapes do), else a comment (W501) where the program goes on.
    std::optional<MachineEvent> pending_cancel_;
    void flush_cancel();
};

// "12.5" from units of 10^-decimals mm (exact), or %.6g for units that are no power of ten.
[[nodiscard]] std::string mm_text(long long units, const Profile& target, int max_decimals = 6);

// A parabola (MotionRecord with CurveKind::Parabola) as arcs through three points of it, each within
// `tolerance_mm` of the curve; the last ends at the parabola's end exactly.
[[nodiscard]] std::vector<MotionRecord> parabola_arcs(const MotionRecord& parabola, double tolerance_mm);

std::unique_ptr<ProgramWriter> make_essi_writer(const Profile& source, const ConvertOptions& o,
                                                std::vector<Diagnostic>& d);
std::unique_ptr<ProgramWriter> make_eia_writer(const Profile& source, const ConvertOptions& o,
                                               std::vector<Diagnostic>& d);
std::unique_ptr<ProgramWriter> make_gcode_writer(const Profile& source, const ConvertOptions& o,
                                                 std::vector<Diagnostic>& d);

}  // namespace essi::detail
