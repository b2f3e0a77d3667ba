#include "render/PathBuffers.hpp"

#include <algorithm>

#include "essi/geom.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

// The compensated pieces, to the kerf layers' segments.
class PathBuffers::KerfSegments final : public MotionSink {
public:
    explicit KerfSegments(PathBuffers& b) : b_(b) {}
    void on_motion(const MotionRecord& m) override {
        if (m.kerf != KerfSide::Off) b_.put_kerf_piece(m);
    }

private:
    PathBuffers& b_;
};

PathBuffers::PathBuffers() = default;
PathBuffers::~PathBuffers() = default;
PathBuffers::PathBuffers(PathBuffers&&) noexcept = default;
PathBuffers& PathBuffers::operator=(PathBuffers&&) noexcept = default;

void PathBuffers::begin(const Document& doc, double tol, ColourBy colour_by, const ColourSources* sources) {
    doc_ = &doc;
    tolerance_ = std::max(tol, kMinChordTolerance);
    colour_by_ = colour_by;
    bins_ = colour_by == ColourBy::Kind ? nullptr : std::make_unique<ColourBins>(doc, colour_by, sources);
    kerf_segments = 0;
    kerf_widths.fill(0);
    kerf_width_count = 0;
    // (a tape without compensation makes no kerf path: its segments are the motions' only)
    const bool compensated =
        std::any_of(doc.kerfs.begin(), doc.kerfs.end(), [](const auto& k) { return k.second > 0; });
    kerf_sink_ = compensated ? std::make_unique<KerfSegments>(*this) : nullptr;
    kerf_ = compensated ? std::make_unique<KerfPath>(*kerf_sink_, tolerance_) : nullptr;
    next_ = 0;
    segment_count = 0;
    staged_first = 0;
    staged_ends.clear();
    staged_kinds.clear();
    first_segment.clear();
    first_segment.reserve(doc.motions.size() + 1);
    markers.clear();
    markers.reserve(doc.pierces.size() + 1 + doc.marks.size());
    for (const std::uint32_t i : doc.pierces) {
        const Point p = doc.start_of(i);
        markers.push_back({static_cast<float>(p.x - doc.origin.x), static_cast<float>(p.y - doc.origin.y),
                           static_cast<float>(MarkerType::Pierce)});
    }
    if (!doc.motions.empty()) {
        const Point s = doc.start_of(0);
        markers.push_back({static_cast<float>(s.x - doc.origin.x), static_cast<float>(s.y - doc.origin.y),
                           static_cast<float>(MarkerType::Start)});
    }
    // The diagnostics' marks last: drawn over the pierces and the start.
    for (const DiagnosticMark& m : doc.marks) {
        const MarkerType type = severity_marker(doc.diagnostics[m.diagnostic].severity);
        markers.push_back({static_cast<float>(m.at.x - doc.origin.x), static_cast<float>(m.at.y - doc.origin.y),
                           static_cast<float>(type)});
    }
}

void PathBuffers::put(Point a, Point b, std::uint8_t kind) {
    const double ox = doc_->origin.x, oy = doc_->origin.y;
    const float x0 = static_cast<float>(a.x - ox), y0 = static_cast<float>(a.y - oy);
    const float x1 = static_cast<float>(b.x - ox), y1 = static_cast<float>(b.y - oy);
    staged_ends.insert(staged_ends.end(), {x0, y0, x1, y1});
    staged_kinds.push_back(kind);
    ++segment_count;
}

bool PathBuffers::step(std::size_t max_motions) {
    if (doc_ == nullptr) return true;
    const Document& doc = *doc_;
    const std::size_t stop = std::min(doc.motions.size(), next_ + max_motions);
    for (; next_ < stop; ++next_) {
        const Motion& m = doc.motions[next_];
        first_segment.push_back(static_cast<std::uint32_t>(segment_count));
        if (kerf_) kerf_->motion(doc.record(next_));
        auto kind = static_cast<std::uint8_t>(m.kind);
        if (bins_) {
            if (const std::optional<std::uint8_t> bin = bins_->bin(next_))
                kind = static_cast<std::uint8_t>((m.kind == MotionKind::Cut ? kColourByCutKind : kColourByMarkKind) +
                                                 *bin);
        }
        // A cut by several torches (kept: its record says how many) is drawn once per torch.
        const MotionRecord* torches = doc.torch_copies(next_);
        const int copies = torches ? torches->torches : 1;
        if (m.curve == CurveKind::Line) {
            for (int c = 0; c < copies; ++c)
                put(torch_copy(doc.start_of(next_), torches ? torches->torch_step : Point{}, c),
                    torch_copy(doc.end_of(next_), torches ? torches->torch_step : Point{}, c), kind);
            continue;
        }
        scratch_.clear();
        flatten(doc.record(next_), tolerance_, scratch_, true);
        for (int c = 0; c < copies; ++c) {
            const Point step = torches ? torches->torch_step : Point{};
            for (std::size_t k = 1; k < scratch_.size(); ++k)
                put(torch_copy(scratch_[k - 1], step, c), torch_copy(scratch_[k], step, c), kind);
        }
    }
    if (next_ >= doc.motions.size()) {
        if (kerf_) {
            kerf_->finish();  // (the last piece: among the last motion's segments)
            kerf_.reset();
            kerf_sink_.reset();
        }
        if (first_segment.size() == doc.motions.size())
            first_segment.push_back(static_cast<std::uint32_t>(segment_count));
        return true;
    }
    return false;
}

// The band's kind for a kerf width: the widths in order of appearance, the last for any beyond kKerfBandWidths.
std::uint8_t PathBuffers::band_kind(double width_mm) {
    const auto w = static_cast<float>(width_mm);
    for (std::size_t k = 0; k < kerf_width_count; ++k)
        if (kerf_widths[k] == w) return static_cast<std::uint8_t>(kKerfBandKind + k);
    if (kerf_width_count < kKerfBandWidths) kerf_widths[kerf_width_count++] = w;
    return static_cast<std::uint8_t>(kKerfBandKind + kerf_width_count - 1);
}

// A compensated piece: the band of the cut's width under it (cuts only), the torch's path over it.
void PathBuffers::put_kerf_piece(const MotionRecord& piece) {
    kerf_scratch_.clear();
    flatten(piece, tolerance_, kerf_scratch_, true);
    const std::uint8_t band = piece.kind == MotionKind::Cut ? band_kind(2 * piece.kerf_mm) : 0;
    for (int c = 0; c < piece.torches; ++c) {
        for (std::size_t k = 1; k < kerf_scratch_.size(); ++k) {
            const Point a = torch_copy(kerf_scratch_[k - 1], piece.torch_step, c),
                        b = torch_copy(kerf_scratch_[k], piece.torch_step, c);
            if (band) put(a, b, band);
            put(a, b, kKerfPathKind);
            kerf_segments += band ? 2 : 1;
        }
    }
}

std::size_t PathBuffers::estimated_segments() const {
    if (doc_ == nullptr) return 0;
    if (complete() || next_ == 0) return std::max(segment_count, doc_->motions.size());
    const double per_motion = static_cast<double>(segment_count) / static_cast<double>(next_);
    return static_cast<std::size_t>(per_motion * static_cast<double>(doc_->motions.size()));
}

float PathBuffers::progress() const {
    if (doc_ == nullptr || doc_->motions.empty()) return 1.f;
    return static_cast<float>(next_) / static_cast<float>(doc_->motions.size());
}

void PathBuffers::drop_staged(std::size_t n) {
    n = std::min(n, staged_count());
    staged_ends.erase(staged_ends.begin(), staged_ends.begin() + static_cast<std::ptrdiff_t>(4 * n));
    staged_kinds.erase(staged_kinds.begin(), staged_kinds.begin() + static_cast<std::ptrdiff_t>(n));
    staged_first += n;
}

void PathBuffers::release_staging() {
    staged_ends = std::vector<float>();  // (`= {}` would keep the capacity)
    staged_kinds = std::vector<std::uint8_t>();
}

std::size_t PathBuffers::memory_bytes() const {
    return first_segment.capacity() * sizeof(std::uint32_t) + markers.capacity() * sizeof(MarkerInstance) +
           staged_ends.capacity() * sizeof(float) + staged_kinds.capacity();
}

}  // namespace essi::viewer
