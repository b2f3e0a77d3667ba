#include "essi/render_svg.hpp"

#include "essi/kerf.hpp"
#include "essi/diagnostic_marks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "essi/geom.hpp"
#include "essi/read.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "essi/pipeline.hpp"

namespace essi {

namespace {

// A scale factor or a width in mm a pixel, with its significant digits (num's 3 decimals would make the width of
// 2 pixels of a 1 mm drawing 0.002).
std::string scale_text(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// A number for SVG: 3 decimals (1 µm), trailing zeros dropped.
std::string num(double v) {
    if (!std::isfinite(v)) v = 0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") s = "0";
    return s;
}

std::string_view mark_color(Severity s) {
    switch (s) {
        case Severity::Error: return kSvgErrorColor;
        case Severity::Warning: return kSvgWarningColor;
        default: return kSvgNoteColor;
    }
}

// The lines the drawing keeps apart: every diagnostic's block, contour and related places.
std::vector<LineRange> wanted_lines(const std::vector<Diagnostic>& diagnostics) {
    std::vector<LineRange> ranges;
    for (const Diagnostic& d : diagnostics) {
        for (const LineRange& r : concerned_lines(d)) ranges.push_back(r);
        for (const LineRange& r : related_lines(d)) ranges.push_back(r);
    }
    return merge_ranges(std::move(ranges));
}

std::string range_text(LineRange r) { return std::to_string(r.first) + "-" + std::to_string(r.last); }

std::string polygon_path(const std::vector<Point>& polygon) {
    std::string d;
    for (const Point& p : polygon) d += (d.empty() ? "M" : "L") + num(p.x) + " " + num(-p.y);
    return d.empty() ? d : d + "Z";
}

// Highlight opacities and widths (SVG pixels): the contour concerned, the related places (dashed, lighter).
constexpr double kContourOpacity = 0.55, kContourWidthPx = 5;
constexpr double kRelatedOpacity = 0.35, kRelatedWidthPx = 4;
constexpr double kOverlapOpacity = 0.45;
constexpr double kMarkFillOpacity = 0.3;

// Collects the drawing: one path per motion kind, pierce points, the diagnostics' places and the lines they concern.
// The diagnostics' places come from `places`; the geometry of the lines in `wanted` (merged ranges) is kept apart
// too, by kind (the contours and related places highlighted, the problems-only view).
class SvgSink : public MotionSink {
public:
    SvgSink(double tolerance, double chord_tolerance_mm, DiagnosticPlaces& places, std::vector<LineRange> wanted)
        : tolerance_(tolerance), places_(places), wanted_(std::move(wanted)), kerf_layer_(*this),
          kerf_(kerf_layer_, chord_tolerance_mm) {}

    void on_motion(const MotionRecord& m) override {
        kerf_.motion(m);
        places_.motion(m.line, m.end);
        if (is_wanted(m.line)) {
            std::string& d = line_paths_[m.line][static_cast<std::size_t>(m.kind)];
            d += "M" + num(m.start.x) + " " + num(-m.start.y);
            points_.clear();
            flatten(m, tolerance_, points_, false);
            for (const Point& p : points_) d += "L" + num(p.x) + " " + num(-p.y);
        }
        if (m.kind == MotionKind::Cut && pierce_pending_) {
            pierces_.push_back(m.start);
            pierce_pending_ = false;
        }
        const auto k = static_cast<std::size_t>(m.kind);
        std::string& d = paths_[k];
        if (!has_last_[k] || !(last_[k] == m.start)) {
            d += "M" + num(m.start.x) + " " + num(-m.start.y);
        }
        points_.clear();
        flatten(m, tolerance_, points_, false);
        for (const Point& p : points_) d += "L" + num(p.x) + " " + num(-p.y);
        last_[k] = m.end;
        has_last_[k] = true;
    }

    void on_event(const MachineEvent& e) override {
        const bool cutting_after = (e.tools_after & kCuttingTools) != 0;
        if (cutting_after && !cutting_) pierce_pending_ = true;
        if (!cutting_after) pierce_pending_ = false;
        cutting_ = cutting_after;
    }

    // The path data of lines [r.first, r.last] (every kind, or one kind), from the lines kept.
    [[nodiscard]] std::string lines_path(LineRange r) const {
        std::string d;
        for (auto it = line_paths_.lower_bound(r.first); it != line_paths_.end() && it->first <= r.last; ++it)
            for (const std::string& k : it->second) d += k;
        return d;
    }
    [[nodiscard]] std::string lines_path(LineRange r, MotionKind kind) const {
        std::string d;
        for (auto it = line_paths_.lower_bound(r.first); it != line_paths_.end() && it->first <= r.last; ++it)
            d += it->second[static_cast<std::size_t>(kind)];
        return d;
    }

    std::array<std::string, 4> paths_;  // by MotionKind: rapid, travel, cut, mark
    std::vector<Point> pierces_;
    std::string kerf_path_;                     // the compensated torch path (§8) while compensation is on
    std::map<double, std::string> kerf_bands_;  // the cuts' compensated path by kerf width (the band's width)
    void finish() { kerf_.finish(); }

private:
    // The compensated pieces: the kerf layer, and for cuts the band of the kerf's width.
    class KerfLayer final : public MotionSink {
    public:
        explicit KerfLayer(SvgSink& svg) : svg_(svg) {}
        void on_motion(const MotionRecord& m) override {
            if (m.kerf == KerfSide::Off) {
                at_valid_ = false;
                return;
            }
            svg_.points_.clear();
            flatten(m, svg_.tolerance_, svg_.points_, false);
            std::string d = "M" + num(m.start.x) + " " + num(-m.start.y);
            for (const Point& p : svg_.points_) d += "L" + num(p.x) + " " + num(-p.y);
            if (!at_valid_ || !(at_ == m.start)) svg_.kerf_path_ += "M" + num(m.start.x) + " " + num(-m.start.y);
            svg_.kerf_path_ += d.substr(d.find('L') == std::string::npos ? d.size() : d.find('L'));
            if (m.kind == MotionKind::Cut) svg_.kerf_bands_[2 * m.kerf_mm] += d;
            at_ = m.end;
            at_valid_ = true;
        }

    private:
        SvgSink& svg_;
        Point at_;
        bool at_valid_ = false;
    };

    double tolerance_;
    std::array<Point, 4> last_{};
    std::array<bool, 4> has_last_{};
    std::vector<Point> points_;
    [[nodiscard]] bool is_wanted(std::uint32_t line) const {
        const auto it = std::upper_bound(wanted_.begin(), wanted_.end(), line,
                                         [](std::uint32_t l, const LineRange& r) { return l < r.first; });
        return it != wanted_.begin() && line <= std::prev(it)->last;
    }
    DiagnosticPlaces& places_;
    std::vector<LineRange> wanted_;
    std::map<std::uint32_t, std::array<std::string, 4>> line_paths_;  // by line, by MotionKind
    bool cutting_ = false;
    bool pierce_pending_ = false;
    KerfLayer kerf_layer_;
    KerfPath kerf_;
};

// The contour each diagnostic concerns, and its related places (dashed, lighter), under the marks.
// `px`: mm a pixel of the SVG. Every stroke width and dash is given in mm (its pixels times px), not with
// vector-effect="non-scaling-stroke": rsvg-convert (the PNG) ignores that, and a tape of a kilometre had strokes
// of a thousandth of a pixel.
void write_highlights(std::string& s, const std::vector<Diagnostic>& diagnostics, const SvgSink& sink, double px) {
    s += "<g id=\"highlights\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    for (std::size_t k = 0; k < diagnostics.size(); ++k) {
        const Diagnostic& d = diagnostics[k];
        const std::string color(mark_color(d.severity)), index = std::to_string(k);
        if (d.contour_first > 0) {
            const LineRange r{d.contour_first, std::max(d.contour_first, d.contour_last)};
            const std::string path = sink.lines_path(r);
            if (!path.empty())
                s += "<path class=\"contour-highlight\" data-diagnostic=\"" + index + "\" data-lines=\"" +
                     range_text(r) + "\" stroke=\"" + color + "\" stroke-opacity=\"" + num(kContourOpacity) +
                     "\" stroke-width=\"" + scale_text(kContourWidthPx * px) + "\" d=\"" + path + "\"/>\n";
        }
        for (const RelatedLocation& rel : d.related()) {
            const LineRange r{rel.line, std::max(rel.line, rel.end_line)};
            const std::string path = rel.line > 0 ? sink.lines_path(r) : std::string();
            if (path.empty()) continue;
            s += "<path class=\"related\" data-diagnostic=\"" + index + "\" data-lines=\"" + range_text(r) +
                 "\" stroke=\"" + color + "\" stroke-opacity=\"" + num(kRelatedOpacity) + "\" stroke-width=\"" +
                 scale_text(kRelatedWidthPx * px) + "\" stroke-dasharray=\"" + scale_text(6 * px) + " " +
                 scale_text(4 * px) + "\" d=\"" + path + "\"><title>" + xml_escape(related_message(rel, Lang::En)) +
                 "</title></path>\n";
        }
    }
    s += "</g>\n";
}

// A collision's overlapping area: the area inside every polygon of Diagnostic::overlap, exactly: the first
// polygon filled inside nested groups clipped by each of the others.
void write_overlaps(std::string& s, const std::vector<Diagnostic>& diagnostics) {
    s += "<g id=\"overlaps\" stroke=\"none\">\n";
    for (std::size_t k = 0; k < diagnostics.size(); ++k) {
        const Diagnostic& d = diagnostics[k];
        if (d.overlap().empty()) continue;
        const std::string index = std::to_string(k);
        const auto clip_id = [&](std::size_t j) { return "overlap-" + index + "-" + std::to_string(j); };
        s += "<defs>";
        for (std::size_t j = 1; j < d.overlap().size(); ++j)
            s += "<clipPath id=\"" + clip_id(j) + "\" clipPathUnits=\"userSpaceOnUse\"><path d=\"" +
                 polygon_path(d.overlap()[j]) + "\"/></clipPath>";
        s += "</defs>\n<g class=\"overlap\" data-diagnostic=\"" + index + "\" data-polygons=\"" +
             std::to_string(d.overlap().size()) + "\">";
        for (std::size_t j = 1; j < d.overlap().size(); ++j) s += "<g clip-path=\"url(#" + clip_id(j) + ")\">";
        s += "<path class=\"overlap-area\" fill=\"" + std::string(mark_color(d.severity)) + "\" fill-opacity=\"" +
             num(kOverlapOpacity) + "\" d=\"" + polygon_path(d.overlap()[0]) + "\"/>";
        for (std::size_t j = 1; j < d.overlap().size(); ++j) s += "</g>";
        s += "</g>\n";
    }
    s += "</g>\n";
}

// A mark per diagnostic with a place: a circle of kSvgMarkRadiusPx SVG pixels (`px`: mm a pixel) in the severity's
// colour (errors crossed), the diagnostic and its related places as the tooltip.
void write_marks(std::string& s, const std::vector<Diagnostic>& diagnostics,
                 const std::vector<std::optional<Point>>& places, const std::string& title, double px) {
    const double r = kSvgMarkRadiusPx * px;
    s += "<g id=\"diagnostics\" stroke-width=\"" + scale_text(2 * px) + "\">\n";
    for (std::size_t k = 0; k < diagnostics.size(); ++k) {
        if (!places[k]) continue;
        const Diagnostic& d = diagnostics[k];
        const Point p = *places[k];
        const std::string color(mark_color(d.severity));
        std::string tip = diagnostic_line(title, d);
        for (const RelatedLocation& rel : d.related()) tip += "\n  " + related_message(rel, Lang::En);
        s += "<g class=\"diagnostic " + std::string(severity_name(d.severity)) + "\" id=\"diagnostic-" +
             std::to_string(k) + "\" data-index=\"" + std::to_string(k) + "\" data-code=\"" + code_name(d.code) +
             "\" data-line=\"" + std::to_string(d.line) + "\" data-x=\"" + num(p.x) + "\" data-y=\"" + num(p.y) +
             "\" data-r-px=\"" + num(kSvgMarkRadiusPx) + "\" stroke=\"" + color + "\" fill=\"" + color +
             "\" fill-opacity=\"" + num(kMarkFillOpacity) + "\"><title>" + xml_escape(tip) + "</title>";
        s += "<circle cx=\"" + num(p.x) + "\" cy=\"" + num(-p.y) + "\" r=\"" + num(r) + "\"/>";
        if (d.severity == Severity::Error)
            s += "<path d=\"M" + num(p.x - r) + " " + num(-p.y - r) + "L" + num(p.x + r) + " " + num(-p.y + r) + "M" +
                 num(p.x - r) + " " + num(-p.y + r) + "L" + num(p.x + r) + " " + num(-p.y - r) + "\"/>";
        s += "</g>\n";
    }
    s += "</g>\n";
}

// The problems only: what the diagnostics concern drawn again in its colours over the faint drawing.
void write_concerned(std::string& s, const std::vector<LineRange>& wanted, const SvgSink& sink, double px) {
    s += "<g id=\"concerned\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    const std::pair<MotionKind, std::string_view> kinds[] = {{MotionKind::Rapid, kSvgRapidColor},
                                                             {MotionKind::Travel, kSvgTravelColor},
                                                             {MotionKind::Mark, kSvgMarkColor},
                                                             {MotionKind::Cut, kSvgCutColor}};
    for (const auto& [kind, color] : kinds) {
        std::string d;
        for (const LineRange& r : wanted) d += sink.lines_path(r, kind);
        if (!d.empty())
            s += "<path class=\"concerned " + std::string(motion_kind_name(kind)) + "\" stroke=\"" +
                 std::string(color) + "\" stroke-width=\"" + scale_text(2 * px) + "\" d=\"" + d + "\"/>\n";
    }
    s += "</g>\n";
}

// Each plate's outline and its remnant (filled faintly), in program mm (y negated).
void write_plates(std::string& s, const std::vector<PlateUse>& plates, const std::string& stroke,
                  const std::string& dashes) {
    const auto rect = [](const Box& b) {
        return "x=\"" + num(b.min_x) + "\" y=\"" + num(-b.max_y) + "\" width=\"" + num(b.max_x - b.min_x) +
               "\" height=\"" + num(b.max_y - b.min_y) + "\"";
    };
    s += "<g id=\"plates\" fill=\"none\" stroke=\"" + std::string(kSvgRemnantColor) + "\"" + stroke + ">\n";
    for (const PlateUse& p : plates) {
        s += "<rect class=\"plate\" data-plate=\"" + std::to_string(p.plate) + "\" " + rect(p.area) + "/>\n";
        if (p.remnant)
            s += "<rect class=\"remnant\" data-plate=\"" + std::to_string(p.plate) + "\" data-remnant-mm=\"" +
                 num(p.remnant->min_x) + " " + num(p.remnant->min_y) + " " + num(p.remnant->max_x) + " " +
                 num(p.remnant->max_y) + "\" " + rect(*p.remnant) + " fill=\"" + std::string(kSvgRemnantColor) +
                 "\" fill-opacity=\"0.1\"" + dashes + "/>\n";
    }
    s += "</g>\n";
}

}  // namespace

RenderResult render_svg(std::string_view bytes, const Profile& profile, const RenderOptions& options,
                        InputFormat format) {
    RenderResult out;
    // Pass 1: the check (diagnostics, stats, extent).
    out.result = check_tape(bytes, profile, format, static_cast<std::size_t>(-1), options.remnant);
    const Stats& st = out.result.stats;
    Box box = st.motion_bbox;
    box.add(st.cut_bbox);
    if (out.result.parts)
        for (const PlateUse& p : out.result.parts->plates) box.add(p.area);
    if (box.empty) box.add(Point{0, 0});
    double w = box.max_x - box.min_x, h = box.max_y - box.min_y;
    const double extent = std::max({w, h, 10.0});
    const double tolerance = std::max(extent / 4000.0, std::max(profile.chord_tolerance_mm, kMinChordTolerance));

    // Pass 2: the drawing (the same pipeline with a sink; its result is the same as pass 1's).
    const std::vector<Diagnostic>& diagnostics = options.diagnostics ? *options.diagnostics : out.result.diagnostics;
    DiagnosticPlaces places(diagnostics);
    const std::vector<LineRange> wanted = wanted_lines(diagnostics);
    SvgSink sink(tolerance, profile.chord_tolerance_mm, places, wanted);
    {
        TapeChecker checker(bytes, profile, &sink);
        TapeReader reader(bytes, profile, format);
        Tape chunk;
        while (reader.read_chunk(chunk, kCheckChunkBlocks)) checker.check_chunk(chunk);
        (void)checker.finish();
        sink.finish();
    }

    double margin = std::max(extent * 0.05, 1.0);
    if (options.view && !options.view->empty) {  // (a view: that box, no margin; the legend's size by its extent)
        box = *options.view;
        w = box.max_x - box.min_x;
        h = box.max_y - box.min_y;
        margin = 0;
    }
    const double shown = options.view ? std::max({w, h, 1e-3}) : extent;  // (the legend and markers scale with it)
    const double font = shown * 0.022;
    // The colour key: a short sample line and a name per layer, on a second row when one is too narrow.
    struct Key {
        std::string_view name, color;
        const char* dash;
    };
    std::vector<Key> keys = {{"cut", kSvgCutColor, ""},
                             {"mark", kSvgMarkColor, ""},
                             {"travel", kSvgTravelColor, " stroke-dasharray=\"2 2\""},
                             {"rapid", kSvgRapidColor, " stroke-dasharray=\"4 3\""}};
    if (!sink.kerf_path_.empty()) keys.push_back({"kerf", kSvgKerfColor, ""});
    if (out.result.parts && !out.result.parts->plates.empty())
        keys.push_back({"remnant", kSvgRemnantColor, " stroke-dasharray=\"4 2\""});
    for (const Key k : {Key{"pierce", kSvgPierceColor, ""}, Key{"error", kSvgErrorColor, ""},
                        Key{"warning", kSvgWarningColor, ""}, Key{"note", kSvgNoteColor, ""}})
        keys.push_back(k);
    const double sample = font * 2;
    const auto key_width = [&](const Key& k) {
        return sample + font * (1.0 + 0.62 * static_cast<double>(k.name.size()));
    };
    double keys_width = 0;
    for (const Key& k : keys) keys_width += key_width(k);
    const std::size_t key_break =
        keys_width > w + margin ? keys.size() / 2 + 1 : keys.size();  // (the second row's first)
    const double legend_h = font * (key_break < keys.size() ? 5.9 : 4.6);
    const double vx = box.min_x - margin, vy = -box.max_y - margin;
    const double vw = w + 2 * margin, vh = h + 2 * margin + legend_h;
    const double height_px = std::max(1.0, std::round(options.width_px * vh / vw));
    const double marker_r = shown * 0.006;
    const double px = vw / options.width_px;  // mm a pixel of the SVG (stroke widths: write_highlights)
    const auto stroke = [&](double width_px) { return " stroke-width=\"" + scale_text(width_px * px) + "\""; };
    const auto dashes = [&](double on_px, double off_px) {
        return " stroke-dasharray=\"" + scale_text(on_px * px) + " " + scale_text(off_px * px) + "\"";
    };

    const std::size_t errors = out.result.count(Severity::Error), warnings = out.result.count(Severity::Warning),
                      notes = out.result.count(Severity::Note);
    std::string s;
    s.reserve(bytes.size() * 2 + 4096);
    s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(options.width_px) + "\" height=\"" +
         num(height_px) + "\" viewBox=\"" + num(vx) + " " + num(vy) + " " + num(vw) + " " + num(vh) +
         "\" data-generator=\"essi render\"" +
         (options.view ? " data-view=\"" + num(box.min_x) + " " + num(box.min_y) + " " + num(box.max_x) + " " +
                             num(box.max_y) + "\""
                       : "") +
         ">\n";
    s += "<title>" + xml_escape(options.title) + "</title>\n";
    s += "<rect id=\"background\" x=\"" + num(vx) + "\" y=\"" + num(vy) + "\" width=\"" + num(vw) + "\" height=\"" +
         num(vh) + "\" fill=\"#ffffff\"/>\n";
    // Machine y points up: every y below is negated.
    s += "<g id=\"drawing\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\"" +
         (options.problems_only ? " class=\"dimmed\" opacity=\"" + num(kSvgDimOpacity) + "\"" : std::string()) + ">\n";
    struct Layer {
        MotionKind kind;
        const char* name;
        std::string_view color;
        std::string extra;
    };
    const Layer layers[] = {
        {MotionKind::Rapid, "rapid", kSvgRapidColor, stroke(1) + dashes(4, 3)},
        {MotionKind::Travel, "travel", kSvgTravelColor, stroke(1) + dashes(2, 2)},
        {MotionKind::Mark, "mark", kSvgMarkColor, stroke(1.5)},
        {MotionKind::Cut, "cut", kSvgCutColor, stroke(2)},
    };
    for (const Layer& l : layers) {
        const std::string& d = sink.paths_[static_cast<std::size_t>(l.kind)];
        if (d.empty()) continue;
        if (!options.show_travel && (l.kind == MotionKind::Rapid || l.kind == MotionKind::Travel)) continue;
        s += "<path id=\"" + std::string(l.name) + "\" class=\"" + l.name + "\" stroke=\"" + std::string(l.color) +
             "\"" + l.extra + " d=\"" + d + "\"/>\n";
    }
    // The kerf: the cut's real width (a band as wide as the kerf along the compensated path) and the torch's path.
    for (const auto& [width, d] : sink.kerf_bands_)
        s += "<path class=\"kerf-band\" data-width-mm=\"" + num(width) + "\" stroke=\"" +
             std::string(kSvgKerfBandColor) + "\" stroke-opacity=\"0.25\" stroke-width=\"" + num(width) + "\" d=\"" +
             d + "\"/>\n";
    if (!sink.kerf_path_.empty())
        s += "<path id=\"kerf\" class=\"kerf\" stroke=\"" + std::string(kSvgKerfColor) + "\"" + stroke(1) + " d=\"" +
             sink.kerf_path_ + "\"/>\n";
    s += "</g>\n<g id=\"pierces\" fill=\"none\" stroke=\"" + std::string(kSvgPierceColor) + "\"" + stroke(1.5) +
         (options.problems_only ? " opacity=\"" + num(kSvgDimOpacity) + "\"" : std::string()) + ">\n";
    for (const Point& p : sink.pierces_)
        s +=
            "<circle class=\"pierce\" cx=\"" + num(p.x) + "\" cy=\"" + num(-p.y) + "\" r=\"" + num(marker_r) + "\"/>\n";
    s += "</g>\n";
    if (out.result.parts) write_plates(s, out.result.parts->plates, stroke(1), dashes(6, 3));
    if (options.problems_only) write_concerned(s, wanted, sink, px);
    write_overlaps(s, diagnostics);
    write_highlights(s, diagnostics, sink, px);
    write_marks(s, diagnostics, places.places(), options.title, px);

    // Legend: below the drawing, written in the SVG's pixels inside a group scaled to mm (a font of 22 000 mm made
    // the PNG's font library fail on a tape of a kilometre).
    const double lx = vx + margin * 0.5, ly0 = -box.min_y + margin;
    const double font_px = font / px, sample_px = sample / px;
    double ly = font_px * 1.2;
    char timebuf[32];
    std::snprintf(timebuf, sizeof timebuf, "%.1f", st.estimated_time_s);
    const std::string cut_mm = mm_text(st.cut_length_mm);
    s += "<g id=\"legend\" transform=\"translate(" + num(lx) + " " + num(ly0) + ") scale(" + scale_text(px) +
         ")\" font-family=\"sans-serif\" font-size=\"" + num(font_px) + "\" fill=\"#202020\">\n";
    s += "<text id=\"legend-file\" x=\"0\" y=\"" + num(ly) + "\" font-weight=\"bold\">" + xml_escape(options.title) +
         "</text>\n";
    ly += font_px * 1.3;
    s += "<text id=\"legend-numbers\" x=\"0\" y=\"" + num(ly) + "\" data-cut-length-mm=\"" + cut_mm +
         "\" data-pierces=\"" + std::to_string(st.pierces) + "\" data-time-s=\"" + timebuf + "\" data-errors=\"" +
         std::to_string(errors) + "\" data-warnings=\"" + std::to_string(warnings) + "\" data-notes=\"" +
         std::to_string(notes) + "\">cut " + cut_mm + " mm, " + std::to_string(st.pierces) +
         (st.pierces == 1 ? " pierce" : " pierces") + ", time " + format_duration(st.estimated_time_s) + ", " +
         std::to_string(errors) + (errors == 1 ? " error" : " errors") + ", " + std::to_string(warnings) +
         (warnings == 1 ? " warning" : " warnings") + "</text>\n";
    ly += font_px * 1.3;
    double kx = 0;
    auto key = [&](std::string_view name, std::string_view color, const char* dash) {
        s += "<g class=\"key\" data-kind=\"" + std::string(name) + "\"><path d=\"M" + num(kx) + " " +
             num(ly - font_px * 0.35) + "h" + num(sample_px) + "\" stroke=\"" + std::string(color) +
             "\" stroke-width=\"2\"" + dash + "/><text x=\"" + num(kx + sample_px + font_px * 0.3) + "\" y=\"" +
             num(ly) + "\">" + std::string(name) + "</text></g>\n";
        kx += sample_px + font_px * (1.0 + 0.62 * static_cast<double>(name.size()));
    };
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (k == key_break) {
            kx = 0;
            ly += font_px * 1.3;
        }
        key(keys[k].name, keys[k].color, keys[k].dash);
    }
    s += "</g>\n</svg>\n";
    out.svg = std::move(s);
    return out;
}

}  // namespace essi
