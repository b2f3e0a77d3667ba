// The ESSI writer (essi/write.hpp): lines of 2 words, arcs of 5 (TC by the sense), functions with their values,
// in the target profile's unit, incremental (81, the default) or absolute (82).
#include <cmath>

#include "essi/functions.hpp"
#include "essi/text.hpp"
#include "writer.hpp"

namespace essi::detail {
namespace {

class EssiWriter final : public ProgramWriter {
public:
    EssiWriter(const Profile& source, const ConvertOptions& o, std::vector<Diagnostic>& d)
        : ProgramWriter(source, o, d) {
        out_ = "%\n";
        if (o.absolute) block(std::to_string(fn::kAbsolute));
    }
    std::string finish() override { return std::move(out_); }

private:
    void block(const std::string& text) { out_ += text + "\n"; }
    static std::string word(long long v) { return (v < 0 ? "-" : "+") + std::to_string(v < 0 ? -v : v); }
    // The words of a point: relative to the block's start (81) or absolute (82).
    std::string point(Units p) const {
        const Units base = options_.absolute ? Units{} : position();
        return word(p.x - base.x) + word(p.y - base.y);
    }
    bool writes_head_addresses() const override { return true; }
    // Head 2's motions with its address (ISO 3.2); head 1's need none, in 3-axis mode too.
    std::string head() const { return head_two() ? "2" : ""; }
    void line(const MotionRecord&, Units end) override { block(head() + point(end)); }
    void arc(const MotionRecord& m, Units end, Units centre) override {
        block(head() + point(end) + point(centre) + (m.ccw ? "+" : "-"));  // TC: '+' counter-clockwise
    }
    void comment(const std::string& text) override {
        block(std::to_string(fn::kIgnoreOn));
        block(text);
        block(std::to_string(fn::kIgnoreOff));
    }
    void function(const MachineEvent& e) override {
        const auto info = function_info(e.code, options_.target.dialect);
        if (!info || !info->assigned) {
            comment(no_counterpart(e, "the " + options_.target.name + " dialect"));
            return;
        }
        if (!e.has_value || info->value == FunctionValue::None) {
            block(std::to_string(e.code));
            return;
        }
        // Values in unit increments go to the target's unit; ESSI values are whole numbers.
        double v = e.value;
        if (info->value_unit == "unit increments") v = v * source_.unit_mm / options_.target.unit_mm;
        if (e.code == fn::kDwell) v = e.value / options_.target.dwell_unit_s;  // (the event's dwell is in seconds)
        const double whole = std::round(v);
        if (std::fabs(whole - v) > 1e-9 || whole < 0) {
            warn(DiagCode::W504_ValueNotWritten, e.line, Msg::WriteNotWhole,
                 {number_text(v), e.code, number_text(std::max(whole, 0.0))});
        }
        block(std::to_string(e.code) + "+" + std::to_string(static_cast<long long>(std::max(whole, 0.0))));
    }
    void end(const MachineEvent&) override {
        if (options_.target.end_codes.empty()) return;  // (the end of the data ends the program)
        const EndCode& c = options_.target.end_codes.front();
        block(c.function >= 0 ? std::to_string(c.function) : std::string(1, c.mark));
    }
};

}  // namespace

std::unique_ptr<ProgramWriter> make_essi_writer(const Profile& source, const ConvertOptions& o,
                                                std::vector<Diagnostic>& d) {
    return std::make_unique<EssiWriter>(source, o, d);
}

}  // namespace essi::detail
