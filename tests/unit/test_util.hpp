// Shared helpers for the core unit tests: a sink that records the motion stream, a one-call
// read + interpret runner, diagnostic look-ups and the named tolerances every test uses.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"  // essi::kPi
#include "essi/interp.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/pipeline.hpp"

namespace essi_test {

// Named tolerances (mm, rad, s). Positions are unit increments times 0.1 mm: exact to rounding.
constexpr double kPosTol = 1e-9;   // mm, positions that are integer units * unit_mm
constexpr double kLenTol = 1e-6;   // mm, closed-form lengths
constexpr double kAngTol = 1e-9;   // rad, sweeps
constexpr double kTimeTol = 1e-6;  // s, time estimates

// The lines of `s` by the line-end rule (CR, LF, CR LF, LF CR), written out the plain way: what the line index
// and the reader must agree with. A line end at the very end starts no line.
inline std::vector<std::string> split_lines(const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c != '\n' && c != '\r') {
            cur += c;
            continue;
        }
        if (i + 1 < s.size() && (s[i + 1] == '\n' || s[i + 1] == '\r') && s[i + 1] != c) ++i;
        out.push_back(cur);
        cur.clear();
    }
    if (!cur.empty() || (out.empty() && !s.empty())) out.push_back(cur);
    return out;
}

// A tape with every line ending, tabs and other control bytes, bytes above 0x7F, lines longer than 8 bytes and
// empty ones, more lines than the line index's stride, and no line end after the last line.
inline std::string tricky_lines_text() {
    std::string text = "%\r\n3\r\nNEST \x01\x0d\tTAB\x0b\x0c\x80\xff LONGER THAN EIGHT BYTES\n4\n\n\r\r\n\r";
    for (int k = 0; k < 300; ++k) {
        text += "+" + std::to_string(k * 7) + "-" + std::to_string(k);
        text += k % 4 == 0 ? "\r\n" : k % 4 == 1 ? "\n" : k % 4 == 2 ? "\n\r" : "\r";
        if (k % 37 == 0) text += "7\t\x02\n";
    }
    text += "63";
    return text;
}

// Records every motion and event in program order.
class RecordingSink : public essi::MotionSink {
public:
    std::vector<essi::MotionRecord> motions;
    std::vector<essi::MachineEvent> events;
    std::string order;  // 'm' for a motion, 'e' for an event, in arrival order

    void on_motion(const essi::MotionRecord& m) override {
        motions.push_back(m);
        order.push_back('m');
    }
    void on_event(const essi::MachineEvent& e) override {
        events.push_back(e);
        order.push_back('e');
    }
    [[nodiscard]] std::vector<essi::MachineEvent> events_of(essi::EventKind k) const {
        std::vector<essi::MachineEvent> out;
        for (const auto& e : events)
            if (e.kind == k) out.push_back(e);
        return out;
    }
    [[nodiscard]] const essi::MachineEvent* event_with_code(essi::EventKind k, int code) const {
        for (const auto& e : events)
            if (e.kind == k && e.code == code) return &e;
        return nullptr;
    }
};

inline std::string dump(const std::vector<essi::Diagnostic>& diags) {
    std::ostringstream os;
    for (const auto& d : diags)
        os << essi::code_name(d.code) << " line " << d.line << " col " << d.column << ": "
           << essi::diagnostic_message(d, essi::Lang::En) << "\n";
    return os.str();
}

inline std::size_t count_code(const std::vector<essi::Diagnostic>& diags, essi::DiagCode code) {
    std::size_t n = 0;
    for (const auto& d : diags)
        if (d.code == code) ++n;
    return n;
}
inline bool has_code(const std::vector<essi::Diagnostic>& diags, essi::DiagCode code) {
    return count_code(diags, code) > 0;
}
inline const essi::Diagnostic* find_code(const std::vector<essi::Diagnostic>& diags, essi::DiagCode code) {
    for (const auto& d : diags)
        if (d.code == code) return &d;
    return nullptr;
}
inline bool has_code_at(const std::vector<essi::Diagnostic>& diags, essi::DiagCode code, std::uint32_t line,
                        std::uint32_t column) {
    for (const auto& d : diags)
        if (d.code == code && d.line == line && d.column == column) return true;
    return false;
}
inline bool has_severity(const std::vector<essi::Diagnostic>& diags, essi::Severity s) {
    for (const auto& d : diags)
        if (d.severity == s) return true;
    return false;
}

// read + interpret; `diags` holds the read diagnostics followed by those of interpretation.
struct RunResult {
    std::string source;
    essi::Tape tape;
    std::vector<essi::Diagnostic> diags;
    RecordingSink sink;

    [[nodiscard]] const std::vector<essi::MotionRecord>& motions() const { return sink.motions; }
    [[nodiscard]] const std::vector<essi::MachineEvent>& events() const { return sink.events; }
    [[nodiscard]] bool has(essi::DiagCode c) const { return has_code(diags, c); }
    [[nodiscard]] std::string dump() const { return essi_test::dump(diags); }
};

inline RunResult run(std::string_view text, const essi::Profile& profile = essi::Profile{}) {
    RunResult r;
    r.source.assign(text.data(), text.size());
    r.tape = essi::read_tape(r.source, profile);
    r.diags = r.tape.diagnostics();
    essi::interpret(r.tape, r.source, profile, r.sink, r.diags);
    return r;
}

inline essi::Profile iso_profile() {
    auto p = essi::builtin_profile("iso6582");
    return p ? *p : essi::Profile{};
}
inline essi::Profile woyda_profile() {
    auto p = essi::builtin_profile("woyda");
    EXPECT_TRUE(p.has_value()) << "built-in profile 'woyda' missing";
    return p ? *p : essi::Profile{};
}

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Two checks of the same tape that must agree to the bit (one thread or two, measures ahead or not): every
// statistic, the doubles compared bit for bit, and every diagnostic.
inline void expect_same_result(const essi::CheckResult& a, const essi::CheckResult& b, const std::string& what) {
    SCOPED_TRACE(what);
    const essi::Stats &x = a.stats, &y = b.stats;
    EXPECT_TRUE(same_bits(x.cut_length_mm, y.cut_length_mm));
    EXPECT_TRUE(same_bits(x.mark_length_mm, y.mark_length_mm));
    EXPECT_TRUE(same_bits(x.travel_length_mm, y.travel_length_mm));
    EXPECT_TRUE(same_bits(x.rapid_length_mm, y.rapid_length_mm));
    EXPECT_TRUE(same_bits(x.estimated_time_s, y.estimated_time_s));
    EXPECT_EQ(x.pierces, y.pierces);
    EXPECT_EQ(x.blocks, y.blocks);
    EXPECT_EQ(x.motions, y.motions);
    for (const auto& [p, q] : {std::pair{x.cut_bbox, y.cut_bbox}, std::pair{x.motion_bbox, y.motion_bbox}}) {
        EXPECT_EQ(p.empty, q.empty);
        EXPECT_TRUE(same_bits(p.min_x, q.min_x) && same_bits(p.min_y, q.min_y) && same_bits(p.max_x, q.max_x) &&
                    same_bits(p.max_y, q.max_y));
    }
    EXPECT_TRUE(same_bits(x.end_position.x, y.end_position.x) && same_bits(x.end_position.y, y.end_position.y));
    ASSERT_EQ(a.diagnostics.size(), b.diagnostics.size());
    for (std::size_t i = 0; i < a.diagnostics.size(); ++i) {
        const essi::Diagnostic &d = a.diagnostics[i], &e = b.diagnostics[i];
        EXPECT_EQ(essi::code_name(d.code), essi::code_name(e.code));
        EXPECT_EQ(d.line, e.line);
        EXPECT_EQ(d.column, e.column);
        EXPECT_EQ(essi::diagnostic_message(d, essi::Lang::En), essi::diagnostic_message(e, essi::Lang::En));
    }
}

// How two records of one motion must agree: to the bit (the interpreter's stream, however it was delivered), or
// as the viewer's compact document rebuilds it (feed and kerf kept as float, the block index not kept).
enum class RecordMatch { Exact, ViewerDocument };

// Every field of `got` against `want` (ASSERTs: the caller checks HasFatalFailure() to stop a loop).
inline void expect_same_record(const essi::MotionRecord& got, const essi::MotionRecord& want, const std::string& at,
                               RecordMatch how = RecordMatch::Exact) {
    const bool exact = how == RecordMatch::Exact;
    ASSERT_EQ(got.line, want.line) << at;
    if (exact) {
        ASSERT_EQ(got.block, want.block) << at;
    }
    ASSERT_EQ(got.kind, want.kind) << at;
    ASSERT_EQ(got.curve, want.curve) << at;
    ASSERT_EQ(got.tools, want.tools) << at;
    ASSERT_EQ(got.head, want.head) << at;
    ASSERT_EQ(got.kerf, want.kerf) << at;
    ASSERT_EQ(got.ccw, want.ccw) << at;
    for (const auto& [x, y] :
         {std::pair{got.start, want.start}, std::pair{got.end, want.end}, std::pair{got.centre, want.centre}})
        ASSERT_TRUE(same_bits(x.x, y.x) && same_bits(x.y, y.y)) << at;
    for (const auto& [x, y] : {std::pair{got.radius, want.radius}, std::pair{got.end_radius, want.end_radius},
                               std::pair{got.sweep, want.sweep}, std::pair{got.length_mm, want.length_mm}})
        ASSERT_TRUE(same_bits(x, y)) << at;
    const auto kept = [exact](double v) { return exact ? v : static_cast<double>(static_cast<float>(v)); };
    ASSERT_TRUE(same_bits(got.feed_mm_min, kept(want.feed_mm_min))) << at;
    ASSERT_TRUE(same_bits(got.kerf_mm, kept(want.kerf_mm))) << at;
    if (want.curve == essi::CurveKind::Parabola) {
        const essi::ParabolaGeom &g = got.parabola, &w = want.parabola;
        ASSERT_TRUE(same_bits(g.vertex.x, w.vertex.x) && same_bits(g.vertex.y, w.vertex.y) && same_bits(g.t0, w.t0) &&
                    same_bits(g.t1, w.t1) && same_bits(g.p, w.p))
            << at;
    }
}

#define EXPECT_POINT_NEAR(p, ex, ey, tol)                   \
    do {                                                    \
        const essi::Point essi_pt_ = (p);                   \
        EXPECT_NEAR(essi_pt_.x, (ex), (tol)) << "x of " #p; \
        EXPECT_NEAR(essi_pt_.y, (ey), (tol)) << "y of " #p; \
    } while (0)

}  // namespace essi_test
