#include "render/PathBuffers.hpp"

#include <algorithm>

#include "essi/geom.hpp"

namespace essi::viewer {

void PathBuffers::begin(const Document& doc, double tol) {
    doc_ = &doc;
    tolerance_ = std::max(tol, kMinChordTolerance);
    next_ = 0;
    segments.clear();
    segments.reserve(doc.motions.size() + doc.arcs.size() * 4);
    first_segment.clear();
    first_segment.reserve(doc.motions.size() + 1);
    markers.clear();
    const float ox = static_cast<float>(doc.origin.x), oy = static_cast<float>(doc.origin.y);
    (void)ox;
    (void)oy;
    for (const Point& p : doc.pierces)
        markers.push_back({static_cast<float>(p.x - doc.origin.x), static_cast<float>(p.y - doc.origin.y), 0.f});
    if (!doc.motions.empty()) {
        const Point s = doc.start_of(0);
        markers.push_back({static_cast<float>(s.x - doc.origin.x), static_cast<float>(s.y - doc.origin.y), 1.f});
    }
}

bool PathBuffers::step(std::size_t max_motions) {
    if (doc_ == nullptr) return true;
    const Document& doc = *doc_;
    const double ox = doc.origin.x, oy = doc.origin.y;
    const std::size_t stop = std::min(doc.motions.size(), next_ + max_motions);
    for (; next_ < stop; ++next_) {
        const Motion& m = doc.motions[next_];
        first_segment.push_back(static_cast<std::uint32_t>(segments.size()));
        const float kind = static_cast<float>(static_cast<int>(m.kind));
        if (m.curve == CurveKind::Line) {
            const Point a = (m.flags & Motion::kFlagJump) ? doc.start_of(next_) : (next_ > 0 ? doc.motions[next_ - 1].end : Point{});
            segments.push_back({static_cast<float>(a.x - ox), static_cast<float>(a.y - oy),
                                static_cast<float>(m.end.x - ox), static_cast<float>(m.end.y - oy), kind});
            continue;
        }
        scratch_.clear();
        flatten(doc.record(next_), tolerance_, scratch_, true);
        for (std::size_t k = 1; k < scratch_.size(); ++k) {
            segments.push_back({static_cast<float>(scratch_[k - 1].x - ox), static_cast<float>(scratch_[k - 1].y - oy),
                                static_cast<float>(scratch_[k].x - ox), static_cast<float>(scratch_[k].y - oy), kind});
        }
    }
    if (next_ >= doc.motions.size() && first_segment.size() == doc.motions.size()) {
        first_segment.push_back(static_cast<std::uint32_t>(segments.size()));
        segment_count = segments.size();
        return true;
    }
    return next_ >= doc.motions.size();
}

float PathBuffers::progress() const {
    if (doc_ == nullptr || doc_->motions.empty()) return 1.f;
    return static_cast<float>(next_) / static_cast<float>(doc_->motions.size());
}

void PathBuffers::release_segments() {
    segments.clear();
    segments.shrink_to_fit();
}

std::size_t PathBuffers::motion_of_segment(std::size_t s) const {
    auto it = std::upper_bound(first_segment.begin(), first_segment.end(), static_cast<std::uint32_t>(s));
    return static_cast<std::size_t>(it - first_segment.begin()) - 1;
}

}  // namespace essi::viewer
