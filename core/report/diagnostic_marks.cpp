#include "essi/diagnostic_marks.hpp"

#include <algorithm>

namespace essi {

std::optional<Point> diagnostic_place(const Diagnostic& d, const LineEnds& ends) {
    if (d.has_at) return d.at;
    if (d.line == 0) return std::nullopt;
    return ends.first_motion_end ? ends.first_motion_end : ends.end_before;
}

DiagnosticPlaces::DiagnosticPlaces(const std::vector<Diagnostic>& diagnostics) : diagnostics_(diagnostics) {
    for (const Diagnostic& d : diagnostics)
        if (!d.has_at && d.line > 0) lines_.push_back(d.line);
    std::sort(lines_.begin(), lines_.end());
    lines_.erase(std::unique(lines_.begin(), lines_.end()), lines_.end());
    ends_.resize(lines_.size());
}

void DiagnosticPlaces::motion(std::uint32_t line, Point end) {
    // The lines the stream has passed without a motion of theirs: the machine stood where the last motion ended.
    while (next_ < lines_.size() && lines_[next_] < line) ends_[next_++].end_before = last_end_;
    if (next_ < lines_.size() && lines_[next_] == line) {
        ends_[next_].end_before = last_end_;
        ends_[next_++].first_motion_end = end;  // (the line's first motion: the next ones pass it by)
    }
    last_end_ = end;
}

std::vector<std::optional<Point>> DiagnosticPlaces::places() const {
    std::vector<std::optional<Point>> out;
    out.reserve(diagnostics_.size());
    for (const Diagnostic& d : diagnostics_) {
        const auto it = std::lower_bound(lines_.begin(), lines_.end(), d.line);
        LineEnds ends;
        if (it != lines_.end() && *it == d.line) {
            const auto k = static_cast<std::size_t>(it - lines_.begin());
            ends = k < next_ ? ends_[k] : LineEnds{std::nullopt, last_end_};  // (lines after the last motion)
        }
        out.push_back(diagnostic_place(d, ends));
    }
    return out;
}

std::vector<LineRange> concerned_lines(const Diagnostic& d) {
    std::vector<LineRange> out;
    if (d.line > 0) out.push_back({d.line, d.line});
    if (d.contour_first > 0) out.push_back({d.contour_first, std::max(d.contour_first, d.contour_last)});
    return out;
}

std::vector<LineRange> related_lines(const Diagnostic& d) {
    std::vector<LineRange> out;
    for (const RelatedLocation& r : d.related())
        if (r.line > 0) out.push_back({r.line, std::max(r.line, r.end_line)});
    return out;
}

std::vector<LineRange> merge_ranges(std::vector<LineRange> ranges) {
    std::sort(ranges.begin(), ranges.end(), [](const LineRange& a, const LineRange& b) { return a.first < b.first; });
    std::vector<LineRange> out;
    for (const LineRange& r : ranges) {
        if (!out.empty() && r.first <= out.back().last + 1) out.back().last = std::max(out.back().last, r.last);
        else out.push_back(r);
    }
    return out;
}

namespace {

// Where the polygon's edges cross the line y, sorted: between crossings 0-1, 2-3, ... the line is inside.
std::vector<double> crossings(const std::vector<Point>& polygon, double y) {
    std::vector<double> xs;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % n];
        if ((a.y <= y) == (b.y <= y)) continue;  // (half-open: a vertex on the line counts once)
        xs.push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
    }
    std::sort(xs.begin(), xs.end());
    return xs;
}

// The intersection of two sorted lists of disjoint intervals.
std::vector<std::pair<double, double>> intersect(const std::vector<std::pair<double, double>>& a,
                                                 const std::vector<std::pair<double, double>>& b) {
    std::vector<std::pair<double, double>> out;
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const double lo = std::max(a[i].first, b[j].first), hi = std::min(a[i].second, b[j].second);
        if (lo < hi) out.emplace_back(lo, hi);
        if (a[i].second < b[j].second) ++i;
        else ++j;
    }
    return out;
}

}  // namespace

std::vector<std::pair<double, double>> overlap_spans(const std::vector<std::vector<Point>>& polygons, double y) {
    std::vector<std::pair<double, double>> spans;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
        const std::vector<double> xs = crossings(polygons[k], y);
        std::vector<std::pair<double, double>> inside;
        for (std::size_t i = 0; i + 1 < xs.size(); i += 2) inside.emplace_back(xs[i], xs[i + 1]);
        spans = k == 0 ? std::move(inside) : intersect(spans, inside);
        if (spans.empty()) break;
    }
    return spans;
}

}  // namespace essi
