// The trace: the motion stream as text, one record a line (LinuxCNC's canonical-motion printout is the
// model). Numbers are fixed to 3 decimals (micrometres) so golden files diff cleanly.
#include "essi/trace.hpp"

#include "essi/kerf.hpp"
#include "essi/placement.hpp"

#include <cmath>
#include <cstdio>

#include "essi/function_codes.hpp"
#include "essi/functions.hpp"
#include "essi/geom.hpp"
#include "essi/interp.hpp"
#include "essi/read.hpp"
#include "essi/report.hpp"

namespace essi {
namespace {

// Prints -0.000 as 0.000.
double tidy(double v, int decimals) { return std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v; }

// `fmt` with "%.*f" for each number (written to `decimals`).
void append(std::string& s, const char* fmt, int decimals, double a, double b) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, decimals, tidy(a, decimals), decimals, tidy(b, decimals));
    s += buf;
}

void append(std::string& s, const char* fmt, int decimals, double a) {
    char buf[96];
    std::snprintf(buf, sizeof buf, fmt, decimals, tidy(a, decimals));
    s += buf;
}

// Buffers lines and hands them to the writer in chunks of about kTraceChunkBytes.
class TraceSink : public MotionSink {
public:
    static constexpr std::size_t kTraceChunkBytes = 1 << 16;
    TraceSink(const TraceWriter& write, Dialect dialect, int decimals)
        : write_(write), dialect_(dialect), decimals_(decimals) {}
    ~TraceSink() override { flush(); }
    void on_motion(const MotionRecord& m) override { add(trace_line(m, decimals_)); }
    void on_event(const MachineEvent& e) override { add(trace_line(e, dialect_)); }
    void add(const std::string& line) {
        buffer_ += line;
        buffer_ += '\n';
        if (buffer_.size() >= kTraceChunkBytes) flush();
    }
    void flush() {
        if (!buffer_.empty()) write_(buffer_);
        buffer_.clear();
    }

private:
    const TraceWriter& write_;
    Dialect dialect_;
    int decimals_;
    std::string buffer_;
};

}  // namespace

std::string trace_line(const MotionRecord& m, int d) {
    std::string s = std::to_string(m.line);
    s += ' ';
    s += motion_kind_name(m.kind);
    s += ' ';
    s += curve_kind_name(m.curve);
    if (m.head != 1) s += " head=" + std::to_string(m.head);
    append(s, " (%.*f,%.*f)", d, m.start.x, m.start.y);
    append(s, "->(%.*f,%.*f)", d, m.end.x, m.end.y);
    if (m.curve == CurveKind::Arc) {
        append(s, " c=(%.*f,%.*f)", d, m.centre.x, m.centre.y);
        append(s, " r=%.*f", d, m.radius);
        s += m.ccw ? " ccw" : " cw";
        append(s, " sweep=%.*f", d, m.sweep * 180.0 / kPi);
    } else if (m.curve == CurveKind::Parabola) {
        append(s, " v=(%.*f,%.*f)", d, m.parabola.vertex.x, m.parabola.vertex.y);
        append(s, " axis=(%.*f,%.*f)", 0, m.parabola.n.x, m.parabola.n.y);
        append(s, " p=%.*f", d, m.parabola.p);
        s += m.ccw ? " ccw" : " cw";
    }
    append(s, " len=%.*f", d, m.length_mm);
    s += " tools=" + tools_text(m.tools);
    append(s, " feed=%.*f", 0, m.feed_mm_min);
    if (m.kerf != KerfSide::Off) {
        s += " kerf=";
        s += kerf_side_name(m.kerf);
        append(s, ":%.*f", d, m.kerf_mm);
    }
    if (m.torches > 1) {
        s += " torches=" + std::to_string(m.torches);
        append(s, " step=(%.*f,%.*f)", d, m.torch_step.x, m.torch_step.y);
    }
    return s;
}

std::string trace_line(const MachineEvent& e, Dialect dialect) {
    std::string s = std::to_string(e.line);
    char buf[96];
    switch (e.kind) {
        case EventKind::Function: {
            s += " fn " + std::to_string(e.code);
            const auto info = function_info(e.code, dialect);
            if (info) {
                s += ' ';
                s += info->name;
            }
            break;
        }
        case EventKind::Dwell:
            std::snprintf(buf, sizeof buf, " dwell %.3f s", e.value);
            s += buf;
            break;
        case EventKind::Stop: s += e.code == fn::kProgramStop ? " stop 0 programmed" : " stop 102 optional"; break;
        case EventKind::End: s += e.code ? " end " + std::to_string(e.code) : std::string(" end"); break;
        case EventKind::ZeroOffset:
            std::snprintf(buf, sizeof buf, " origin (%.3f,%.3f)", tidy(e.x, kTraceDecimals), tidy(e.y, kTraceDecimals));
            s += buf;
            break;
    }
    if (e.kind == EventKind::Function && e.has_value) {
        std::snprintf(buf, sizeof buf, " value=%g", e.value);
        s += buf;
    }
    s += " tools=" + tools_text(e.tools_after);
    return s;
}

std::vector<Diagnostic> trace_tape(std::string_view bytes, const Profile& profile, const TraceWriter& write,
                                   InputFormat format, int decimals, TraceView view) {
    const Tape tape = read_tape(bytes, profile, format);
    std::vector<Diagnostic> diagnostics = tape.diagnostics();
    TraceSink sink(write, profile.dialect, decimals);
    // The chain: (the kerf path ->) (the machine's coordinates ->) the trace.
    MachineSink placed(sink, profile);
    MotionSink& after_kerf = view.machine ? static_cast<MotionSink&>(placed) : sink;
    if (view.kerf) {
        KerfSink torch(after_kerf, profile.chord_tolerance_mm);
        interpret(tape, bytes, profile, torch, diagnostics);
        torch.finish();
        for (KerfGouge& g : torch.take_gouges())
            diagnostics.push_back(
                make_diagnostic(Severity::Error, DiagCode::E307_KerfGouge, g.line, 1, g.msg, std::move(g.args)));
    } else {
        interpret(tape, bytes, profile, after_kerf, diagnostics);
    }
    sort_diagnostics(diagnostics);
    for (const auto& d : diagnostics) {
        sink.add("# " + code_name(d.code) + " line " + std::to_string(d.line) + " col " + std::to_string(d.column) +
                 ": " + diagnostic_message(d, Lang::En));
    }
    sink.flush();
    return diagnostics;
}

std::string trace_tape(std::string_view bytes, const Profile& profile, InputFormat format) {
    std::string out;
    (void)trace_tape(
        bytes, profile, [&](std::string_view piece) { out += piece; }, format);
    return out;
}

}  // namespace essi
