#include "app/Describe.hpp"

#include <cmath>

#include "app/Format.hpp"
#include "essi/functions.hpp"
#include "essi/text.hpp"

namespace essi::viewer {

namespace {
// describe_motion: a sweep this close (radians) to a whole turn is called a full circle, and an end radius this
// close (mm) to the start radius is not mentioned (rounding in the interpreter's numbers, not a spiral).
constexpr double kFullTurnTolerance = 1e-9;
constexpr double kSameRadiusMm = 1e-9;
}  // namespace

const char* motion_kind_text(MotionKind kind, Lang lang) {
    switch (kind) {
        case MotionKind::Rapid: return c_text(Msg::UiKindRapid, lang);
        case MotionKind::Travel: return c_text(Msg::UiKindTravel, lang);
        case MotionKind::Cut: return c_text(Msg::UiKindCut, lang);
        case MotionKind::Mark: return c_text(Msg::UiKindMark, lang);
    }
    return motion_kind_name(kind);
}

const char* curve_kind_text(CurveKind curve, Lang lang) {
    switch (curve) {
        case CurveKind::Line: return c_text(Msg::UiCurveLine, lang);
        case CurveKind::Arc: return c_text(Msg::UiCurveArc, lang);
        case CurveKind::Parabola: return c_text(Msg::UiCurveParabola, lang);
    }
    return curve_kind_name(curve);
}

std::string tools_label(std::uint8_t tools, Lang lang) {
    if (tools == 0) return "-";
    return format_template("{0}", lang, MessageArgs{tools_arg(tools)});  // (the core's words, joined with '+')
}

namespace {
std::string xy(Point p) { return mm_text(p.x) + ", " + mm_text(p.y); }
constexpr int kSweepDecimals = 3;  // degrees
}  // namespace

std::string describe_motion(const MotionRecord& m, Lang lang) {
    const char* kind = motion_kind_text(m.kind, lang);
    std::string s;
    switch (m.curve) {
        case CurveKind::Line:
            s = format_message(Msg::UiMotionLine, lang, {kind, xy(m.start), xy(m.end), mm_text(m.length_mm)});
            break;
        case CurveKind::Arc: {
            const bool full = std::fabs(std::fabs(m.sweep) - 2 * kPi) < kFullTurnTolerance;
            s = format_message(Msg::UiMotionArc, lang,
                               {kind, full ? Msg::UiFullCircle : Msg::UiArc, m.ccw ? Msg::UiCcw : Msg::UiCw,
                                mm_text(m.radius), xy(m.centre), xy(m.start), xy(m.end),
                                fixed_text(m.sweep * 180.0 / kPi, kSweepDecimals), mm_text(m.length_mm)});
            if (std::fabs(m.end_radius - m.radius) > kSameRadiusMm)
                s += " " + format_message(Msg::UiArcEndRadius, lang, {mm_text(m.end_radius)});
            break;
        }
        case CurveKind::Parabola: {
            const ParabolaGeom& g = m.parabola;
            s = format_message(
                Msg::UiMotionParabola, lang,
                {kind, xy(g.vertex), xy(g.n), mm_text(g.p), xy(m.start), xy(m.end), mm_text(m.length_mm)});
            break;
        }
    }
    s += format_message(Msg::UiMotionTools, lang, {tools_label(m.tools, lang)});
    if (m.head == 2) s += text(Msg::UiMotionHead2, lang);
    if (m.kerf != KerfSide::Off)
        s += format_message(Msg::UiMotionKerf, lang, {kerf_offset_text(m.kerf, m.kerf_mm, lang)});
    s += (lang == Lang::Zh ? "，" : ", ") + fmt("%.0f mm/min", m.feed_mm_min);
    return s;
}

namespace {
// A motion block's words by their names (docs/semantics.md §2): TC and TP count by their sign only.
std::string motion_block_text(const Tape& tape, std::size_t i, Lang lang) {
    const Block& b = tape.block(i);
    const auto w = tape.words(i);
    static constexpr const char* kLine[] = {"DX", "DY"};
    static constexpr const char* kArc[] = {"DX", "DY", "XC", "YC"};
    static constexpr const char* kParabola[] = {"DX", "DY", "XP", "YP"};
    const char* const* names = w.size() == 5 ? kArc : w.size() == 6 ? kParabola : kLine;
    const std::size_t named = w.size() == 2 ? 2 : w.size() == 5 || w.size() == 6 ? 4 : 0;
    std::string s = format_message(Msg::UiMotionBlock, lang, {b.word_count()});
    const char* comma = lang == Lang::Zh ? "，" : ", ";
    for (std::size_t k = 0; k < named; ++k)
        s += (k == 0 ? std::string(" ") : comma) + fmt("%s %+d", names[k], static_cast<int>(w[k]));
    if (named == 0)
        for (auto v : w) s += fmt(" %+d", static_cast<int>(v));
    if (w.size() >= 5) s += comma + std::string(text(b.tc_positive() ? Msg::UiTcCcw : Msg::UiTcCw, lang));
    if (w.size() == 6) s += comma + std::string(text(b.tp_positive() ? Msg::UiTpY : Msg::UiTpX, lang));
    s += (lang == Lang::Zh ? "" : " ") + std::string(text(Msg::UiUnitIncrements, lang));
    if (b.has_address()) s += format_message(Msg::UiBlockHead, lang, {static_cast<int>(b.code)});
    return s;
}
}  // namespace

std::string describe_block(const Tape& tape, std::size_t i, const Profile& profile, Lang lang) {
    const Block& b = tape.block(i);
    switch (b.kind) {
        case BlockKind::Function: return describe_function(b.code, false, 0, profile, lang);
        case BlockKind::FunctionValue: {
            const auto w = tape.words(i);
            return describe_function(b.code, true, w.empty() ? 0.0 : b.function_value(w[0]), profile, lang);
        }
        case BlockKind::Motion: return motion_block_text(tape, i, lang);
        case BlockKind::Comment: return std::string(text(Msg::UiBlockComment, lang));
        case BlockKind::Percent: return std::string(text(Msg::UiBlockPercent, lang));
        case BlockKind::EndMark: return std::string(text(Msg::UiBlockEnd, lang));
        case BlockKind::Invalid: return std::string(text(Msg::UiBlockInvalid, lang));
    }
    return "";
}

std::vector<InspectorLine> inspector_lines(const Document& doc, std::uint32_t line, Lang lang) {
    std::vector<InspectorLine> out;
    if (line == 0) return out;
    const LineBlocks blocks = doc.blocks_of_line(line);
    for (std::size_t b = blocks.first; b < blocks.last; ++b)
        out.push_back(
            {InspectorLine::Of::Block, MotionKind::Travel, describe_block(*blocks.chunk, b, doc.profile, lang)});
    const auto [m0, m1] = doc.motions_of_line(line);
    for (std::size_t m = m0; m < m1 && m < m0 + kInspectorMotions; ++m) {
        const MotionRecord r = doc.record(m);
        out.push_back({InspectorLine::Of::Motion, r.kind, describe_motion(r, lang)});
    }
    const std::vector<MotionRecord> torch = doc.torch_path_of_line(line);
    for (std::size_t k = 0; k < torch.size() && k < kInspectorMotions; ++k)
        out.push_back({InspectorLine::Of::Torch, torch[k].kind,
                       format_message(Msg::UiTorchKerf, lang, {describe_motion(torch[k], lang)})});
    return out;
}

}  // namespace essi::viewer
