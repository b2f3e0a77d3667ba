#include "app/Document.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "essi/functions.hpp"
#include "essi/interp.hpp"

namespace essi::viewer {

namespace {

// Sends the core's stream to the statistics (exactly what `essi check` computes) and to the viewer's copy.
class ViewerSink : public MotionSink {
public:
    ViewerSink(Document& doc, StatsSink& stats) : doc_(doc), stats_(stats) {}

    void on_motion(const MotionRecord& r) override {
        stats_.on_motion(r);
        Motion m;
        m.start = r.start;
        m.end = r.end;
        m.line = r.line;
        m.block = r.block;
        m.kind = r.kind;
        m.curve = r.curve;
        m.tools = r.tools;
        m.feed_mm_min = static_cast<float>(r.feed_mm_min);
        m.kerf_mm = static_cast<float>(r.kerf_mm);
        if (r.head == 2) m.flags |= Motion::kFlagHead2;
        if (r.kerf == KerfSide::Left) m.flags |= Motion::kFlagKerfLeft;
        if (r.kerf == KerfSide::Right) m.flags |= Motion::kFlagKerfRight;
        if (r.curve != CurveKind::Line) {
            m.curve_index = static_cast<std::uint32_t>(doc_.curves.size());
            doc_.curves.push_back(r);
        }
        if (pierce_pending_ && (r.tools & kCuttingTools)) doc_.pierces.push_back(r.start);
        pierce_pending_ = false;
        doc_.bbox.add(bounding_box(r));
        doc_.motions.push_back(m);
    }

    void on_event(const MachineEvent& e) override {
        stats_.on_event(e);
        const bool was_on = (tools_ & kCuttingTools) != 0;
        const bool now_on = (e.tools_after & kCuttingTools) != 0;
        if (!was_on && now_on) pierce_pending_ = true;
        if (!now_on) pierce_pending_ = false;
        tools_ = e.tools_after;
    }

private:
    Document& doc_;
    StatsSink& stats_;
    std::uint8_t tools_ = 0;
    bool pierce_pending_ = false;
};

std::string fmt(const char* format, auto... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

}  // namespace

std::string_view Document::line(std::size_t n) const {
    if (n == 0 || n > line_starts.size()) return {};
    const std::size_t begin = line_starts[n - 1];
    std::size_t end = n < line_starts.size() ? line_starts[n] : bytes.size();
    while (end > begin && (bytes[end - 1] == '\n' || bytes[end - 1] == '\r')) --end;
    return std::string_view(bytes).substr(begin, end - begin);
}

MotionRecord Document::record(std::size_t i) const {
    const Motion& m = motions[i];
    if (m.curve_index != Motion::kNoCurve) return curves[m.curve_index];
    MotionRecord r;
    r.line = m.line;
    r.block = m.block;
    r.kind = m.kind;
    r.curve = m.curve;
    r.tools = m.tools;
    r.head = (m.flags & Motion::kFlagHead2) ? 2 : 1;
    r.kerf = (m.flags & Motion::kFlagKerfLeft) ? KerfSide::Left
             : (m.flags & Motion::kFlagKerfRight) ? KerfSide::Right : KerfSide::Off;
    r.start = m.start;
    r.end = m.end;
    r.length_mm = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y);
    r.feed_mm_min = m.feed_mm_min;
    r.kerf_mm = m.kerf_mm;
    return r;
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
           curves.capacity() * sizeof(MotionRecord) + pierces.capacity() * sizeof(Point) +
           line_starts.capacity() * sizeof(std::uint32_t);
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
DocumentLoader::DocumentLoader(std::string name, std::string bytes, Profile profile)
    : doc_(std::make_unique<Document>()) {
    doc_->name = std::move(name);
    doc_->bytes = std::move(bytes);
    doc_->profile = std::move(profile);
}

bool DocumentLoader::step() {
    Document& d = *doc_;
    switch (stage_) {
        case 0: {  // line index, 8 MB a step
            const std::string& s = d.bytes;
            if (index_pos_ == 0) {
                d.line_starts.clear();
                d.line_starts.push_back(0);
            }
            const std::size_t stop = std::min(s.size(), index_pos_ + (std::size_t(8) << 20));
            std::size_t i = index_pos_;
            while (i < stop) {
                const char c = s[i];
                if (c == '\n' || c == '\r') {
                    ++i;
                    if (i < s.size() && (s[i] == '\n' || s[i] == '\r') && s[i] != c) ++i;
                    if (i < s.size()) d.line_starts.push_back(static_cast<std::uint32_t>(i));
                } else {
                    ++i;
                }
            }
            index_pos_ = i;
            if (index_pos_ >= s.size()) stage_ = 1;
            return false;
        }
        case 1:
            d.tape = read_tape(d.bytes, d.profile);
            d.diagnostics = d.tape.diagnostics();
            stage_ = 2;
            return false;
        case 2: {
            // The same pipeline as essi::check_tape, with the viewer's copy of the stream taken on the way.
            StatsSink stats(d.profile);
            ViewerSink sink(d, stats);
            interpret(d.tape, d.bytes, d.profile, sink, d.diagnostics);
            d.stats = stats.stats();
            d.stats.blocks = count_program_blocks(d.tape);
            sort_diagnostics(d.diagnostics);
            d.motions.shrink_to_fit();
            d.curves.shrink_to_fit();
            if (!d.bbox.empty) d.origin = {std::round((d.bbox.min_x + d.bbox.max_x) / 2), std::round((d.bbox.min_y + d.bbox.max_y) / 2)};
            stage_ = 3;
            return true;
        }
        default: return true;
    }
}

float DocumentLoader::progress() const {
    switch (stage_) {
        case 0: return doc_->bytes.empty() ? 0.1f : 0.1f * static_cast<float>(index_pos_) / static_cast<float>(doc_->bytes.size());
        case 1: return 0.1f;
        case 2: return 0.4f;
        default: return 0.7f;
    }
}

const char* DocumentLoader::stage() const {
    switch (stage_) {
        case 0: return "indexing lines";
        case 1: return "reading blocks";
        case 2: return "interpreting";
        default: return "building the drawing";
    }
}

}  // namespace essi::viewer
