#include "app/Problems.hpp"

#include <algorithm>
#include <cmath>

#include "essi/diagnostic_marks.hpp"

namespace essi::viewer {

namespace {

// The segments of motions [a, b) (the buffers know every motion's first segment once the drawing is made).
SegmentRun segments_of(const PathBuffers& buffers, std::size_t a, std::size_t b) {
    if (a >= b || b >= buffers.first_segment.size()) return {};
    return {buffers.first_segment[a], buffers.first_segment[b] - buffers.first_segment[a]};
}

bool drawing_complete(const Document& doc, const PathBuffers& buffers) {
    return buffers.first_segment.size() == doc.motions.size() + 1;
}

Rgba with_alpha(Rgba c, float a) {
    c.a = a;
    return c;
}

}  // namespace

Point mark_screen(const Document& doc, const View& view, const DiagnosticMark& mark) {
    return view.to_screen({mark.at.x - doc.origin.x, mark.at.y - doc.origin.y});
}

std::vector<std::size_t> marks_near(const Document& doc, const View& view, double sx, double sy) {
    std::vector<std::pair<double, std::size_t>> near;
    for (std::size_t k = 0; k < doc.marks.size(); ++k) {
        const Point p = mark_screen(doc, view, doc.marks[k]);
        const double d = std::hypot(p.x - sx, p.y - sy);
        if (d <= kMarkHitRadiusPx) near.emplace_back(d, k);
    }
    std::stable_sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::size_t> out;
    for (const auto& n : near) out.push_back(n.second);
    return out;
}

std::size_t mark_at(const Document& doc, const View& view, double sx, double sy) {
    const std::vector<std::size_t> near = marks_near(doc, view, sx, sy);
    return near.empty() ? kNoMark : near.front();
}

std::vector<std::size_t> active_diagnostics(const Document& doc, std::size_t hovered_mark,
                                            std::uint32_t selected_line) {
    std::vector<std::size_t> out;
    if (hovered_mark < doc.marks.size()) out.push_back(doc.marks[hovered_mark].diagnostic);
    if (selected_line == 0) return out;
    // (the diagnostics are sorted by line)
    const auto first = std::lower_bound(doc.diagnostics.begin(), doc.diagnostics.end(), selected_line,
                                        [](const Diagnostic& d, std::uint32_t l) { return d.line < l; });
    for (auto it = first; it != doc.diagnostics.end() && it->line == selected_line; ++it) {
        const auto k = static_cast<std::size_t>(it - doc.diagnostics.begin());
        if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
    }
    return out;
}

std::vector<SegmentRun> concerned_runs(const Document& doc, const PathBuffers& buffers) {
    std::vector<SegmentRun> runs;
    if (!drawing_complete(doc, buffers)) return runs;
    for (const auto& [a, b] : doc.concerned_motions) {
        const SegmentRun r = segments_of(buffers, a, b);
        if (r.count > 0) runs.push_back(r);
    }
    return runs;
}

std::vector<Highlight> diagnostic_highlights(const Document& doc, const PathBuffers& buffers,
                                             const std::vector<std::size_t>& active) {
    std::vector<Highlight> out;
    if (!drawing_complete(doc, buffers)) return out;
    const auto add = [&](const std::vector<LineRange>& ranges, Rgba color, float extra_px) {
        for (const LineRange& r : ranges) {
            const auto [a, b] = doc.motions_of_lines(r);
            const SegmentRun run = segments_of(buffers, a, b);
            if (run.count > 0) out.push_back({run, color, extra_px});
        }
    };
    for (const std::size_t k : active) {
        const Diagnostic& d = doc.diagnostics[k];
        const Rgba& c = severity_rgba(d.severity);
        add(related_lines(d), with_alpha(c, kRelatedHighlightAlpha), kRelatedHighlightExtraPx);
        add(concerned_lines(d), with_alpha(c, kContourHighlightAlpha), kContourHighlightExtraPx);
    }
    return out;
}

}  // namespace essi::viewer
