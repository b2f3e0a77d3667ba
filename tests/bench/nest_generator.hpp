// A deterministic generator of realistic nesting tapes (ESSI, 0.1 mm units) for benchmarks and tests.
//
// The tape looks like the output of a nesting program: a 3/4 comment header, a feed (39+v), then plate
// after plate of parts. Each part is cut as its holes (full circles, counter-clockwise) followed by its
// outer contour (clockwise), each one as: rapid 5, move, 6, kerf 29, pierce 7, lead-in line, contour of
// lines and arcs (both senses; arcs at arbitrary angles have end points rounded to whole units, so they
// lie on the circle within 1 unit), 8, 38. A full plate ends with a rapid home and a stop 0; the tape
// ends with a rapid home and 63. The result checks with no error (tests/unit/nest_generator_test.cpp).
//
// Header-only, so the benchmark, the unit suite (native and WASM) and the essi_gen_nest CLI use it with no
// extra source file to wire.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace essi::bench {

enum class LineEnding { Lf, CrLf };

// A tape of at least `target_bytes` bytes (a few hundred bytes more: it always ends with a whole part and
// the program end). The same arguments give the same bytes on a given platform.
// (defined at the end of this header)
inline std::string generate_nest_tape(std::size_t target_bytes, unsigned seed, LineEnding eol = LineEnding::CrLf);

namespace detail {

inline constexpr double kPi = 3.14159265358979323846;

// splitmix64: portable and fully specified (std:: distributions are not the same everywhere).
class Rng {
public:
    explicit Rng(unsigned seed) : s_(0x9E3779B97F4A7C15ull ^ (static_cast<std::uint64_t>(seed) << 17)) {}
    std::uint64_t next() {
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [lo, hi] (hi >= lo).
    long long range(long long lo, long long hi) {
        return lo + static_cast<long long>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    // Uniform in [lo, hi).
    double real(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
    bool chance(int percent) { return range(0, 99) < percent; }

private:
    std::uint64_t s_;
};

// Writes blocks in incremental (81) mode and keeps the current position in whole units.
class TapeWriter {
public:
    TapeWriter(std::string& out, LineEnding eol) : out_(out), eol_(eol == LineEnding::CrLf ? "\r\n" : "\n") {}

    long long x() const { return x_; }
    long long y() const { return y_; }

    void text(std::string_view s) {
        out_ += s;
        end();
    }
    void function(int code) {
        number(code);
        end();
    }
    void function_value(int code, long long value) {
        number(code);
        word(value);
        end();
    }
    void line_to(long long X, long long Y) {
        word(X - x_);
        word(Y - y_);
        end();
        x_ = X;
        y_ = Y;
    }
    // Arc from the current point to (X, Y) around (CX, CY); ccw: TC '+'.
    void arc_to(long long X, long long Y, long long CX, long long CY, bool ccw) {
        word(X - x_);
        word(Y - y_);
        word(CX - x_);
        word(CY - y_);
        out_ += ccw ? '+' : '-';
        end();
        x_ = X;
        y_ = Y;
    }
    // Arc at an arbitrary end angle `phi` (radians, around the centre): the end point is rounded to whole
    // units, so it lies on the circle within sqrt(2)/2 units (arc tolerance: 2 units).
    void arc_to_angle(double phi, long long CX, long long CY, bool ccw) {
        const double r = std::hypot(static_cast<double>(x_ - CX), static_cast<double>(y_ - CY));
        const long long X = CX + std::llround(r * std::cos(phi));
        const long long Y = CY + std::llround(r * std::sin(phi));
        arc_to(X, Y, CX, CY, ccw);
    }

private:
    void number(long long v) {
        char buf[24];
        auto res = std::to_chars(buf, buf + sizeof buf, v);
        out_.append(buf, res.ptr);
    }
    void word(long long v) {
        out_ += v < 0 ? '-' : '+';
        number(v < 0 ? -v : v);
    }
    void end() { out_ += eol_; }

    std::string& out_;
    std::string_view eol_;
    long long x_ = 0, y_ = 0;
};

struct NestState {
    // The plate: 3000 x 1500 mm in 0.1 mm units, parts placed in columns from the lower left.
    static constexpr long long kPlateW = 30000, kPlateH = 15000, kMargin = 200, kGap = 350;
    long long col_x = kMargin;  // left edge of the current column
    long long col_w = 0;        // widest part in the current column
    long long cur_y = kMargin;  // next free y in the current column
    int plate = 1;
    int part = 0;
};

inline void rapid_to(TapeWriter& w, long long X, long long Y) {
    w.function(5);
    w.line_to(X, Y);
    w.function(6);
}

inline void start_cut(TapeWriter& w, Rng& rng) {
    if (rng.chance(20)) {
        w.function_value(29, 20);  // kerf width 2.0 mm, given explicitly
    } else {
        w.function(29);  // the profile's kerf
    }
    w.function(7);
}

inline void end_cut(TapeWriter& w) {
    w.function(8);
    w.function(38);
}

// A full-circle hole of radius rh around (cx, cy): pierce at the centre, lead-in to the circle, one
// counter-clockwise circle (kerf 29 = left = inside the hole).
inline void cut_hole(TapeWriter& w, Rng& rng, long long cx, long long cy, long long rh) {
    rapid_to(w, cx, cy);
    start_cut(w, rng);
    w.line_to(cx + rh, cy);
    w.arc_to(cx + rh, cy, cx, cy, true);  // DX = DY = 0: full circle
    end_cut(w);
}

// The outer contour of a W x H part at (ox, oy), clockwise (kerf 29 = left = outside), starting on the
// left edge: rounded corners (clockwise quarter arcs), a notch in the top edge (counter-clockwise half
// circle), a bulge on the right edge (clockwise arc at an arbitrary angle) and a dip in the bottom edge
// (counter-clockwise arc at an arbitrary angle).
inline void cut_outer(TapeWriter& w, Rng& rng, long long ox, long long oy, long long W, long long H) {
    const long long r = rng.chance(25) ? 0 : rng.range(40, std::min(W, H) / 6);
    const long long ys = oy + H / 2 + rng.range(-H / 10, H / 10);
    const long long lead = rng.range(80, 200);

    rapid_to(w, ox - lead, ys);
    start_cut(w, rng);
    w.line_to(ox, ys);  // lead-in

    // Left edge up, top-left corner.
    w.line_to(ox, oy + H - r);
    if (r > 0) w.arc_to(ox + r, oy + H, ox + r, oy + H - r, false);

    // Top edge to the right, with a notch (concave: counter-clockwise) in its middle third.
    const long long top_len = W - 2 * r;
    if (top_len > 400 && rng.chance(60)) {
        const long long n = rng.range(50, std::min(top_len / 6, H / 6));
        const long long a = ox + r + top_len / 3 + rng.range(0, top_len / 3 - 2 * n);
        w.line_to(a, oy + H);
        w.arc_to(a + 2 * n, oy + H, a + n, oy + H, true);
    }
    w.line_to(ox + W - r, oy + H);
    if (r > 0) w.arc_to(ox + W, oy + H - r, ox + W - r, oy + H - r, false);

    // Right edge down, with a bulge (convex: clockwise) ending at an arbitrary angle.
    const long long right_top = oy + H - r, right_bot = oy + r;
    if (right_top - right_bot > 600 && rng.chance(60)) {
        const long long yb = right_bot + (right_top - right_bot) * 3 / 4 - rng.range(0, 100);
        const long long s = rng.range(60, std::clamp<long long>((yb - right_bot - 100) / 3, 60, 300));
        const long long k = rng.range(s, 3 * s);
        w.line_to(ox + W, yb);
        const long long cx = ox + W - k, cy = yb - s;
        const double theta = std::atan2(static_cast<double>(s), static_cast<double>(k));
        w.arc_to_angle(-theta * rng.real(0.6, 1.0), cx, cy, false);
    }
    w.line_to(ox + W, oy + r);
    if (r > 0) w.arc_to(ox + W - r, oy, ox + W - r, oy + r, false);

    // Bottom edge to the left, with a dip (concave: counter-clockwise, centre below the edge) ending at an
    // arbitrary angle.
    const long long bot_len = W - 2 * r;
    if (bot_len > 600 && rng.chance(60)) {
        const long long k2 = rng.range(100, std::min(bot_len / 5, H / 4));
        const long long s2 = rng.range(k2 / 2, 2 * k2);
        const long long xb = ox + W - r - bot_len / 4;
        w.line_to(xb, oy);
        const long long cx = xb - k2, cy = oy - s2;
        const double theta = std::atan2(static_cast<double>(s2), static_cast<double>(k2));
        w.arc_to_angle(kPi - theta * rng.real(0.9, 1.1), cx, cy, true);
    }
    w.line_to(ox + r, oy);
    if (r > 0) w.arc_to(ox, oy + r, ox + r, oy + r, false);

    w.line_to(ox, ys);  // close
    end_cut(w);
}

inline void cut_part(TapeWriter& w, Rng& rng, NestState& st) {
    const long long W = rng.range(800, 4000);
    const long long H = rng.range(600, 3000);
    if (st.cur_y + H + NestState::kMargin > NestState::kPlateH) {  // next column
        st.col_x += st.col_w + NestState::kGap;
        st.col_w = 0;
        st.cur_y = NestState::kMargin;
    }
    if (st.col_x + W + NestState::kMargin > NestState::kPlateW) {  // next plate
        rapid_to(w, 0, 0);
        w.function(0);  // programmed stop: the operator changes the plate
        st.col_x = NestState::kMargin;
        st.col_w = 0;
        st.cur_y = NestState::kMargin;
        ++st.plate;
    }
    const long long ox = st.col_x, oy = st.cur_y;
    st.cur_y += H + NestState::kGap;
    st.col_w = std::max(st.col_w, W);
    ++st.part;

    // Holes along the middle, left to right.
    const int holes = static_cast<int>(rng.range(0, 4));
    if (holes > 0) {
        const long long rh_max = std::max<long long>(60, std::min(W / (3 * (holes + 1)), H / 10));
        for (int i = 0; i < holes; ++i) {
            const long long rh = rng.range(60, rh_max);
            const long long cx = ox + W * (i + 1) / (holes + 1);
            const long long cy = oy + H / 2 + rng.range(-H / 20, H / 20);
            cut_hole(w, rng, cx, cy, rh);
        }
    }
    cut_outer(w, rng, ox, oy, W, H);
}

}  // namespace detail

inline std::string generate_nest_tape(std::size_t target_bytes, unsigned seed, LineEnding eol) {
    using namespace detail;
    std::string out;
    out.reserve(target_bytes + 4096);
    TapeWriter w(out, eol);
    Rng rng(seed);
    NestState st;

    static constexpr int kFeeds[] = {800, 1200, 1400, 2000};
    w.function(3);
    w.text("NEST " + std::to_string(seed) + " - essikit benchmark tape");
    w.text("PLATE 3000 X 1500 MM, S355, 15 MM; UNITS 0.1 MM");
    w.function(4);
    w.function_value(39, kFeeds[rng.range(0, 3)]);

    const std::size_t tail = 64;  // the rapid home and 63
    while (out.size() + tail < target_bytes) cut_part(w, rng, st);

    rapid_to(w, 0, 0);
    w.function(63);
    return out;
}

}  // namespace essi::bench
