// Where diagnostics are drawn (essi/diagnostic_marks.hpp) and how `essi render`'s SVG draws them
// (core/draw/render_svg.cpp): a mark per diagnostic at its place, a constant size in the SVG's pixels, notes too,
// the contour concerned, the related places, a collision's overlapping area and the problems-only view.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "essi/diagnostic_marks.hpp"
#include "essi/profile.hpp"
#include "essi/render_svg.hpp"

namespace {

// 1: 7 (torch on), 2: cut to (100, 0), 3: cut to (100, 100), 4: 8 (off), 5: travel to (150, 100), 6: end.
const std::string kTape = "7\n+1000+0\n+0+1000\n8\n+500+0\n64\n";

essi::Diagnostic diag(essi::Severity s, std::uint32_t line, std::string message = "a problem") {
    essi::Diagnostic d;
    d.severity = s;
    d.code = essi::DiagCode::E605_PartsCollide;
    d.line = line;
    d.column = 1;
    d.set_text(std::move(message));
    return d;
}

std::string render(std::vector<essi::Diagnostic> ds, bool problems_only = false, double width = 1200) {
    essi::RenderOptions o;
    o.title = "t.esi";
    o.width_px = width;
    o.diagnostics = std::move(ds);
    o.problems_only = problems_only;
    return essi::render_svg(kTape, *essi::builtin_profile("iso6582"), o).svg;
}

// The element whose attributes contain `key` (its opening tag).
std::string element_with(const std::string& svg, const std::string& key) {
    const auto at = svg.find(key);
    if (at == std::string::npos) return "";
    const auto open = svg.rfind('<', at);
    return svg.substr(open, svg.find('>', at) - open + 1);
}

std::string attr(const std::string& element, const std::string& name) {
    const std::regex re(" " + name + "=\"([^\"]*)\"");
    std::smatch m;
    return std::regex_search(element, m, re) ? m[1].str() : "";
}

}  // namespace

TEST(DiagnosticMarks, PlaceIsAtThenTheLinesFirstMotionEndThenTheMachinePosition) {
    std::vector<essi::Diagnostic> ds = {diag(essi::Severity::Error, 3), diag(essi::Severity::Warning, 4),
                                        diag(essi::Severity::Note, 1),  diag(essi::Severity::Error, 0),
                                        diag(essi::Severity::Error, 6), diag(essi::Severity::Error, 2)};
    ds[5].has_at = true;
    ds[5].at = {42, 7};
    essi::DiagnosticPlaces places(ds);
    places.motion(2, {100, 0});
    places.motion(3, {100, 100});
    places.motion(5, {150, 100});
    const auto p = places.places();
    ASSERT_EQ(p.size(), ds.size());
    EXPECT_EQ(p[0], (essi::Point{100, 100}));  // the end of line 3's motion
    EXPECT_EQ(p[1], (essi::Point{100, 100}));  // a function: where the machine is
    EXPECT_FALSE(p[2].has_value());            // before any motion
    EXPECT_FALSE(p[3].has_value());            // no line
    EXPECT_EQ(p[4], (essi::Point{150, 100}));  // after the last motion
    EXPECT_EQ(p[5], (essi::Point{42, 7}));     // its own point
}

TEST(DiagnosticMarks, OverlapSpansAreInsideEveryPolygon) {
    const std::vector<essi::Point> a = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    const std::vector<essi::Point> b = {{5, 0}, {15, 0}, {15, 10}, {5, 10}};
    // A U open at the top: inside for x in [0, 2] and [8, 10] at y = 5.
    const std::vector<essi::Point> u = {{0, 0}, {10, 0}, {10, 10}, {8, 10}, {8, 2}, {2, 2}, {2, 10}, {0, 10}};
    using Spans = std::vector<std::pair<double, double>>;
    EXPECT_EQ(essi::overlap_spans({a, b}, 5), (Spans{{5, 10}}));
    EXPECT_EQ(essi::overlap_spans({u, b}, 5), (Spans{{8, 10}}));
    EXPECT_EQ(essi::overlap_spans({u, a}, 5), (Spans{{0, 2}, {8, 10}}));
    EXPECT_TRUE(essi::overlap_spans({a, b}, 11).empty());
    EXPECT_TRUE(essi::overlap_spans({}, 5).empty());
}

TEST(DiagnosticMarks, RangesMerge) {
    using R = std::vector<essi::LineRange>;
    EXPECT_EQ(essi::merge_ranges({{5, 9}, {1, 2}, {3, 3}, {8, 12}, {20, 20}}), (R{{1, 3}, {5, 12}, {20, 20}}));
    essi::Diagnostic d = diag(essi::Severity::Error, 7);
    d.contour_first = 2;
    d.contour_last = 9;
    d.add_related({12, 15, essi::Msg::None, {}});
    EXPECT_EQ(essi::concerned_lines(d), (R{{7, 7}, {2, 9}}));
    EXPECT_EQ(essi::related_lines(d), (R{{12, 15}}));
}

TEST(RenderMarks, AMarkPerDiagnosticAtItsPlaceInItsColourNotesToo) {
    const std::string svg = render(
        {diag(essi::Severity::Error, 3, "bad <arc>"), diag(essi::Severity::Warning, 4), diag(essi::Severity::Note, 5)});
    const std::string e = element_with(svg, "id=\"diagnostic-0\"");
    EXPECT_EQ(attr(e, "class"), "diagnostic error");
    EXPECT_EQ(attr(e, "data-line"), "3");
    EXPECT_EQ(attr(e, "data-x") + "," + attr(e, "data-y"), "100,100");
    EXPECT_EQ(attr(e, "stroke"), std::string(essi::kSvgErrorColor));
    EXPECT_NE(svg.find("<title>t.esi:3:1: error E605: bad &lt;arc&gt;</title>"), std::string::npos);
    EXPECT_EQ(attr(element_with(svg, "id=\"diagnostic-1\""), "class"), "diagnostic warning");
    const std::string n = element_with(svg, "id=\"diagnostic-2\"");
    EXPECT_EQ(attr(n, "class"), "diagnostic note");
    EXPECT_EQ(attr(n, "stroke"), std::string(essi::kSvgNoteColor));
    EXPECT_EQ(attr(n, "data-x") + "," + attr(n, "data-y"), "150,100");
    EXPECT_NE(svg.find("data-kind=\"note\""), std::string::npos);  // (the legend's key)
}

TEST(RenderMarks, TheMarkHasTheSameSizeInTheSvgsPixelsAtEveryWidth) {
    for (const double width : {400.0, 1200.0, 3000.0}) {
        const std::string svg = render({diag(essi::Severity::Error, 3)}, false, width);
        double vx = 0, vy = 0, vw = 0, vh = 0;
        ASSERT_EQ(
            std::sscanf(attr(element_with(svg, "viewBox="), "viewBox").c_str(), "%lf %lf %lf %lf", &vx, &vy, &vw, &vh),
            4);
        const std::string mark = svg.substr(svg.find("id=\"diagnostic-0\""));
        const double r = std::stod(attr(element_with(mark, "<circle"), "r"));
        EXPECT_NEAR(r * width / vw, essi::kSvgMarkRadiusPx, 0.01) << width;
    }
}

TEST(RenderMarks, ContourRelatedPlacesAndTheOverlapIntersection) {
    essi::Diagnostic d = diag(essi::Severity::Error, 3, "parts collide");
    d.contour_first = 2;
    d.contour_last = 3;
    d.add_related({5, 5, essi::Msg::RelatedOtherPart, {}});
    d.set_overlap({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 5}, {15, 5}, {15, 15}, {5, 15}}});
    const std::string svg = render({d});
    const std::string contour = element_with(svg, "class=\"contour-highlight\"");
    EXPECT_EQ(attr(contour, "data-lines"), "2-3");
    EXPECT_EQ(attr(contour, "data-diagnostic"), "0");
    EXPECT_EQ(attr(contour, "d"), "M0 0L100 0M100 0L100 -100");  // lines 2 and 3, y flipped
    const std::string related = element_with(svg, "class=\"related\"");
    EXPECT_EQ(attr(related, "data-lines"), "5-5");
    EXPECT_EQ(attr(related, "d"), "M100 -100L150 -100");
    EXPECT_NE(svg.find("the other part</title></path>"), std::string::npos);
    EXPECT_NE(svg.find("\n  the other part</title>"), std::string::npos);  // (the mark's tooltip lists it)
    // The overlap: the first polygon filled, clipped by the second.
    const std::string clip = svg.substr(svg.find("<clipPath id=\"overlap-0-1\""));
    EXPECT_EQ(attr(element_with(clip, "<path"), "d"), "M5 -5L15 -5L15 -15L5 -15Z");
    EXPECT_EQ(attr(element_with(svg, "class=\"overlap\""), "data-polygons"), "2");
    const std::string area_group = svg.substr(svg.find("class=\"overlap\""));
    EXPECT_LT(area_group.find("clip-path=\"url(#overlap-0-1)\""), area_group.find("class=\"overlap-area\""));
    const std::string area = element_with(svg, "class=\"overlap-area\"");
    EXPECT_EQ(attr(area, "d"), "M0 0L10 0L10 -10L0 -10Z");
    EXPECT_EQ(attr(area, "fill"), std::string(essi::kSvgErrorColor));
}

TEST(RenderMarks, ProblemsOnlyDimsTheDrawingAndDrawsWhatIsConcerned) {
    essi::Diagnostic d = diag(essi::Severity::Warning, 3);
    EXPECT_EQ(render({d}).find("class=\"dimmed\""), std::string::npos);
    const std::string svg = render({d}, true);
    EXPECT_EQ(attr(element_with(svg, "id=\"drawing\""), "opacity"), "0.2");
    const std::string cut = element_with(svg, "class=\"concerned cut\"");
    EXPECT_EQ(attr(cut, "d"), "M100 0L100 -100");  // line 3 only
    EXPECT_EQ(element_with(svg, "class=\"concerned travel\""), "");
}

TEST(RenderMarks, AnExampleTapesErrorIsMarkedAtTheEndOfItsMotion) {
    // bad_arc_off_circle.esi: the arc of line 12 ends off its circle, at (100, 100) mm.
    const std::string tape = "39+500\n+500+500\n7\n+1000+0\n+500+500+0+550+\n8\n63\n";
    essi::RenderOptions o;
    const auto r = essi::render_svg(tape, *essi::builtin_profile("iso6582"), o);
    ASSERT_FALSE(r.result.diagnostics.empty());
    const std::string e = element_with(r.svg, "id=\"diagnostic-0\"");
    EXPECT_EQ(attr(e, "data-code"), "E301");
    EXPECT_EQ(attr(e, "data-line"), "5");
    EXPECT_EQ(attr(e, "data-x") + "," + attr(e, "data-y"), "200,100");
}

// The viewer's document (web/app/Document.cpp) places its diagnostics by the same rule once the tape is checked:
// a mark per diagnostic with a place, and the motions they concern.
#include "viewer_util.hpp"

TEST(ViewerMarks, TheDocumentPlacesItsDiagnosticsAsTheSvgDoes) {
    // 1: 7, 2: cut to (100, 0), 3: an arc from (100, 0) about (100, 50) ending off its circle, 4: cut, 5: 8, 6: end.
    const std::string tape = "7\n+1000+0\n+500+500+0+550+\n+0+1000\n8\n64\n";
    const auto doc = essi_test::load_document(tape);
    ASSERT_FALSE(doc->diagnostics.empty());
    const essi::Diagnostic& d = doc->diagnostics.front();
    EXPECT_EQ(d.code, essi::DiagCode::E301_ArcEndNotOnCircle);
    ASSERT_EQ(doc->marks.size(), doc->diagnostics.size());
    EXPECT_EQ(doc->marks.front().diagnostic, 0u);
    const auto [a, b] = doc->motions_of_line(d.line);
    ASSERT_LT(a, b);
    EXPECT_EQ(doc->marks.front().at, doc->end_of(a));
    // The same place as `essi render`'s mark.
    essi::RenderOptions o;
    const std::string svg = essi::render_svg(tape, *essi::builtin_profile("iso6582"), o).svg;
    const std::string mark = element_with(svg, "id=\"diagnostic-0\"");
    EXPECT_EQ(std::stod(attr(mark, "data-x")), doc->marks.front().at.x);
    EXPECT_EQ(std::stod(attr(mark, "data-y")), doc->marks.front().at.y);
    // The motions it concerns: its block's.
    ASSERT_FALSE(doc->concerned_motions.empty());
    EXPECT_LE(doc->concerned_motions.front().first, a);
    EXPECT_GE(doc->concerned_motions.front().second, b);
    const auto [la, lb] = doc->motions_of_lines({d.line, d.line});
    EXPECT_EQ(la, a);
    EXPECT_EQ(lb, b);
}
