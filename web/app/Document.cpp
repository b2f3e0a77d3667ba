#include "app/Document.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>

#include "essi/functions.hpp"
#include "essi/interp.hpp"

namespace essi::viewer {

namespace {

constexpr std::size_t kChunkBlocks = 16384;  // blocks per TapeReader chunk (a few ms in the browser)

double now_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string fmt(const char* format, auto... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

}  // namespace

std::string_view Document::line(std::size_t n) const {
    if (n == 0 || n > lines) return {};
    const std::string& s = bytes;
    std::size_t i = line_index[(n - 1) / kLineIndexStride];
    for (std::size_t skip = (n - 1) % kLineIndexStride; skip > 0; --skip) {
        while (i < s.size() && s[i] != '\n' && s[i] != '\r') ++i;
        if (i >= s.size()) return {};
        const char c = s[i++];
        if (i < s.size() && (s[i] == '\n' || s[i] == '\r') && s[i] != c) ++i;
    }
    std::size_t end = i;
    while (end < s.size() && s[end] != '\n' && s[end] != '\r') ++end;
    return std::string_view(s).substr(i, end - i);
}

Point Document::start_of(std::size_t i) const {
    if (i < motions.size() && (motions[i].flags & Motion::kFlagJump)) {
        auto it = std::lower_bound(jumps.begin(), jumps.end(), static_cast<std::uint32_t>(i),
                                   [](const auto& j, std::uint32_t k) { return j.first < k; });
        if (it != jumps.end() && it->first == i) return it->second;
    }
    return i > 0 && i <= motions.size() ? motions[i - 1].end : Point{};
}

MotionRecord Document::record(std::size_t i) const {
    const Motion& m = motions[i];
    if (m.curve == CurveKind::Parabola && m.curve_index != Motion::kNoCurve) return parabolas[m.curve_index];
    MotionRecord r;
    r.line = m.line;
    r.kind = m.kind;
    r.curve = m.curve;
    r.tools = m.tools;
    r.head = (m.flags & Motion::kFlagHead2) ? 2 : 1;
    r.kerf = (m.flags & Motion::kFlagKerfLeft) ? KerfSide::Left
             : (m.flags & Motion::kFlagKerfRight) ? KerfSide::Right : KerfSide::Off;
    r.start = start_of(i);
    r.end = m.end;
    r.feed_mm_min = m.feed_mm_min;
    auto k = std::upper_bound(kerfs.begin(), kerfs.end(), static_cast<std::uint32_t>(i),
                              [](std::uint32_t v, const auto& e) { return v < e.first; });
    r.kerf_mm = k == kerfs.begin() ? 0.0 : static_cast<double>(std::prev(k)->second);
    if (m.curve == CurveKind::Arc && m.curve_index != Motion::kNoCurve) {
        const ArcData& a = arcs[m.curve_index];
        r.centre = a.centre;
        r.radius = a.radius;
        r.end_radius = a.end_radius;
        r.sweep = a.sweep;
        r.ccw = a.sweep > 0;
        r.length_mm = a.length_mm;
    } else {
        r.length_mm = std::hypot(r.end.x - r.start.x, r.end.y - r.start.y);
    }
    return r;
}

std::size_t Document::block_of(std::size_t i) const {
    const auto [b0, b1] = blocks_of_line(motions[i].line);
    for (std::size_t b = b0; b < b1; ++b)
        if (tape.block(b).kind == BlockKind::Motion) return b;
    return b0;
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

std::pair<std::size_t, std::size_t> Document::blocks_of_line(std::uint32_t line) const {
    const auto& blocks = tape.blocks();
    auto lo = std::lower_bound(blocks.begin(), blocks.end(), line,
                               [](const Block& b, std::uint32_t l) { return b.line < l; });
    auto hi = lo;
    while (hi != blocks.end() && hi->line == line) ++hi;
    return {static_cast<std::size_t>(lo - blocks.begin()), static_cast<std::size_t>(hi - blocks.begin())};
}

bool Document::has_errors() const { return count(Severity::Error) > 0; }

std::size_t Document::count(Severity s) const {
    return static_cast<std::size_t>(
        std::count_if(diagnostics.begin(), diagnostics.end(), [s](const Diagnostic& d) { return d.severity == s; }));
}

std::size_t Document::memory_bytes() const {
    return bytes.capacity() + tape.memory_bytes() + motions.capacity() * sizeof(Motion) +
           arcs.capacity() * sizeof(ArcData) + parabolas.capacity() * sizeof(MotionRecord) +
           jumps.capacity() * sizeof(jumps[0]) + kerfs.capacity() * sizeof(kerfs[0]) +
           pierces.capacity() * sizeof(Point) + line_index.capacity() * sizeof(std::uint32_t);
}

std::string describe_motion(const MotionRecord& m) {
    std::string s = motion_kind_name(m.kind);
    switch (m.curve) {
        case CurveKind::Line:
            s += fmt(" line from (%.3f, %.3f) to (%.3f, %.3f), %.3f mm", m.start.x, m.start.y, m.end.x, m.end.y,
                     m.length_mm);
            break;
        case CurveKind::Arc: {
            const bool full = std::fabs(std::fabs(m.sweep) - 2 * kPi) < 1e-9;
            s += fmt(" %s %s r=%.3f mm, centre (%.3f, %.3f), from (%.3f, %.3f) to (%.3f, %.3f), sweep %.3f°, %.3f mm",
                     full ? "full circle" : "arc", m.ccw ? "CCW" : "CW", m.radius, m.centre.x, m.centre.y, m.start.x,
                     m.start.y, m.end.x, m.end.y, m.sweep * 180.0 / kPi, m.length_mm);
            if (std::fabs(m.end_radius - m.radius) > 1e-9)
                s += fmt(" (end radius %.3f mm)", m.end_radius);
            break;
        }
        case CurveKind::Parabola: {
            const ParabolaGeom& g = m.parabola;
            s += fmt(" parabola, vertex (%.3f, %.3f), axis (%.3f, %.3f), p=%.3f mm, from (%.3f, %.3f) to (%.3f, %.3f), "
                     "%.3f mm",
                     g.vertex.x, g.vertex.y, g.n.x, g.n.y, g.p, m.start.x, m.start.y, m.end.x, m.end.y, m.length_mm);
            break;
        }
    }
    s += "; tools " + tools_text(m.tools);
    if (m.head == 2) s += ", head 2";
    if (m.kerf != KerfSide::Off)
        s += fmt(", kerf %s %.3f mm", m.kerf == KerfSide::Left ? "left" : "right", m.kerf_mm);
    s += fmt(", %.0f mm/min", m.feed_mm_min);
    return s;
}

std::string describe_block(const Document& doc, std::size_t i) {
    const Block& b = doc.tape.block(i);
    switch (b.kind) {
        case BlockKind::Function:
            return describe_function(b.code, false, 0, doc.profile);
        case BlockKind::FunctionValue: {
            const auto w = doc.tape.words(i);
            return describe_function(b.code, true, w.empty() ? 0 : static_cast<long>(w[0]), doc.profile);
        }
        case BlockKind::Motion: {
            const auto w = doc.tape.words(i);
            std::string s = fmt("motion block, %d words:", b.word_count());
            for (auto v : w) s += fmt(" %+d", static_cast<int>(v));
            if (b.has_address()) s += fmt(" (head %d)", static_cast<int>(b.code));
            return s;
        }
        case BlockKind::Comment: return "comment (inside 3 ... 4, not executed)";
        case BlockKind::Percent: return "%: initialisation / rewind-stop mark";
        case BlockKind::EndMark: return "end of program";
        case BlockKind::Invalid: return "invalid block (skipped; see its diagnostic)";
    }
    return "";
}

// ---------------------------------------------------------------------------------------------------------
// The viewer's copy of the stream: TapeChecker's `also` sink (the statistics are the checker's own).
class DocumentLoader::Sink : public MotionSink {
public:
    explicit Sink(Document& doc) : doc_(doc) {}

    void on_motion(const MotionRecord& r) override {
        const auto index = static_cast<std::uint32_t>(doc_.motions.size());
        Motion m;
        m.end = r.end;
        m.line = r.line;
        m.kind = r.kind;
        m.curve = r.curve;
        m.tools = r.tools;
        m.feed_mm_min = static_cast<float>(r.feed_mm_min);
        if (r.head == 2) m.flags |= Motion::kFlagHead2;
        if (r.kerf == KerfSide::Left) m.flags |= Motion::kFlagKerfLeft;
        if (r.kerf == KerfSide::Right) m.flags |= Motion::kFlagKerfRight;
        if (index == 0 || !(doc_.motions.back().end == r.start)) {
            m.flags |= Motion::kFlagJump;
            doc_.jumps.emplace_back(index, r.start);
        }
        const float kerf = static_cast<float>(r.kerf_mm);
        if (doc_.kerfs.empty() ? kerf != 0.f : doc_.kerfs.back().second != kerf) doc_.kerfs.emplace_back(index, kerf);
        if (r.curve == CurveKind::Arc) {
            m.curve_index = static_cast<std::uint32_t>(doc_.arcs.size());
            doc_.arcs.push_back({r.centre, r.radius, r.end_radius, r.sweep, r.length_mm});
        } else if (r.curve == CurveKind::Parabola) {
            m.curve_index = static_cast<std::uint32_t>(doc_.parabolas.size());
            doc_.parabolas.push_back(r);
        }
        if (pierce_pending_ && (r.tools & kCuttingTools)) doc_.pierces.push_back(r.start);
        pierce_pending_ = false;
        doc_.motions.push_back(m);
    }

    void on_event(const MachineEvent& e) override {
        const bool was_on = (tools_ & kCuttingTools) != 0;
        const bool now_on = (e.tools_after & kCuttingTools) != 0;
        if (!was_on && now_on) pierce_pending_ = true;
        if (!now_on) pierce_pending_ = false;
        tools_ = e.tools_after;
    }

private:
    Document& doc_;
    std::uint8_t tools_ = 0;
    bool pierce_pending_ = false;
};

DocumentLoader::DocumentLoader(std::string name, std::string bytes, Profile profile)
    : doc_(std::make_unique<Document>()) {
    doc_->name = std::move(name);
    doc_->bytes = std::move(bytes);
    doc_->profile = std::move(profile);
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
}  // namespace

bool DocumentLoader::step(double budget_ms) {
    Document& d = *doc_;
    const double until = now_ms() + budget_ms;
    if (stage_ == 0) {  // the sparse line index
        const std::string& s = d.bytes;
        if (index_pos_ == 0) {
            d.line_index.clear();
            d.line_index.push_back(0);
            d.lines = s.empty() ? 0 : 1;
            motion_lines_ = !s.empty() && (s[0] == '+' || s[0] == '-');
        }
        const char* p = s.data();
        const std::size_t n = s.size();
        std::size_t i = index_pos_;
        while (i < n) {
            const std::size_t stop = std::min(n, i + (std::size_t(2) << 20));
            while (i < stop) {
                const char c = p[i++];
                if (c != '\n' && c != '\r') continue;
                if (i < n && (p[i] == '\n' || p[i] == '\r') && p[i] != c) ++i;
                if (i < n) {
                    if (d.lines % Document::kLineIndexStride == 0) d.line_index.push_back(static_cast<std::uint32_t>(i));
                    ++d.lines;
                    motion_lines_ += p[i] == '+' || p[i] == '-';
                }
            }
            if (now_ms() > until) break;
        }
        index_pos_ = i;
        if (index_pos_ < n) return false;
        stage_ = 1;
        // Room for the motion stream at once (lines that start with a sign are motions, near enough): no late
        // reserve has to copy hundreds of MB in one slice. grow() covers the few motions this misses.
        d.motions.reserve(motion_lines_ + motion_lines_ / kMotionReserveSlack + 16);
        sink_ = std::make_unique<Sink>(d);
        reader_ = std::make_unique<TapeReader>(d.bytes, d.profile);
        checker_ = std::make_unique<TapeChecker>(d.bytes, d.profile, sink_.get());
        if (now_ms() > until) return false;
    }
    if (stage_ == 1) {  // read and check, a chunk at a time
        for (;;) {
            if (!reader_->read_chunk(chunk_, kChunkBlocks)) {
                stage_ = 2;
                break;
            }
            if (chunk_.size() > 0) read_pos_ = chunk_.block(chunk_.size() - 1).offset;
            grow(d.motions, chunk_.size(), read_pos_, d.bytes.size());
            checker_->check_chunk(chunk_);
            if (d.tape.size() == 0) d.tape.reserve(d.lines + 16, 2 * d.lines + 16);
            d.tape.append(chunk_);
            if (now_ms() > until) return false;
        }
    }
    if (stage_ == 2) {
        CheckResult r = checker_->finish();
        d.stats = r.stats;
        d.diagnostics = std::move(r.diagnostics);
        d.bbox = d.stats.motion_bbox;
        checker_.reset();
        reader_.reset();
        sink_.reset();
        chunk_ = Tape{};
        if (d.motions.capacity() > d.motions.size() + d.motions.size() / 8 + 4096) d.motions.shrink_to_fit();
        d.arcs.shrink_to_fit();
        if (!d.bbox.empty)
            d.origin = {std::round((d.bbox.min_x + d.bbox.max_x) / 2), std::round((d.bbox.min_y + d.bbox.max_y) / 2)};
        stage_ = 3;
    }
    return true;
}

float DocumentLoader::progress() const {
    const double n = static_cast<double>(std::max<std::size_t>(doc_ ? doc_->bytes.size() : 1, 1));
    switch (stage_) {
        case 0: return static_cast<float>(0.1 * static_cast<double>(index_pos_) / n);
        case 1: return static_cast<float>(0.1 + 0.6 * static_cast<double>(read_pos_) / n);
        default: return 0.7f;
    }
}

const char* DocumentLoader::stage() const {
    switch (stage_) {
        case 0: return "indexing lines";
        case 1: return "reading and checking";
        default: return "building the drawing";
    }
}

}  // namespace essi::viewer
