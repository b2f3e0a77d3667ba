// The EIA writer (essi/write.hpp): RS-274 blocks by the target profile's EIA table (docs/semantics.md §10). G01,
// G02 and G03 are written when the motion changes (modal); rapid as G00 where the dialect has a rapid motion mode,
// else by its table's 5/6 words (Woyda G05/G06); F for the feed, the dwell word with its time; every other
// function by the table, or a comment (W501).
#include <cmath>

#include "essi/text.hpp"
#include "writer.hpp"

namespace essi::detail {
namespace {

constexpr int kGLine = 1, kGArcCw = 2, kGArcCcw = 3;

class EiaWriter final : public ProgramWriter {
public:
    EiaWriter(const Profile& source, const ConvertOptions& o, std::vector<Diagnostic>& d)
        : ProgramWriter(source, o, d), e_(o.target.eia) {
        out_ = "%\n";
        if (!e_.mm_words.empty()) block(word_text(e_.mm_words.front()));
        const std::string mode = word_of(o.absolute ? fn::kAbsolute : fn::kIncremental);
        if (!mode.empty()) block(mode);
        else if (o.absolute) warn(DiagCode::W501_NoCounterpart, 0, Msg::WriteNoAbsoluteMode, {o.target.name});
        absolute_ = o.absolute && !mode.empty();
    }
    std::string finish() override { return std::move(out_); }

private:
    void block(const std::string& text) { out_ += text + "\n"; }
    void comment(const std::string& text) override { block("(" + text + ")"); }
    static std::string word_text(const EiaWord& w) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%c%02d", w.letter, w.number);
        return buf;
    }
    // The table's word for ESSI function `code` (its first row), or "".
    std::string word_of(int code) const {
        for (const EiaCode& c : e_.codes)
            if (c.function == code) return word_text(c.word);
        return {};
    }
    std::string coordinate(char letter, long long units) const {
        return std::string(1, letter) + mm_text(units, options_.target);
    }
    std::string point(Units p) const {
        const Units base = absolute_ ? Units{} : position();
        return coordinate('X', p.x - base.x) + " " + coordinate('Y', p.y - base.y);
    }
    // The motion word when it changes: G00 for rapid (dialects with a rapid mode), G01, G02, G03.
    std::string motion_word(const MotionRecord& m, int g) {
        const bool rapid = e_.rapid_motion_g >= 0 && m.kind == MotionKind::Rapid;
        const int want = rapid ? e_.rapid_motion_g : g;
        if (want == mode_) return {};
        mode_ = want;
        return word_text({'G', want}) + " ";
    }
    void line(const MotionRecord& m, Units end) override { block(motion_word(m, kGLine) + point(end)); }
    void arc(const MotionRecord& m, Units end, Units centre) override {
        const Units start = position();  // I J: always relative to the start
        block(motion_word(m, m.ccw ? kGArcCcw : kGArcCw) + point(end) + " " + coordinate('I', centre.x - start.x) +
              " " + coordinate('J', centre.y - start.y));
    }
    void function(const MachineEvent& e) override {
        const bool rapid_word = e.code == fn::kRapidOn || e.code == fn::kRapidOff;
        if (rapid_word && e_.rapid_motion_g >= 0) return;  // (G00 says it on the motions)
        if (e.code == fn::kFeed) {
            block("F" + number_text(e.value));
            return;
        }
        const std::string w = word_of(e.code);
        if (w.empty()) {
            comment(no_counterpart(e, "the " + options_.target.name + " EIA table"));
            return;
        }
        if (e.code == fn::kDwell) {
            block(w + " " + std::string(1, e_.dwell_letter) + number_text(e.value / e_.dwell_unit_s));
            return;
        }
        if (e.has_value)
            warn(DiagCode::W504_ValueNotWritten, e.line, Msg::WriteValueNoPlace, {number_text(e.value), e.code, w});
        block(w);
    }
    void end(const MachineEvent& e) override {
        for (const EndCode& c : options_.target.end_codes) {
            if (c.function < 0) continue;
            const std::string w = word_of(c.function);
            if (!w.empty()) {
                block(w);
                return;
            }
        }
        if (!options_.target.end_codes.empty())
            warn(DiagCode::W501_NoCounterpart, e.line, Msg::WriteNoEndWord, {options_.target.name});
    }

    const EiaDialect& e_;
    bool absolute_ = false;
    int mode_ = -1;  // the motion G in force (modal)
};

}  // namespace

std::unique_ptr<ProgramWriter> make_eia_writer(const Profile& source, const ConvertOptions& o,
                                               std::vector<Diagnostic>& d) {
    return std::make_unique<EiaWriter>(source, o, d);
}

}  // namespace essi::detail
