// DXF R12 of a tape's drawing (essi/dxf.hpp).
#include "essi/dxf.hpp"

#include <cmath>
#include <cstdio>

#include "essi/geom.hpp"
#include "essi/interp.hpp"
#include "essi/kerf.hpp"
#include "essi/pipeline.hpp"

namespace essi {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTextHeightMm = 2.5;  // the diagnostics' labels

struct Layer {
    const char* name;
    int colour;  // AutoCAD colour index
};
constexpr Layer kCut{"CUT", 1}, kMark{"MARK", 3}, kTravel{"TRAVEL", 8}, kKerf{"KERF", 4},
    kDiagnostics{"DIAGNOSTICS", 6};

const Layer& layer_of(MotionKind k) {
    switch (k) {
        case MotionKind::Cut: return kCut;
        case MotionKind::Mark: return kMark;
        default: return kTravel;
    }
}

// Writes group codes and values, one per line (LF).
class DxfText {
public:
    void code(int c, const std::string& v) { text_ += std::to_string(c) + "\n" + v + "\n"; }
    void number(int c, double v) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "%.6f", std::fabs(v) < 5e-7 ? 0.0 : v);
        code(c, buf);
    }
    void point(int c, Point p) {
        number(c, p.x);
        number(c + 10, p.y);
        number(c + 20, 0.0);
    }
    std::string& text() { return text_; }

private:
    std::string text_;
};

double degrees(Point from, Point to) {
    double a = std::atan2(to.y - from.y, to.x - from.x) * 180.0 / kPi;
    return a < 0 ? a + 360.0 : a;
}

// Collects the entities; remembers where each source line's motions end (for the diagnostics).
// The compensated torch path (§8) goes to the layer KERF, where compensation is on.
class DxfSink final : public MotionSink {
public:
    DxfSink(DxfText& out, const Profile& profile)
        : out_(out), profile_(profile), kerf_layer_(*this), kerf_(kerf_layer_, profile.chord_tolerance_mm) {}
    void on_motion(const MotionRecord& m) override {
        kerf_.motion(m);
        for (int c = 0; c < m.torches; ++c) draw(m, layer_of(m.kind), torch_copy({0, 0}, m.torch_step, c));
        ends_.emplace_back(m.line, m.end);
    }
    void finish() { kerf_.finish(); }
    // Where the motions of `line` (or the next line with motion) end; the last position when none.
    [[nodiscard]] Point where(std::uint32_t line) const {
        for (const auto& [l, p] : ends_)
            if (l >= line) return p;
        return ends_.empty() ? Point{} : ends_.back().second;
    }

private:
    void line(const Layer& layer, Point a, Point b) {
        out_.code(0, "LINE");
        out_.code(8, layer.name);
        out_.point(10, a);
        out_.point(11, b);
    }
    void arc(const Layer& layer, Point centre, double r, double from_deg, double to_deg) {
        out_.code(0, "ARC");
        out_.code(8, layer.name);
        out_.point(10, centre);
        out_.number(40, r);
        out_.number(50, from_deg);
        out_.number(51, to_deg);
    }
    void draw(const MotionRecord& m, const Layer& layer, Point shift) {
        const auto at = [&](Point p) { return Point{p.x + shift.x, p.y + shift.y}; };
        if (m.curve == CurveKind::Line) return line(layer, at(m.start), at(m.end));
        if (m.curve == CurveKind::Parabola) {
            std::vector<Point> pts;
            flatten(m, profile_.chord_tolerance_mm, pts, true);
            for (std::size_t k = 1; k < pts.size(); ++k) line(layer, at(pts[k - 1]), at(pts[k]));
            return;
        }
        const Point c = at(m.centre);
        const double a0 = degrees(m.centre, m.start);
        if (std::fabs(std::fabs(m.sweep) - 2 * kPi) < 1e-12) {  // a full circle: two half arcs
            arc(layer, c, m.radius, a0, std::fmod(a0 + 180.0, 360.0));
            arc(layer, c, m.radius, std::fmod(a0 + 180.0, 360.0), a0);
            return;
        }
        const double a1 = degrees(m.centre, m.end);
        if (m.ccw) arc(layer, c, m.radius, a0, a1);
        else arc(layer, c, m.radius, a1, a0);  // (DXF arcs run counter-clockwise)
    }

    class KerfLayer final : public MotionSink {
    public:
        explicit KerfLayer(DxfSink& dxf) : dxf_(dxf) {}
        void on_motion(const MotionRecord& m) override {
            if (m.kerf == KerfSide::Off) return;
            for (int c = 0; c < m.torches; ++c) dxf_.draw(m, kKerf, torch_copy({0, 0}, m.torch_step, c));
        }

    private:
        DxfSink& dxf_;
    };

    DxfText& out_;
    const Profile& profile_;
    std::vector<std::pair<std::uint32_t, Point>> ends_;
    KerfLayer kerf_layer_;
    KerfPath kerf_;
};

void header(DxfText& d) {
    d.code(0, "SECTION");
    d.code(2, "HEADER");
    d.code(9, "$ACADVER");
    d.code(1, "AC1009");
    d.code(0, "ENDSEC");
    d.code(0, "SECTION");
    d.code(2, "TABLES");
    d.code(0, "TABLE");
    d.code(2, "LAYER");
    d.code(70, "5");
    for (const Layer* l : {&kCut, &kMark, &kTravel, &kKerf, &kDiagnostics}) {
        d.code(0, "LAYER");
        d.code(2, l->name);
        d.code(70, "0");
        d.code(62, std::to_string(l->colour));
        d.code(6, "CONTINUOUS");
    }
    d.code(0, "ENDTAB");
    d.code(0, "ENDSEC");
    d.code(0, "SECTION");
    d.code(2, "ENTITIES");
}

}  // namespace

DxfResult render_dxf(std::string_view bytes, const TapeSetup& setup) {
    DxfResult r;
    DxfText d;
    header(d);
    DxfSink sink(d, setup.profile);
    const Tape tape = read_tape(bytes, setup.profile, setup.format);
    std::vector<Diagnostic> drawn;  // (the check's, below: the same list as essi check, the cut plan's too)
    interpret(tape, bytes, setup.profile, sink, drawn);
    sink.finish();
    r.diagnostics = check_tape(bytes, setup).diagnostics;
    for (const Diagnostic& diag : r.diagnostics) {
        if (diag.line == 0) continue;
        const Point p = diag.has_at ? diag.at : sink.where(diag.line);
        d.code(0, "POINT");
        d.code(8, kDiagnostics.name);
        d.point(10, p);
        d.code(0, "TEXT");
        d.code(8, kDiagnostics.name);
        d.point(10, p);
        d.number(40, kTextHeightMm);
        d.code(1, code_name(diag.code) + " line " + std::to_string(diag.line));
    }
    d.code(0, "ENDSEC");
    d.code(0, "EOF");
    r.text = std::move(d.text());
    return r;
}

}  // namespace essi
