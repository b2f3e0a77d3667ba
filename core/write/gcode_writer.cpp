// The G-code writer (essi/write.hpp): RS-274/NGC as LinuxCNC reads it (docs/conversions.md). G17 G21 G40 G90|G91
// G91.1 G94 at the start; G0 for rapid motion, G1/G2/G3 with F for the rest; the cutting tools as QtPlasmaC's
// M3 $0 S1 / M5 $0, the marking tools as M3 $1 S1 / M5 $1; kerf as G41.1/G42.1 D<kerf width> and G40, written before
// the motion whose compensation differs from the last written (the side as the motion has it, after a mirror; G40
// first when it was on: LinuxCNC does not switch sides while on); G4 P<s>;
// M0, M1; M2 at the end; every other function a comment (W501). Coordinates in mm with 4 decimals.
#include <cmath>

#include "essi/text.hpp"
#include "writer.hpp"

namespace essi::detail {
namespace {

constexpr double kRadiusTolerance = 1e-4;  // mm: an arc whose radii differ more gets a centre on the bisector

class GcodeWriter final : public ProgramWriter {
public:
    GcodeWriter(const Profile& source, const ConvertOptions& o, std::vector<Diagnostic>& d)
        : ProgramWriter(source, o, d) {
        out_ = std::string("G17 G21 G40 ") + (o.absolute ? "G90" : "G91") + " G91.1 G94\n";
    }
    std::string finish() override { return std::move(out_); }

private:
    void block(const std::string& text) { out_ += text + "\n"; }
    void comment(const std::string& text) override { block("(" + text + ")"); }
    std::string coordinate(char letter, long long units) const {
        return std::string(1, letter) + mm_text(units, options_.target, 4);
    }
    std::string point(Units p) const {
        const Units base = options_.absolute ? Units{} : position();
        return coordinate('X', p.x - base.x) + " " + coordinate('Y', p.y - base.y);
    }
    std::string feed(const MotionRecord& m) {
        if (m.feed_mm_min == feed_ || !(m.feed_mm_min > 0)) return {};
        feed_ = m.feed_mm_min;
        return " F" + number_text(feed_);
    }
    // The compensation the motion is made with (docs/semantics.md §8), written when it differs from the last.
    void compensation(const MotionRecord& m) {
        const KerfSide side = m.kerf_mm > 0 ? m.kerf : KerfSide::Off;
        if (side == kerf_ && (side == KerfSide::Off || m.kerf_mm == kerf_mm_)) return;
        if (kerf_ != KerfSide::Off) block("G40");
        kerf_ = side;
        kerf_mm_ = m.kerf_mm;
        if (side != KerfSide::Off)
            block(std::string(side == KerfSide::Left ? "G41.1" : "G42.1") + " D" + number_text(2 * m.kerf_mm));
    }
    void line(const MotionRecord& m, Units end) override {
        compensation(m);
        if (m.kind == MotionKind::Rapid) block("G0 " + point(end));
        else block("G1 " + point(end) + feed(m));
    }
    void arc(const MotionRecord& m, Units end, Units centre) override {
        compensation(m);
        const Units start = position();
        // LinuxCNC wants the end on the circle (within about a micrometre); an ESSI arc may miss it by the profile's
        // arc tolerance: then the centre goes to the nearest point of the chord's bisector.
        double cx = static_cast<double>(centre.x), cy = static_cast<double>(centre.y);
        const double r0 = std::hypot(cx - start.x, cy - start.y), r1 = std::hypot(cx - end.x, cy - end.y);
        if (std::fabs(r0 - r1) * options_.target.unit_mm > kRadiusTolerance && !(start == end)) {
            const double mx = (start.x + end.x) / 2.0, my = (start.y + end.y) / 2.0;
            const double nx = -(end.y - start.y), ny = end.x - start.x, nn = nx * nx + ny * ny;
            const double t = ((cx - mx) * nx + (cy - my) * ny) / nn;
            cx = mx + t * nx;
            cy = my + t * ny;
        }
        const Units c{std::llround(cx), std::llround(cy)};
        block(std::string(m.ccw ? "G3 " : "G2 ") + point(end) + " " + coordinate('I', c.x - start.x) + " " +
              coordinate('J', c.y - start.y) + feed(m));
    }
    // The tools: cutting (M3 $0 S1 / M5 $0) and marking (M3 $1 S1 / M5 $1) as they go on and off.
    bool tools(const MachineEvent& e) {
        const std::uint8_t before = tools_;
        tools_ = e.tools_after;
        const bool cut_before = (before & kCuttingTools) != 0, cut_after = (tools_ & kCuttingTools) != 0;
        const bool mark_before = (before & kMarkingTools) != 0, mark_after = (tools_ & kMarkingTools) != 0;
        if (cut_after != cut_before) block(cut_after ? "M3 $0 S1" : "M5 $0");
        if (mark_after != mark_before) block(mark_after ? "M3 $1 S1" : "M5 $1");
        return before != tools_;
    }
    void function(const MachineEvent& e) override {
        if (tools(e)) return;
        switch (e.code) {
            case fn::kRapidOn:
            case fn::kRapidOff:
            case fn::kFeed: return;  // (G0 and F on the motions)
            case fn::kKerfLeft:
            case fn::kKerfRight:
            case fn::kKerfOff: return;  // (with the motions: compensation())
            case fn::kDwell: block("G4 P" + number_text(e.value)); return;
            case fn::kProgramStop: block("M0"); return;
            case fn::kCancelFunctions:
            case fn::kEndOfTape:
                return;  // (no end here: the stored functions cancelled; tools above, kerf with the motions)
            case fn::kOptionalStop: block("M1"); return;
            default: break;
        }
        const bool tool_word = e.code == fn::kOxygenOn || e.code == fn::kOxygenOff || e.code == fn::kPlasmaOn ||
                               e.code == fn::kPlasmaOff || e.code == fn::kPunchMarkingOn ||
                               e.code == fn::kPunchMarkingOff;
        if (tool_word) return;  // (a tool switched that was already so)
        comment(no_counterpart(e, "G-code"));
    }
    void end(const MachineEvent&) override {
        if (kerf_ != KerfSide::Off) block("G40");
        if (tools_ & kCuttingTools) block("M5 $0");
        if (tools_ & kMarkingTools) block("M5 $1");
        block("M2");
    }

    double feed_ = -1;
    std::uint8_t tools_ = 0;
    KerfSide kerf_ = KerfSide::Off;  // the compensation written last
    double kerf_mm_ = 0;
};

}  // namespace

std::unique_ptr<ProgramWriter> make_gcode_writer(const Profile& source, const ConvertOptions& o,
                                                 std::vector<Diagnostic>& d) {
    return std::make_unique<GcodeWriter>(source, o, d);
}

}  // namespace essi::detail
