// `essi render`'s SVG (core/draw/render_svg.cpp): layers, the legend, the pierces; and a view of a part of the
// tape (the viewer's Export: the view as SVG).
#include <gtest/gtest.h>

#include <string>

#include "essi/profile.hpp"
#include "essi/render_svg.hpp"

TEST(Render, LegendAndLayers) {
    const std::string tape = "39+3000\n+0+1000\n7\n+1000+0\n+0+1000+0+500-\n8\n+5+5\n63\n";
    essi::RenderOptions o;
    o.title = "t<1>.esi";
    const auto r = essi::render_svg(tape, *essi::builtin_profile("iso6582"), o);
    EXPECT_NE(r.svg.find("id=\"cut\""), std::string::npos);
    EXPECT_NE(r.svg.find(std::string(essi::kSvgCutColor)), std::string::npos);
    EXPECT_NE(r.svg.find("class=\"pierce\""), std::string::npos);
    EXPECT_NE(r.svg.find("t&lt;1&gt;.esi"), std::string::npos);
    EXPECT_NE(r.svg.find("data-pierces=\"" + std::to_string(r.result.stats.pierces) + "\""), std::string::npos);
}

TEST(Render, AViewIsThatBoxOfTheDrawing) {
    const std::string tape = "7\n+1000+0\n+0+1000\n8\n5\n+5000+0\n6\n7\n+1000+0\n8\n64\n";
    essi::RenderOptions o;
    o.view = essi::Box::of({-10, -10}, {120, 110});  // the first square's corner, not the line 500 mm away
    const auto r = essi::render_svg(tape, *essi::builtin_profile("iso6582"), o);
    EXPECT_NE(r.svg.find("viewBox=\"-10 -110 130 "), std::string::npos) << r.svg.substr(0, 400);
    EXPECT_NE(r.svg.find("data-view=\"-10 -10 120 110\""), std::string::npos);
}
