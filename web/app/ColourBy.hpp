// Colour by: the cuts and marks drawn in the colour of a value of theirs instead of their kind's: the feed they are
// cut at, or their cut's place in the cutting order (the pierces before it). The values go into kColourBins bins,
// the colours of render/Palette.hpp's ramp from low to high; the legend says what each colour stands for. Rapids and
// travel keep their kind's colour. docs/viewer.md, "Colour by".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/Document.hpp"
#include "essi/i18n.hpp"

namespace essi::viewer {

enum class ColourBy : std::uint8_t { Kind, Feed, CutOrder };
inline constexpr ColourBy kColourByModes[] = {ColourBy::Kind, ColourBy::Feed, ColourBy::CutOrder};

// Its name in the page's API and the settings ("kind", "feed", "order"); from a name, none for another word.
[[nodiscard]] std::string_view colour_by_name(ColourBy by);
[[nodiscard]] std::optional<ColourBy> colour_by_named(std::string_view name);
// Its name in the panels, in the UI's language.
[[nodiscard]] Msg colour_by_label(ColourBy by);

// A line of the legend: the bins it stands for (their colours) and what they mean.
struct ColourLegendEntry {
    std::uint8_t first_bin = 0, last_bin = 0;
    std::string text;
};

// The bins of one document's motions, in stream order (PathBuffers asks motion after motion), and the legend.
class ColourBins {
public:
    ColourBins(const Document& doc, ColourBy by);
    // The bin of motion i (asked in increasing order) when it is drawn by its value, else none (its kind's colour).
    [[nodiscard]] std::optional<std::uint8_t> bin(std::size_t i);
    [[nodiscard]] std::vector<ColourLegendEntry> legend(Lang lang) const;

private:
    [[nodiscard]] std::uint8_t feed_bin(float feed) const;
    [[nodiscard]] std::uint8_t order_bin(std::size_t cut) const;

    const Document& doc_;
    ColourBy by_;
    std::vector<float> feeds_;   // the distinct feeds of the feeds table, ascending (up to kColourBins of them)
    float low_ = 0, high_ = 0;   // the feeds' range (more distinct feeds than bins: binned linearly)
    std::size_t feed_at_ = 0;    // the feeds table's entry in force at the motion asked last
    std::size_t pierce_at_ = 0;  // the pierces at or before the motion asked last
};

}  // namespace essi::viewer
