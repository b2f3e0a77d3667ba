#include "app/Document.hpp"

#include "essi/kerf.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "app/Format.hpp"
#include "essi/functions.hpp"
#include "essi/interp.hpp"
#include "essi/pipeline.hpp"
#include "essi/stats.hpp"
#include "essi/text.hpp"

namespace essi::viewer {

namespace {

double now_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

std::string_view Document::line(std::size_t n) const { return line_index.line(bytes, n); }

void RankIndex::reserve(std::size_t n) {
    bits_.reserve(n / 64 + 1);
    before_.reserve(n / 64 + 1);
}

void RankIndex::push_back(bool has_entry) {
    if (size_ % 64 == 0) {
        bits_.push_back(0);
        before_.push_back(static_cast<std::uint32_t>(count_));
    }
    if (has_entry) {
        bits_.back() |= std::uint64_t(1) << (size_ % 64);
        ++count_;
    }
    ++size_;
}

std::size_t RankIndex::rank(std::size_t i) const {
    const std::size_t word = i / 64;
    const std::uint64_t below = (std::uint64_t(1) << (i % 64)) - 1;
    return before_[word] + static_cast<std::size_t>(std::popcount(bits_[word] & below));
}

std::size_t RankIndex::memory_bytes() const {
    return bits_.capacity() * sizeof(std::uint64_t) + before_.capacity() * sizeof(std::uint32_t);
}

bool Document::to_units(Point mm, UnitPoint& out) const {
    long long x = 0, y = 0;
    if (!mm_to_units(profile, mm, x, y)) return false;
    constexpr long long kMax = std::numeric_limits<std::int32_t>::max();
    if (x < -kMax || x > kMax || y < -kMax || y > kMax) return false;  // beyond what a Motion holds
    out = {static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
    return true;
}

const MotionRecord& Document::kept_record(std::size_t i) const {
    auto it = std::lower_bound(kept.begin(), kept.end(), static_cast<std::uint32_t>(i),
                               [](const auto& k, std::uint32_t v) { return k.first < v; });
    return it->second;
}

Point Document::end_of(std::size_t i) const {
    const Motion& m = motions[i];
    return (m.flags & Motion::kFlagKept) ? kept_record(i).end : point_mm(m.end_units);
}

Point Document::start_of(std::size_t i) const {
    if (i < motions.size() && (motions[i].flags & Motion::kFlagJump)) {
        auto it = std::lower_bound(jumps.begin(), jumps.end(), static_cast<std::uint32_t>(i),
                                   [](const auto& j, std::uint32_t k) { return j.first < k; });
        if (it != jumps.end() && it->first == i) return it->second;
    }
    return i > 0 && i <= motions.size() ? end_of(i - 1) : Point{};
}

namespace {
// The value of a change list ((first motion, value) whenever it changes) at motion i; 0 before the first change.
float value_at(const std::vector<std::pair<std::uint32_t, float>>& changes, std::size_t i) {
    auto k = std::upper_bound(changes.begin(), changes.end(), static_cast<std::uint32_t>(i),
                              [](std::uint32_t v, const auto& e) { return v < e.first; });
    return k == changes.begin() ? 0.f : std::prev(k)->second;
}

// The length in units between two points in units, by the interpreter's formula.
double units_between(UnitPoint a, UnitPoint b) {
    return units_length(static_cast<long long>(b.x) - a.x, static_cast<long long>(b.y) - a.y);
}
}  // namespace

Point Document::arc_centre(std::size_t i) const {
    return (motions[i].flags & Motion::kFlagKept) ? kept_record(i).centre : point_mm(arc_centres[arc_rank.rank(i)]);
}

float Document::kerf_of(std::size_t i) const {
    if (!(motions[i].flags & (Motion::kFlagKerfLeft | Motion::kFlagKerfRight))) return 0.f;
    return value_at(kerfs, i);
}

std::vector<MotionRecord> Document::torch_path_of_line(std::uint32_t line) const {
    std::vector<MotionRecord> out;
    const auto [m0, m1] = motions_of_line(line);
    if (m0 == m1) return out;
    const auto compensated = [&](std::size_t i) { return kerf_of(i) > 0; };
    // (a line whose motions and the one before them are without compensation: the torch is on the contour)
    bool any = m0 > 0 && compensated(m0 - 1);
    for (std::size_t i = m0; i < m1 && !any; ++i) any = compensated(i);
    if (!any) return out;
    std::size_t first = m0;
    while (first > 0 && compensated(first - 1)) --first;  // where this compensation started
    struct Collect final : MotionSink {
        std::uint32_t line;
        std::vector<MotionRecord>& out;
        Collect(std::uint32_t l, std::vector<MotionRecord>& o) : line(l), out(o) {}
        void on_motion(const MotionRecord& m) override {
            if (m.line == line) out.push_back(m);
        }
    } collect(line, out);
    KerfPath path(collect, profile.chord_tolerance_mm);
    for (std::size_t i = first; i < std::min(m1 + 1, motions.size()); ++i) path.motion(record(i));
    path.finish();
    return out;
}

float Document::feed_of(std::size_t i) const {
    if (motions[i].flags & Motion::kFlagRapidFeed) return static_cast<float>(profile.rapid_mm_min);
    return value_at(feeds, i);
}

double Document::duration_s(std::size_t i) const {
    double t = motion_time_s(record(i).length_mm, feed_of(i));
    if (std::binary_search(pierces.begin(), pierces.end(), static_cast<std::uint32_t>(i))) t += profile.pierce_time_s;
    return t;
}

const MotionRecord* Document::torch_copies(std::size_t i) const {
    if (!(motions[i].flags & Motion::kFlagKept)) return nullptr;
    const MotionRecord& r = kept_record(i);
    return r.torches > 1 ? &r : nullptr;
}

MotionRecord Document::record(std::size_t i) const {
    const Motion& m = motions[i];
    if (m.flags & Motion::kFlagKept) return kept_record(i);
    MotionRecord r;
    r.line = m.line;
    r.kind = m.kind;
    r.curve = m.curve;
    r.tools = m.tools;
    r.head = (m.flags & Motion::kFlagHead2) ? 2 : 1;
    r.kerf = (m.flags & Motion::kFlagKerfLeft) ? KerfSide::Left
             : (m.flags & Motion::kFlagKerfRight) ? KerfSide::Right : KerfSide::Off;
    r.start = start_of(i);
    r.end = point_mm(m.end_units);
    r.feed_mm_min = feed_of(i);
    r.kerf_mm = kerf_of(i);
    UnitPoint start;
    static_cast<void>(to_units(r.start, start));  // whole units: the loader kept the motion compact only then
    if (m.curve == CurveKind::Arc) {
        // The interpreter's numbers: radii and sweep from the integer vectors centre -> start and centre -> end
        // (in the machine frame they are the tape frame's, swapped or mirrored: the same squares, the same
        // dot product and the cross product's sign turned with the sense).
        const UnitPoint c = arc_centres[arc_rank.rank(i)];  // (arc_centre(i), in units)
        r.centre = point_mm(c);
        r.ccw = (m.flags & Motion::kFlagCcw) != 0;
        const MotionMeasure arc = measure_arc(start.x, start.y, m.end_units.x, m.end_units.y, c.x, c.y, r.ccw);
        r.radius = arc.r0 * profile.unit_mm;
        r.end_radius = arc.r1 * profile.unit_mm;
        r.sweep = arc.sweep;
        r.length_mm = r.radius * std::abs(r.sweep);
    } else {
        r.length_mm = units_between(start, m.end_units) * profile.unit_mm;
    }
    return r;
}

const Tape& Document::reread(std::size_t chunk) const {
    if (reread_chunk_ != chunk) {
        TapeReader reader = chunks[chunk].reader;  // a copy: the kept one stays before the chunk
        reader.read_chunk(reread_, kReadChunkBlocks);
        reread_chunk_ = chunk;
    }
    return reread_;
}

LineBlocks Document::blocks_of_line(std::uint32_t line) const {
    // The last chunk that starts on or before the line (a line holds one block at most: the blocks of a line
    // are in one chunk).
    auto it = std::upper_bound(chunks.begin(), chunks.end(), line,
                               [](std::uint32_t l, const ReadChunk& c) { return l < c.first_line; });
    if (it == chunks.begin()) return {};
    const Tape& t = reread(static_cast<std::size_t>(it - chunks.begin()) - 1);
    const auto blocks_read = t.blocks();
    auto lo = std::lower_bound(blocks_read.begin(), blocks_read.end(), line,
                               [](const Block& b, std::uint32_t l) { return b.line < l; });
    auto hi = lo;
    while (hi != blocks_read.end() && hi->line == line) ++hi;
    return {&t, static_cast<std::size_t>(lo - blocks_read.begin()), static_cast<std::size_t>(hi - blocks_read.begin())};
}

std::size_t Document::block_of(std::size_t i) const {
    const LineBlocks lb = blocks_of_line(motions[i].line);
    for (std::size_t k = lb.first; k < lb.last; ++k)
        if (lb.chunk->block(k).kind == BlockKind::Motion) return lb.tape_index(k);
    return lb.chunk != nullptr ? lb.tape_index(lb.first) : 0;
}

std::size_t Document::first_motion_at_or_after(std::uint32_t line) const {
    auto it = std::lower_bound(motions.begin(), motions.end(), line,
                               [](const Motion& m, std::uint32_t l) { return m.line < l; });
    return static_cast<std::size_t>(it - motions.begin());
}

std::pair<std::size_t, std::size_t> Document::motions_of_line(std::uint32_t line) const {
    std::size_t a = first_motion_at_or_after(line);
    std::size_t b = a;
    while (b < motions.size() && motions[b].line == line) ++b;
    return {a, b};
}

std::pair<std::size_t, std::size_t> Document::motions_of_lines(LineRange lines) const {
    const std::size_t a = first_motion_at_or_after(lines.first);
    const std::size_t b = lines.last == ~std::uint32_t(0) ? motions.size() : first_motion_at_or_after(lines.last + 1);
    return {a, std::max(a, b)};
}

LineEnds Document::line_ends(std::uint32_t line) const {
    LineEnds ends;
    const auto [a, b] = motions_of_line(line);
    if (a < b) ends.first_motion_end = end_of(a);
    if (a > 0) ends.end_before = end_of(a - 1);
    return ends;
}

void Document::place_diagnostics() {
    marks.clear();
    std::vector<LineRange> lines;
    for (std::size_t k = 0; k < diagnostics.size(); ++k) {
        const Diagnostic& d = diagnostics[k];
        if (const auto at = diagnostic_place(d, d.line > 0 ? line_ends(d.line) : LineEnds{}))
            marks.push_back({static_cast<std::uint32_t>(k), *at});
        for (const LineRange& r : concerned_lines(d)) lines.push_back(r);
        for (const LineRange& r : related_lines(d)) lines.push_back(r);
    }
    concerned_motions.clear();
    for (const LineRange& r : merge_ranges(std::move(lines))) {
        const auto [a, b] = motions_of_lines(r);
        if (a == b) continue;
        if (!concerned_motions.empty() && concerned_motions.back().second >= a) concerned_motions.back().second = static_cast<std::uint32_t>(b);
        else concerned_motions.emplace_back(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b));
    }
}

bool Document::has_errors() const { return count(Severity::Error) > 0; }

std::size_t Document::count(Severity s) const {
    return static_cast<std::size_t>(
        std::count_if(diagnostics.begin(), diagnostics.end(), [s](const Diagnostic& d) { return d.severity == s; }));
}

std::vector<std::pair<const char*, std::size_t>> Document::memory_parts() const {
    return {
        {"bytes", bytes.capacity()},
        {"motions", motions.capacity() * sizeof(Motion)},
        {"arc_centres", arc_centres.capacity() * sizeof(UnitPoint) + arc_rank.memory_bytes()},
        {"kept", kept.capacity() * sizeof(kept[0])},
        {"changes", jumps.capacity() * sizeof(jumps[0]) + kerfs.capacity() * sizeof(kerfs[0]) +
                        feeds.capacity() * sizeof(feeds[0])},
        {"pierces", pierces.capacity() * sizeof(std::uint32_t)},
        {"diagnostics", diagnostics.capacity() * sizeof(Diagnostic) + marks.capacity() * sizeof(DiagnosticMark) +
                            concerned_motions.capacity() * sizeof(concerned_motions[0])},
        {"line_index", line_index.memory_bytes()},
        {"read_chunks", chunks.capacity() * sizeof(ReadChunk) + (chunks.empty() ? 0 : chunks.size() * chunks.front().reader.state_bytes()) +
                            reread_.memory_bytes()},
    };
}

std::size_t Document::memory_bytes() const {
    std::size_t n = 0;
    for (const auto& part : memory_parts()) n += part.second;
    return n;
}

std::size_t Document::core_tape_bytes() const {
    return blocks * sizeof(Block) + block_words * sizeof(std::int32_t) +
           (blocks / Tape::kWordIndexStride + 1) * sizeof(std::uint32_t);
}

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
                               {kind, full ? Msg::UiFullCircle : Msg::UiArc, m.ccw ? Msg::UiCcw : Msg::UiCw, mm_text(m.radius),
                                xy(m.centre), xy(m.start), xy(m.end), fixed_text(m.sweep * 180.0 / kPi, kSweepDecimals), mm_text(m.length_mm)});
            if (std::fabs(m.end_radius - m.radius) > kSameRadiusMm)
                s += " " + format_message(Msg::UiArcEndRadius, lang, {mm_text(m.end_radius)});
            break;
        }
        case CurveKind::Parabola: {
            const ParabolaGeom& g = m.parabola;
            s = format_message(Msg::UiMotionParabola, lang,
                               {kind, xy(g.vertex), xy(g.n), mm_text(g.p), xy(m.start), xy(m.end), mm_text(m.length_mm)});
            break;
        }
    }
    s += format_message(Msg::UiMotionTools, lang, {tools_label(m.tools, lang)});
    if (m.head == 2) s += text(Msg::UiMotionHead2, lang);
    if (m.kerf != KerfSide::Off) s += format_message(Msg::UiMotionKerf, lang, {kerf_offset_text(m.kerf, m.kerf_mm, lang)});
    s += (lang == Lang::Zh ? "，" : ", ") + fmt("%.0f mm/min", m.feed_mm_min);
    return s;
}

std::string describe_block(const Tape& tape, std::size_t i, const Profile& profile, Lang lang) {
    const Block& b = tape.block(i);
    switch (b.kind) {
        case BlockKind::Function:
            return describe_function(b.code, false, 0, profile, lang);
        case BlockKind::FunctionValue: {
            const auto w = tape.words(i);
            return describe_function(b.code, true, w.empty() ? 0.0 : b.function_value(w[0]), profile, lang);
        }
        case BlockKind::Motion: {
            // The words by their names (docs/semantics.md §2): TC and TP count by their sign only.
            const auto w = tape.words(i);
            static constexpr const char* kLine[] = {"DX", "DY"};
            static constexpr const char* kArc[] = {"DX", "DY", "XC", "YC"};
            static constexpr const char* kParabola[] = {"DX", "DY", "XP", "YP"};
            const char* const* names = w.size() == 5 ? kArc : w.size() == 6 ? kParabola : kLine;
            const std::size_t named = w.size() == 2 ? 2 : w.size() == 5 || w.size() == 6 ? 4 : 0;
            std::string s = format_message(Msg::UiMotionBlock, lang, {b.word_count()});
            const char* comma = lang == Lang::Zh ? "，" : ", ";
            for (std::size_t k = 0; k < named; ++k) s += (k == 0 ? std::string(" ") : comma) + fmt("%s %+d", names[k], static_cast<int>(w[k]));
            if (named == 0)
                for (auto v : w) s += fmt(" %+d", static_cast<int>(v));
            if (w.size() >= 5) s += comma + std::string(text(b.tc_positive() ? Msg::UiTcCcw : Msg::UiTcCw, lang));
            if (w.size() == 6) s += comma + std::string(text(b.tp_positive() ? Msg::UiTpY : Msg::UiTpX, lang));
            s += (lang == Lang::Zh ? "" : " ") + std::string(text(Msg::UiUnitIncrements, lang));
            if (b.has_address()) s += format_message(Msg::UiBlockHead, lang, {static_cast<int>(b.code)});
            return s;
        }
        case BlockKind::Comment: return std::string(text(Msg::UiBlockComment, lang));
        case BlockKind::Percent: return std::string(text(Msg::UiBlockPercent, lang));
        case BlockKind::EndMark: return std::string(text(Msg::UiBlockEnd, lang));
        case BlockKind::Invalid: return std::string(text(Msg::UiBlockInvalid, lang));
    }
    return "";
}

// ---------------------------------------------------------------------------------------------------------
// The viewer's copy of the stream: TapeChecker's `also` sink (the statistics are the checker's own).
class DocumentLoader::Sink : public MotionSink {
public:
    explicit Sink(Document& doc) : doc_(doc) {}

    void on_motion(const MotionRecord& r) override {
        Document& d = doc_;
        Motion m = start_motion(r.line, r.kind, r.curve, r.tools, r.head, r.kerf, r.start, r.end, r.kerf_mm,
                                r.feed_mm_min);
        // Compact when every point is whole units (always, but for positions beyond 32 bits), not a parabola, and
        // its kerf is what the flags say.
        UnitPoint start, centre;
        // (a cut by several torches keeps its record: the drawing makes its copies from it)
        bool compact = r.curve != CurveKind::Parabola && r.torches == 1 && kerf_in_flags(r.kerf, r.kerf_mm) &&
                       d.to_units(r.end, m.end_units) && d.to_units(r.start, start);
        if (compact && r.curve == CurveKind::Arc) compact = d.to_units(r.centre, centre);
        if (!compact) {
            m.flags |= Motion::kFlagKept;
            d.kept.emplace_back(static_cast<std::uint32_t>(d.motions.size()), r);
        } else if (r.curve == CurveKind::Arc) {
            if (r.ccw) m.flags |= Motion::kFlagCcw;
            d.arc_centres.push_back(centre);
        }
        d.arc_rank.push_back(compact && r.curve == CurveKind::Arc);
        if (r.curve != CurveKind::Line) ++d.curves;
        add(m);
    }

    // Most motions: their units as the interpreter has them (no division and rounding back from mm). With no
    // setup offset, mm = units x unit_mm exactly, so these are the units Document::to_units gives for the mm.
    void on_line(const UnitLine& l) override {
        constexpr long long kMax = std::numeric_limits<std::int32_t>::max();
        const auto fits = [](long long v) { return v >= -kMax && v <= kMax; };
        if (!kerf_in_flags(l.kerf, l.kerf_mm) || !fits(l.start_x) || !fits(l.start_y) ||
            !fits(l.end_x) || !fits(l.end_y)) {
            on_motion(record_of(l));
            return;
        }
        Motion m = start_motion(l.line, l.kind, CurveKind::Line, l.tools, 1, l.kerf, l.start, l.end, l.kerf_mm,
                                l.feed_mm_min);
        m.end_units = {static_cast<std::int32_t>(l.end_x), static_cast<std::int32_t>(l.end_y)};
        doc_.arc_rank.push_back(false);
        add(m);
    }

    void on_event(const MachineEvent& e) override { pierces_.on_tools(e.tools_after); }

private:
    // The compact form has no kerf value where compensation is off: a motion whose kerf is not 0 there (which the
    // interpreter never makes) keeps its record.
    static bool kerf_in_flags(KerfSide side, double kerf_mm) {
        return side != KerfSide::Off || static_cast<float>(kerf_mm) == 0.f;
    }
    // What every motion records: its kind, flags, whether it starts where the one before ended, the kerf and
    // feed when they change.
    Motion start_motion(std::uint32_t line, MotionKind kind, CurveKind curve, std::uint8_t tools, int head,
                        KerfSide kerf_side, Point start, Point end, double kerf_mm, double feed_mm_min) {
        Document& d = doc_;
        const auto index = static_cast<std::uint32_t>(d.motions.size());
        Motion m;
        m.line = line;
        m.kind = kind;
        m.curve = curve;
        m.tools = tools;
        if (head == 2) m.flags |= Motion::kFlagHead2;
        if (kerf_side == KerfSide::Left) m.flags |= Motion::kFlagKerfLeft;
        if (kerf_side == KerfSide::Right) m.flags |= Motion::kFlagKerfRight;
        if (index == 0 || !(last_end_ == start)) {
            m.flags |= Motion::kFlagJump;
            d.jumps.emplace_back(index, start);
        }
        last_end_ = end;
        // Kerf compensation goes on and off with every contour: its value is listed only where it is on.
        const float kerf = static_cast<float>(kerf_mm);
        if (kerf_side != KerfSide::Off && (d.kerfs.empty() ? kerf != 0.f : d.kerfs.back().second != kerf))
            d.kerfs.emplace_back(index, kerf);
        // Rapids alternate with cuts: their feed (the rapid speed) is a flag, and only the others' changes are listed.
        const float feed = static_cast<float>(feed_mm_min);
        if (feed == rapid_feed_) m.flags |= Motion::kFlagRapidFeed;
        else if (d.feeds.empty() ? feed != 0.f : d.feeds.back().second != feed) d.feeds.emplace_back(index, feed);
        return m;
    }
    void add(const Motion& m) {
        Document& d = doc_;
        if (pierces_.at_motion(m.tools)) d.pierces.push_back(static_cast<std::uint32_t>(d.motions.size()));
        d.motions.push_back(m);
    }

    Document& doc_;
    const float rapid_feed_ = static_cast<float>(doc_.profile.rapid_mm_min);
    Point last_end_;  // of the motion before (a motion that starts elsewhere is a jump)
    PierceTracker pierces_;  // the statistics' pierces, each at its motion
};

// The document's motions as the cut plan reads them back (Document::record: the interpreter's own numbers).
class DocumentLoader::Motions final : public MotionStore {
public:
    explicit Motions(const Document& doc) : doc_(doc) {}
    [[nodiscard]] MotionRecord motion(std::size_t index) const override { return doc_.record(index); }

private:
    const Document& doc_;
};

DocumentLoader::DocumentLoader(std::string name, std::string bytes, TapeSetup setup, bool plan_later)
    : doc_(std::make_unique<Document>()), plan_later_(plan_later) {
    doc_->name = std::move(name);
    doc_->bytes = std::move(bytes);
    doc_->profile = setup.profile;
    doc_->setup = std::move(setup);
}

DocumentLoader::~DocumentLoader() = default;

namespace {
// Grows `v` ahead of need to the size projected from the share of the tape read so far (no doubling: a
// 10 M motion stream must not cost twice its size).
template <class T>
void grow(std::vector<T>& v, std::size_t more, std::size_t read, std::size_t total) {
    if (v.size() + more <= v.capacity()) return;
    const double share = read > 0 ? static_cast<double>(read) / static_cast<double>(total) : 0.0;
    std::size_t want = v.size() + more;
    if (share > 0.01) want = std::max(want, static_cast<std::size_t>(static_cast<double>(v.size()) / share * 1.05) + 1024);
    else want = std::max(want, v.capacity() * 2);
    v.reserve(want);
}

// Gives back the room reserved ahead when it is more than an eighth (a copy: the WASM heap's peak grows by it).
template <class T>
void shrink_if_loose(std::vector<T>& v) {
    if (v.capacity() > v.size() + v.size() / 8 + 4096) v.shrink_to_fit();
}
}  // namespace

bool DocumentLoader::step(double budget_ms) {
    Document& d = *doc_;
    const double until = now_ms() + budget_ms;
    if (stage_ == Stage::IndexLines) {  // the sparse line index, 2 MB at a time until the slice's time is up
        constexpr std::size_t kIndexBytesPerTry = std::size_t(2) << 20;
        while (!d.line_index.build(d.bytes, kIndexBytesPerTry))
            if (now_ms() > until) return false;
        const std::size_t motion_lines = d.line_index.signed_lines();  // the motion stream's size, near enough
        stage_ = Stage::ReadAndCheck;
        // Room for the motion stream at once (lines that start with a sign are motions, near enough): no late
        // reserve has to copy hundreds of MB in one slice. grow() covers the few motions this misses.
        d.motions.reserve(motion_lines + motion_lines / kMotionReserveSlack + 16);
        d.arc_rank.reserve(d.motions.capacity());
        sink_ = std::make_unique<Sink>(d);
        reader_ = std::make_unique<TapeReader>(d.bytes, d.profile, d.setup.format);
        chunk_.reserve(Document::kReadChunkBlocks, 2 * Document::kReadChunkBlocks);  // (no doubling steps)
        checker_ = std::make_unique<TapeChecker>(d.bytes, d.profile, sink_.get());
        if (plan_later_) {
            motions_ = std::make_unique<Motions>(d);
            checker_->defer_plan(motions_.get());
        }
        if (now_ms() > until) return false;
    }
    if (stage_ == Stage::ReadAndCheck) {  // read and check, a chunk at a time
        for (;;) {
            TapeReader before = *reader_;  // kept with the chunk: the inspector reads it again from there
            if (!reader_->read_chunk(chunk_, Document::kReadChunkBlocks)) {
                stage_ = Stage::Finish;
                break;
            }
            if (chunk_.size() > 0) {
                read_pos_ = chunk_.block(chunk_.size() - 1).offset;
                d.chunks.push_back({std::move(before), static_cast<std::uint32_t>(chunk_.first_block()),
                                    chunk_.block(0).line});
            }
            d.blocks += chunk_.size();
            d.block_words += chunk_.all_words().size();
            // Room for the chunk's motions (a motion block makes at most one): counting the chunk's blocks instead
            // made the last chunks re-reserve the whole stream that was reserved for every motion line at once (a
            // copy of it, and a hole the size of it in the heap, at 150 000 motions a quarter of the budget).
            std::size_t motion_blocks = 0;
            for (std::size_t b = 0; b < chunk_.size(); ++b) motion_blocks += chunk_.block(b).kind == BlockKind::Motion;
            grow(d.motions, motion_blocks, read_pos_, d.bytes.size());
            grow(d.arc_centres, motion_blocks, read_pos_, d.bytes.size());
            checker_->check_chunk(chunk_);
            if (now_ms() > until) return false;
        }
    }
    if (stage_ == Stage::Finish) {
        CheckResult r = plan_later_ ? checker_->finish_before_plan() : checker_->finish();
        record_setup(r, d.setup);  // (the note N403 among the diagnostics, as `essi check` has it)
        d.stats = r.stats;
        d.diagnostics = std::move(r.diagnostics);
        d.bbox = d.stats.motion_bbox;
        if (!plan_later_) {
            checker_.reset();
            sink_.reset();
        }
        reader_.reset();
        chunk_ = Tape{};
        shrink_if_loose(d.motions);
        shrink_if_loose(d.arc_centres);
        shrink_if_loose(d.jumps);
        shrink_if_loose(d.kerfs);
        shrink_if_loose(d.feeds);
        shrink_if_loose(d.pierces);
        d.chunks.shrink_to_fit();
        if (!d.bbox.empty)
            d.origin = {std::round((d.bbox.min_x + d.bbox.max_x) / 2), std::round((d.bbox.min_y + d.bbox.max_y) / 2)};
        d.place_diagnostics();  // (after the check: a few marks, not a pass over the motions)
        stage_ = Stage::Done;
    }
    return true;
}

bool DocumentLoader::step_plan(Document& doc, double budget_ms) {
    if (!checker_) return true;
    const double until = now_ms() + budget_ms;
    while (checker_->analyse_plan_plate())
        if (now_ms() > until) return false;
    std::vector<Diagnostic> found = checker_->plan_findings();
    doc.diagnostics.insert(doc.diagnostics.end(), std::make_move_iterator(found.begin()), std::make_move_iterator(found.end()));
    sort_diagnostics(doc.diagnostics);  // (as TapeChecker::finish orders them: the same list as essi check's)
    doc.place_diagnostics();
    checker_.reset();
    sink_.reset();
    motions_.reset();
    return true;
}

float DocumentLoader::plan_progress() const {
    if (!checker_ || checker_->plan_plates() == 0) return 1.f;
    return 1.f - static_cast<float>(checker_->plan_plates_left()) / static_cast<float>(checker_->plan_plates());
}

float DocumentLoader::progress() const {
    const double n = static_cast<double>(std::max<std::size_t>(doc_ ? doc_->bytes.size() : 1, 1));
    switch (stage_) {
        case Stage::IndexLines: return static_cast<float>(0.1 * static_cast<double>(doc_ ? doc_->line_index.position() : 0) / n);
        case Stage::ReadAndCheck: return static_cast<float>(0.1 + 0.6 * static_cast<double>(read_pos_) / n);
        default: return 0.7f;
    }
}

Msg DocumentLoader::stage() const {
    switch (stage_) {
        case Stage::IndexLines: return Msg::UiStageIndexing;
        case Stage::ReadAndCheck: return Msg::UiStageReading;
        default: return Msg::UiStageBuilding;
    }
}

std::vector<Document::InspectorLine> Document::inspector_lines(std::uint32_t line, Lang lang) const {
    std::vector<InspectorLine> out;
    if (line == 0) return out;
    const LineBlocks blocks = blocks_of_line(line);
    for (std::size_t b = blocks.first; b < blocks.last; ++b)
        out.push_back({InspectorLine::Of::Block, MotionKind::Travel, describe_block(*blocks.chunk, b, profile, lang)});
    const auto [m0, m1] = motions_of_line(line);
    for (std::size_t m = m0; m < m1 && m < m0 + kInspectorMotions; ++m) {
        const MotionRecord r = record(m);
        out.push_back({InspectorLine::Of::Motion, r.kind, describe_motion(r, lang)});
    }
    const std::vector<MotionRecord> torch = torch_path_of_line(line);
    for (std::size_t k = 0; k < torch.size() && k < kInspectorMotions; ++k)
        out.push_back({InspectorLine::Of::Torch, torch[k].kind, format_message(Msg::UiTorchKerf, lang, {describe_motion(torch[k], lang)})});
    return out;
}

}  // namespace essi::viewer
