// DXF of a tape (essi/dxf.hpp): the entities and their group codes.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "essi/dxf.hpp"

using namespace essi;

namespace {
// The (code, value) pairs of the ENTITIES section.
std::vector<std::pair<int, std::string>> entities(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::pair<int, std::string>> all;
    std::string code, value;
    while (std::getline(in, code) && std::getline(in, value)) all.emplace_back(std::stoi(code), value);
    std::vector<std::pair<int, std::string>> out;
    bool inside = false;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (all[i] == std::pair<int, std::string>{2, "ENTITIES"}) inside = true;
        else if (inside && all[i] == std::pair<int, std::string>{0, "ENDSEC"}) break;
        else if (inside) out.push_back(all[i]);
    }
    return out;
}
std::string value_after(const std::vector<std::pair<int, std::string>>& e, std::size_t from, int code) {
    for (std::size_t i = from; i < e.size(); ++i)
        if (e[i].first == code) return e[i].second;
    return {};
}
}  // namespace

TEST(Dxf, LinesArcsAndLayers) {
    TapeSetup s;
    s.profile = *builtin_profile("iso6582");
    // a travel line, then cut: a line, a clockwise quarter arc, a full circle
    const DxfResult r = render_dxf("+100+0\n7\n+1000+0\n+500-500+0-500-\n+0+0+100+0+\n8\n64\n", s);
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_EQ(r.text.rfind("0\nEOF\n"), r.text.size() - 6);
    const auto e = entities(r.text);
    std::vector<std::size_t> starts;
    for (std::size_t i = 0; i < e.size(); ++i)
        if (e[i].first == 0) starts.push_back(i);
    ASSERT_EQ(starts.size(), 5u);  // LINE, LINE, ARC, ARC, ARC
    EXPECT_EQ(e[starts[0]].second, "LINE");
    EXPECT_EQ(value_after(e, starts[0], 8), "TRAVEL");
    EXPECT_EQ(value_after(e, starts[1], 8), "CUT");
    EXPECT_EQ(e[starts[2]].second, "ARC");
    // the clockwise quarter from (110, 0) to (160, -50) around (110, -50): written from its end (0 deg) to its start
    // (90)
    EXPECT_EQ(value_after(e, starts[2], 10), "110.000000");
    EXPECT_EQ(value_after(e, starts[2], 20), "-50.000000");
    EXPECT_EQ(value_after(e, starts[2], 40), "50.000000");
    EXPECT_EQ(value_after(e, starts[2], 50), "0.000000");
    EXPECT_EQ(value_after(e, starts[2], 51), "90.000000");
    // the full circle: two half arcs
    EXPECT_EQ(value_after(e, starts[3], 50), "180.000000");
    EXPECT_EQ(value_after(e, starts[3], 51), "0.000000");
    EXPECT_EQ(value_after(e, starts[4], 50), "0.000000");
    EXPECT_EQ(value_after(e, starts[4], 51), "180.000000");
}

TEST(Dxf, DiagnosticsAndTorches) {
    TapeSetup s;
    s.profile = *builtin_profile("woyda");
    const DxfResult r = render_dxf("135+2\n136+1000\n7\n+100+0\n8\n99\n63\n", s);
    const auto e = entities(r.text);
    std::size_t cut_lines = 0, texts = 0;
    for (std::size_t i = 0; i < e.size(); ++i) {
        if (e[i] == std::pair<int, std::string>{0, "LINE"} && value_after(e, i, 8) == "CUT") ++cut_lines;
        if (e[i] == std::pair<int, std::string>{0, "TEXT"}) {
            ++texts;
            EXPECT_EQ(value_after(e, i, 1), "W201 line 6");
        }
    }
    EXPECT_EQ(cut_lines, 2u);  // one a torch
    EXPECT_EQ(texts, 1u);
}
