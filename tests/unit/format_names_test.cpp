// The formats' names both ways (essi/read.hpp, essi/write.hpp, essi/dialect.hpp): every edge (the CLI, the
// server, the viewer, the Python module, share links) reads a format's name with these.
#include <gtest/gtest.h>

#include <optional>
#include <string_view>

#include "essi/dialect.hpp"
#include "essi/read.hpp"
#include "essi/write.hpp"

using namespace essi;

TEST(FormatNames, InputFormatsReadBackFromTheirNames) {
    EXPECT_STREQ(input_format_name(InputFormat::Essi), "essi");
    EXPECT_STREQ(input_format_name(InputFormat::Eia), "eia");
    EXPECT_EQ(parse_input_format("essi"), InputFormat::Essi);
    EXPECT_EQ(parse_input_format("eia"), InputFormat::Eia);
    for (const InputFormat f : kInputFormats) EXPECT_EQ(parse_input_format(input_format_name(f)), f);
}

TEST(FormatNames, InputFormatRefusesOtherText) {
    for (const std::string_view text : {"", "auto", "EIA", "Essi", "gcode", "eia ", "es"})
        EXPECT_EQ(parse_input_format(text), std::nullopt) << text;
}

TEST(FormatNames, OutputFormatsReadBackFromTheirNames) {
    EXPECT_STREQ(output_format_name(OutputFormat::Essi), "essi");
    EXPECT_STREQ(output_format_name(OutputFormat::Eia), "eia");
    EXPECT_STREQ(output_format_name(OutputFormat::Gcode), "gcode");
    EXPECT_EQ(parse_output_format("essi"), OutputFormat::Essi);
    EXPECT_EQ(parse_output_format("eia"), OutputFormat::Eia);
    EXPECT_EQ(parse_output_format("gcode"), OutputFormat::Gcode);
    for (const OutputFormat f : kOutputFormats) EXPECT_EQ(parse_output_format(output_format_name(f)), f);
}

TEST(FormatNames, OutputFormatRefusesOtherText) {
    for (const std::string_view text : {"", "auto", "G-code", "GCODE", "ngc", "dxf", "gcode\n"})
        EXPECT_EQ(parse_output_format(text), std::nullopt) << text;
}

TEST(FormatNames, InputChoiceIsANameOrAuto) {
    std::optional<InputFormat> format = InputFormat::Essi;
    EXPECT_TRUE(parse_input_choice("eia", format));
    EXPECT_EQ(format, InputFormat::Eia);
    EXPECT_TRUE(parse_input_choice("auto", format));
    EXPECT_EQ(format, std::nullopt);
    format = InputFormat::Eia;
    EXPECT_TRUE(parse_input_choice("", format));
    EXPECT_EQ(format, std::nullopt);
    format = InputFormat::Eia;
    EXPECT_FALSE(parse_input_choice("gcode", format));
    EXPECT_EQ(format, InputFormat::Eia);  // (unchanged)
    EXPECT_FALSE(parse_input_choice("AUTO", format));
}
