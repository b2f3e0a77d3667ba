// The job sheet as one self-contained HTML file (essi/job_sheet.hpp): the CSS inline, the drawing an inline SVG in
// paper millimetres, A4 pages when printed (@page), well-formed XML as well.
#include "essi/job_sheet.hpp"

#include <string>

#include "essi/text.hpp"

namespace essi {
namespace {

constexpr const char* kBaseCss = R"css(
@page { size: A4 portrait; margin: 15mm; }
html { font-family: "DejaVu Sans", "WenQuanYi Micro Hei", sans-serif; font-size: 8.5pt; color: #202020; }
body { margin: 0 auto; max-width: 180mm; }
@media screen { body { padding: 10mm 0; } }
h1 { font-size: 16pt; margin: 0 0 1mm; }
p.tape { font-size: 11pt; margin: 0 0 3mm; overflow-wrap: anywhere; }
h2 { font-size: 11pt; margin: 5mm 0 1.5mm; padding-bottom: 0.5mm; border-bottom: 0.3mm solid #999; break-after: avoid; }
table { border-collapse: collapse; width: 100%; }
table.fields { break-inside: avoid; }
table.fields th { width: 50mm; text-align: left; font-weight: normal; color: #555; vertical-align: top;
                  padding: 0.4mm 2mm 0.4mm 0; }
table.fields td { padding: 0.4mm 0; vertical-align: top; overflow-wrap: anywhere; }
table.list th { text-align: left; background: #eee; padding: 0.6mm 1.5mm; }
table.list td { border-bottom: 0.2mm solid #ddd; padding: 0.6mm 1.5mm; vertical-align: top; overflow-wrap: anywhere; }
table.list .num { text-align: right; white-space: nowrap; }
thead { display: table-header-group; }
tr { break-inside: avoid; }
section.drawing { break-inside: avoid; }
svg.drawing { display: block; border: 0.2mm solid #bbb; }
ul.legend { list-style: none; padding: 0; margin: 1.5mm 0; display: flex; flex-wrap: wrap; gap: 1mm 5mm; }
ul.legend svg { vertical-align: middle; margin-right: 1mm; }
p.note { color: #555; margin: 1mm 0; }
footer { margin-top: 6mm; padding-top: 1mm; border-top: 0.2mm solid #ccc; font-size: 7pt; color: #777; }
)css";

std::string esc(std::string_view s) { return xml_escape(s); }
// A length on paper (mm) for the SVG: 10 µm.
std::string paper(double v) { return fixed_text(v, 2); }

void write_fields(std::string& h, const SheetSection& s) {
    h += "<table class=\"fields\">\n";
    for (const SheetField& f : s.fields) h += "<tr><th>" + esc(f.label) + "</th><td>" + esc(f.value) + "</td></tr>\n";
    h += "</table>\n";
}

void write_table(std::string& h, const SheetTable& t) {
    const auto cell_class = [&](std::size_t c, bool first_of_diagnostic) {
        std::string cls = t.numeric[c] ? "num" : "";
        if (first_of_diagnostic) cls += cls.empty() ? "severity" : " severity";
        return cls.empty() ? std::string() : " class=\"" + cls + "\"";
    };
    h += "<table class=\"list\">\n<thead><tr>";
    for (std::size_t c = 0; c < t.columns.size(); ++c)
        h += "<th" + cell_class(c, false) + ">" + esc(t.columns[c]) + "</th>";
    h += "</tr></thead>\n<tbody>\n";
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        const std::optional<Severity>& sev = t.row_severity[r];
        const std::string severity = sev ? std::string(severity_name(*sev)) : std::string();
        h += severity.empty() ? std::string("<tr>") : "<tr class=\"" + severity + "\">";
        for (std::size_t c = 0; c < t.rows[r].size(); ++c) {
            const bool colored = !severity.empty() && c == 0;
            h += "<td" + cell_class(c, colored) + ">" + esc(t.rows[r][c]) + "</td>";
        }
        h += "</tr>\n";
    }
    h += "</tbody>\n</table>\n";
}

std::string stroke_attributes(const SheetStroke& s) {
    std::string a = "stroke=\"" + std::string(s.color) + "\" stroke-width=\"" + paper(s.width_mm) + "\"";
    if (s.dash_mm > 0) a += " stroke-dasharray=\"" + paper(s.dash_mm) + " " + paper(s.dash_mm) + "\"";
    return a;
}

std::string mark_shape(Point c, Severity sev) {
    const double r = kSheetMarkRadiusMm;
    const std::string color(sheet_mark_color(sev));
    std::string s = "<g class=\"mark " + std::string(severity_name(sev)) + "\" stroke=\"" + color + "\" fill=\"" +
                    color + "\" stroke-width=\"0.3\"><circle cx=\"" + paper(c.x) + "\" cy=\"" + paper(c.y) + "\" r=\"" +
                    paper(r) + "\" fill-opacity=\"0.3\"/>";
    if (sev == Severity::Error)
        s += "<path d=\"M" + paper(c.x - r) + " " + paper(c.y - r) + "L" + paper(c.x + r) + " " + paper(c.y + r) + "M" +
             paper(c.x - r) + " " + paper(c.y + r) + "L" + paper(c.x + r) + " " + paper(c.y - r) + "\"/>";
    return s + "</g>";
}

std::string label_text(Point at, std::string_view text) {
    return "<text class=\"part-label\" x=\"" + paper(at.x) + "\" y=\"" + paper(at.y) + "\" font-size=\"" +
           paper(kSheetLabelHeightMm) +
           "\" font-weight=\"bold\" text-anchor=\"middle\" dominant-baseline=\"central\" fill=\"#202020\" "
           "stroke=\"#ffffff\" stroke-width=\"0.6\" paint-order=\"stroke\">" +
           esc(text) + "</text>";
}

void write_drawing(std::string& h, const SheetDrawing& d) {
    h += "<svg class=\"drawing\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" + paper(d.width_mm) + "mm\" height=\"" +
         paper(d.height_mm) + "mm\" viewBox=\"0 0 " + paper(d.width_mm) + " " + paper(d.height_mm) + "\">\n";
    h += "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    for (const MotionKind kind : kSheetDrawOrder) {
        std::string path;
        for (const std::vector<Point>& line : d.paths[static_cast<std::size_t>(kind)]) {
            if (line.size() < 2) continue;
            for (std::size_t i = 0; i < line.size(); ++i) {
                const Point p = d.to_paper(line[i]);
                path += (i == 0 ? "M" : "L") + paper(p.x) + " " + paper(p.y);
            }
        }
        if (!path.empty())
            h += "<path class=\"" + std::string(motion_kind_name(kind)) + "\" " +
                 stroke_attributes(sheet_stroke(kind)) + " d=\"" + path + "\"/>\n";
    }
    h += "</g>\n<g class=\"pierces\" fill=\"none\" stroke=\"" + std::string(kSvgPierceColor) +
         "\" stroke-width=\"0.2\">\n";
    for (const Point& p : d.pierces) {
        const Point c = d.to_paper(p);
        h +=
            "<circle cx=\"" + paper(c.x) + "\" cy=\"" + paper(c.y) + "\" r=\"" + paper(kSheetPierceRadiusMm) + "\"/>\n";
    }
    h += "</g>\n";
    for (const SheetDrawing::Mark& m : d.marks) h += mark_shape(d.to_paper(m.at), m.severity) + "\n";
    for (const SheetDrawing::Label& l : d.labels) h += label_text(d.to_paper(l.at), l.text) + "\n";
    h += "</svg>\n";
}

// A legend entry's sample: 8 x 3 mm.
std::string legend_sample(const SheetLegendEntry& e) {
    std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"8mm\" height=\"3mm\" viewBox=\"0 0 8 3\">";
    switch (e.sample) {
        case SheetLegendEntry::Sample::Stroke:
            s += "<path d=\"M0.5 1.5H7.5\" fill=\"none\" " + stroke_attributes(sheet_stroke(e.kind)) + "/>";
            break;
        case SheetLegendEntry::Sample::Pierce:
            s += "<circle cx=\"4\" cy=\"1.5\" r=\"" + paper(kSheetPierceRadiusMm) + "\" fill=\"none\" stroke=\"" +
                 std::string(kSvgPierceColor) + "\" stroke-width=\"0.2\"/>";
            break;
        case SheetLegendEntry::Sample::Mark: s += mark_shape({4, 1.5}, e.severity); break;
        case SheetLegendEntry::Sample::Label: s += label_text({4, 1.5}, "1"); break;
    }
    return s + "</svg>";
}

}  // namespace

const std::string& job_sheet_css() {
    static const std::string css = [] {
        std::string c = kBaseCss;
        for (const Severity sev : {Severity::Error, Severity::Warning, Severity::Note})
            c += "tr." + std::string(severity_name(sev)) +
                 " td.severity { color: " + std::string(sheet_mark_color(sev)) + "; }\n";
        return c;
    }();
    return css;
}

std::string job_sheet_html(const JobSheet& sheet) {
    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"" + std::string(lang_code(sheet.lang)) +
         "\">\n<head>\n<meta charset=\"utf-8\"/>\n";
    h += "<meta name=\"generator\" content=\"essi report\"/>\n<title>" + esc(sheet.title + ": " + sheet.tape) +
         "</title>\n";
    h += "<style>" + job_sheet_css() + "</style>\n</head>\n<body>\n";
    h += "<header>\n<h1>" + esc(sheet.title) + "</h1>\n<p class=\"tape\">" + esc(sheet.tape) + "</p>\n</header>\n";
    for (const SheetSection& s : sheet.sections) {
        h += "<section id=\"" + s.id + "\"" + (s.drawing ? " class=\"drawing\"" : "") + ">\n<h2>" + esc(s.title) +
             "</h2>\n";
        if (!s.fields.empty()) write_fields(h, s);
        if (s.table) write_table(h, *s.table);
        if (s.drawing) {
            write_drawing(h, sheet.drawing);
            h += "<ul class=\"legend\">\n";
            for (const SheetLegendEntry& e : sheet.legend) h += "<li>" + legend_sample(e) + esc(e.text) + "</li>\n";
            h += "</ul>\n";
        }
        if (!s.note.empty()) h += "<p class=\"note\">" + esc(s.note) + "</p>\n";
        h += "</section>\n";
    }
    h += "<footer>" + esc(sheet.footer) + "</footer>\n</body>\n</html>\n";
    return h;
}

}  // namespace essi
