#include "app/Document.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "essi/interp.hpp"
#include "essi/kerf.hpp"

namespace essi::viewer {

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

void RankIndex::save(WireWriter& out) const {
    out.put_vector(bits_);
    out.put_vector(before_);
    out.put<std::uint64_t>(size_);
    out.put<std::uint64_t>(count_);
}

bool RankIndex::restore(WireReader& in) {
    std::uint64_t size = 0, count = 0;
    if (!in.get_vector(bits_) || !in.get_vector(before_) || !in.get(size) || !in.get(count)) return false;
    size_ = static_cast<std::size_t>(size);
    count_ = static_cast<std::size_t>(count);
    return bits_.size() * 64 >= size_ && before_.size() >= bits_.size();
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
    r.kerf = (m.flags & Motion::kFlagKerfLeft)    ? KerfSide::Left
             : (m.flags & Motion::kFlagKerfRight) ? KerfSide::Right
                                                  : KerfSide::Off;
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
        if (!concerned_motions.empty() && concerned_motions.back().second >= a)
            concerned_motions.back().second = static_cast<std::uint32_t>(b);
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
        {"read_chunks", chunks.capacity() * sizeof(ReadChunk) +
                            (chunks.empty() ? 0 : chunks.size() * chunks.front().reader.state_bytes()) +
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

}  // namespace essi::viewer
