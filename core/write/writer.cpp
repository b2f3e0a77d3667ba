// The writers' common part and convert_tape (essi/write.hpp, core/write/writer.hpp).
#include "writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "essi/functions.hpp"
#include "essi/geom.hpp"
#include "essi/interp.hpp"
#include "essi/pipeline.hpp"
#include "essi/text.hpp"

namespace essi {
namespace detail {
namespace {

constexpr double kOnGrid = 1e-6;  // units: a coordinate this close to a whole unit is on the grid
constexpr int kMaxArcsPerParabola = 4096;
constexpr double kGcodeUnitMm = 1e-4;  // G-code coordinates: mm to 4 decimals

// The circle through three points: false when they are (nearly) on a line.
bool circle_through(Point a, Point b, Point c, Point& centre) {
    const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    if (std::fabs(d) < 1e-12) return false;
    const double a2 = a.x * a.x + a.y * a.y, b2 = b.x * b.x + b.y * b.y, c2 = c.x * c.x + c.y * c.y;
    centre = {(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
              (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d};
    return true;
}

double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

ProgramWriter::ProgramWriter(const Profile& source, const ConvertOptions& options, std::vector<Diagnostic>& diagnostics)
    : source_(source), options_(options), diagnostics_(diagnostics) {}

Units ProgramWriter::to_units(Point mm, std::uint32_t line) {
    const double ux = mm.x / options_.target.unit_mm;
    const double uy = mm.y / options_.target.unit_mm;
    const Units u{std::llround(ux), std::llround(uy)};
    if (std::fabs(ux - static_cast<double>(u.x)) > kOnGrid || std::fabs(uy - static_cast<double>(u.y)) > kOnGrid) {
        if (rounded_++ == 0) rounded_line_ = line;
    }
    return u;
}

void ProgramWriter::flush_cancel() {
    if (!pending_cancel_) return;
    const MachineEvent e = *pending_cancel_;
    pending_cancel_.reset();
    comment(no_counterpart(e, "the " + options_.target.name + " dialect, where it ends the program"));
}

void ProgramWriter::close() {
    if (!ended_) {  // the source ended at the end of its data (ISO): the target's end code
        MachineEvent e;
        e.kind = EventKind::End;
        e.line = last_line_;
        pending_cancel_.reset();
        end(e);
    }
    if (rounded_ == 0 || options_.to == OutputFormat::Gcode) return;  // (G-code: 0.1 um, below any machine's step)
    warn(DiagCode::W503_RoundedToUnit, rounded_line_, Msg::WriteRounded,
         {rounded_, number_text(options_.target.unit_mm), options_.target.name});
}

void ProgramWriter::warn(DiagCode code, std::uint32_t line, Msg msg, MessageArgs args) {
    diagnostics_.push_back(make_diagnostic(default_severity(code), code, line, 1, msg, std::move(args)));
}

std::string ProgramWriter::no_counterpart(const MachineEvent& e, std::string_view target) {
    const auto info = function_info(e.code, source_.dialect);
    std::string name = "ESSI " + std::to_string(e.code);
    if (e.has_value) name += "+" + number_text(e.value);
    if (info) name += ": " + std::string(info->name);
    warn(DiagCode::W501_NoCounterpart, e.line, Msg::WriteNoCounterpart,
         {e.code, info ? " (" + std::string(info->name) + ")" : std::string(), target});
    return name;
}

bool ProgramWriter::applied_in_geometry(int code) {
    return (code >= fn::kAxesNormal && code <= fn::kAxesMappingLast) || code == fn::kIncremental ||
           code == fn::kAbsolute || code == fn::kZeroOffset || code == fn::kIgnoreOn || code == fn::kIgnoreOff ||
           code == fn::kOptionalIgnoreOn || code == fn::kOptionalIgnoreOff;
}

bool ProgramWriter::would_end_program(const MachineEvent& e) const {
    return std::any_of(options_.target.end_codes.begin(), options_.target.end_codes.end(),
                       [&](const EndCode& c) { return c.function == e.code; });
}

void ProgramWriter::on_motion(const MotionRecord& m) {
    flush_cancel();
    last_line_ = m.line;
    if (m.curve == CurveKind::Parabola) {
        const std::vector<MotionRecord> arcs = parabola_arcs(m, source_.chord_tolerance_mm);
        warn(DiagCode::W502_ParabolaAsArcs, m.line, Msg::WriteParabolaAsArcs,
             {arcs.size(), number_text(source_.chord_tolerance_mm)});
        for (const MotionRecord& a : arcs) on_motion(a);
        return;
    }
    head_ = m.head == 2 ? 1 : 0;
    if (head_two() && !writes_head_addresses()) {
        if (!head_two_left_out_)
            warn(DiagCode::W501_NoCounterpart, m.line, Msg::WriteHeadTwoLeftOut,
                 {options_.to == OutputFormat::Gcode ? "G-code" : "EIA"});
        head_two_left_out_ = true;
        return;
    }
    const Units end = to_units(m.end, m.line);
    if (m.curve == CurveKind::Arc) arc(m, end, to_units(m.centre, m.line));
    else line(m, end);
    pos_[head_] = end;
}

void ProgramWriter::on_event(const MachineEvent& e) {
    last_line_ = e.line;
    if (e.kind == EventKind::End) {
        pending_cancel_.reset();  // (the end right after it: the cancel was the end)
        ended_ = true;
        end(e);
        return;
    }
    flush_cancel();
    switch (e.kind) {
        case EventKind::ZeroOffset: break;  // (in the coordinates)
        default:
            if (applied_in_geometry(e.code)) break;
            // 63 that cancels the functions in the source but ends the program in the target (ISO -> Woyda): not
            // written as such (the tools are off by their own blocks, or the next ones say it)
            if (would_end_program(e)) {
                pending_cancel_ = e;
                break;
            }
            function(e);
            break;
    }
}

std::string mm_text(long long units, const Profile& target, int max_decimals) {
    int decimals = -1;
    double scale = 1;
    for (int k = 0; k <= max_decimals; ++k, scale *= 10)
        if (std::fabs(target.unit_mm * scale - 1.0) < 1e-9) decimals = k;
    char buf[48];
    if (decimals < 0) {
        std::snprintf(buf, sizeof buf, "%.*f", max_decimals, static_cast<double>(units) * target.unit_mm);
        std::string s = buf;
        while (s.find('.') != std::string::npos && (s.back() == '0' || s.back() == '.')) {
            const bool dot = s.back() == '.';
            s.pop_back();
            if (dot) break;
        }
        return s == "-0" ? "0" : s;
    }
    long long p = 1;
    for (int k = 0; k < decimals; ++k) p *= 10;
    const bool negative = units < 0;
    const unsigned long long a =
        negative ? 0ULL - static_cast<unsigned long long>(units) : static_cast<unsigned long long>(units);
    std::string s = (negative ? "-" : "") + std::to_string(a / static_cast<unsigned long long>(p));
    unsigned long long frac = a % static_cast<unsigned long long>(p);
    if (frac != 0) {
        std::string f = std::to_string(frac);
        f.insert(0, static_cast<std::size_t>(decimals) - f.size(), '0');
        while (!f.empty() && f.back() == '0') f.pop_back();
        s += "." + f;
    }
    return s;
}

std::vector<MotionRecord> parabola_arcs(const MotionRecord& m, double tolerance_mm) {
    const ParabolaGeom& g = m.parabola;
    for (int n = 1;; n *= 2) {
        std::vector<MotionRecord> arcs;
        bool fits = true;
        for (int k = 0; k < n && fits; ++k) {
            const double t0 = g.t0 + (g.t1 - g.t0) * k / n, t1 = g.t0 + (g.t1 - g.t0) * (k + 1) / n;
            const Point a = k == 0 ? m.start : parabola_point(g, t0), b = parabola_point(g, (t0 + t1) / 2);
            const Point c = k == n - 1 ? m.end : parabola_point(g, t1);
            MotionRecord r = m;
            r.curve = CurveKind::Arc;
            r.start = a;
            r.end = c;
            if (!circle_through(a, b, c, r.centre)) {  // (straight enough: a line)
                r.curve = CurveKind::Line;
            } else {
                r.radius = distance(a, r.centre);
                r.end_radius = distance(c, r.centre);
                r.ccw = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) > 0;
                r.sweep = arc_sweep(a, c, r.centre, r.ccw, false);
                // the curve between the sample points must stay within the tolerance of the circle
                for (double q : {0.25, 0.75}) {
                    const Point p = parabola_point(g, t0 + (t1 - t0) * q);
                    fits = fits && std::fabs(distance(p, r.centre) - r.radius) <= tolerance_mm;
                }
            }
            arcs.push_back(r);
        }
        if (fits || n >= kMaxArcsPerParabola) return arcs;
    }
}

}  // namespace detail

const char* output_format_name(OutputFormat f) {
    switch (f) {
        case OutputFormat::Essi: return "essi";
        case OutputFormat::Eia: return "eia";
        case OutputFormat::Gcode: return "gcode";
    }
    return "essi";
}

std::optional<OutputFormat> parse_output_format(std::string_view name) {
    for (const OutputFormat f : kOutputFormats)
        if (name == output_format_name(f)) return f;
    return std::nullopt;
}

bool ConvertResult::ok() const {
    return std::none_of(diagnostics.begin(), diagnostics.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

ConvertResult convert_tape(std::string_view bytes, const TapeSetup& source, const ConvertOptions& options) {
    ConvertResult r;
    CheckResult check = check_tape(bytes, source);
    const bool errors = !check.ok();
    r.diagnostics = std::move(check.diagnostics);
    if (errors && !options.force) {
        r.refused = true;
        return r;
    }
    // G-code is written in mm to 4 decimals, whatever the target's ESSI unit.
    ConvertOptions o = options;
    if (o.to == OutputFormat::Gcode) o.target.unit_mm = detail::kGcodeUnitMm;
    std::unique_ptr<detail::ProgramWriter> writer;
    switch (o.to) {
        case OutputFormat::Essi: writer = detail::make_essi_writer(source.profile, o, r.diagnostics); break;
        case OutputFormat::Eia: writer = detail::make_eia_writer(source.profile, o, r.diagnostics); break;
        case OutputFormat::Gcode: writer = detail::make_gcode_writer(source.profile, o, r.diagnostics); break;
    }
    const Tape tape = read_tape(bytes, source.profile, source.format);
    std::vector<Diagnostic> checked_again;  // (the check's own, already in r.diagnostics)
    interpret(tape, bytes, source.profile, *writer, checked_again);
    writer->close();
    r.text = writer->finish();
    sort_diagnostics(r.diagnostics);
    return r;
}

}  // namespace essi
