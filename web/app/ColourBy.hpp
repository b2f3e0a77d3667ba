// Colour by: the cuts and marks drawn in the colour of a value of theirs instead of their kind's: the feed they are
// cut at, their cut's place in the cutting order (the pierces before it), the group of the part they cut
// (essi/parts.hpp), or the highest speed the machine reaches on them (the machine-time planner's, with the profile's
// accel_mm_s2; without one, their feed). The values go into kColourBins bins, the colours of render/Palette.hpp's
// ramp; the legend says what each colour stands for. Rapids, travel and cuts of no part keep their kind's colour.
// docs/viewer.md, "Colour by".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/Document.hpp"
#include "essi/i18n.hpp"
#include "essi/machine_time.hpp"
#include "essi/parts.hpp"

namespace essi::viewer {

enum class ColourBy : std::uint8_t { Kind, Feed, CutOrder, PartGroup, Speed };
inline constexpr ColourBy kColourByModes[] = {ColourBy::Kind, ColourBy::Feed, ColourBy::CutOrder, ColourBy::PartGroup,
                                              ColourBy::Speed};

// Its name in the page's API and the settings ("kind", "feed", "order", "group", "speed"); from a name, none for
// another word.
[[nodiscard]] std::string_view colour_by_name(ColourBy by);
[[nodiscard]] std::optional<ColourBy> colour_by_named(std::string_view name);
// Its name in the panels, in the UI's language.
[[nodiscard]] Msg colour_by_label(ColourBy by);

// What colour by part group and by speed need of the open tape beyond its document; asked only in those modes.
class ColourSources {
public:
    virtual ~ColourSources() = default;
    [[nodiscard]] virtual const PartsList* parts() const = 0;
    [[nodiscard]] virtual const std::vector<PlannedMotion>* planned() const = 0;
};

// A line of the legend: the bins it stands for (their colours) and what they mean.
struct ColourLegendEntry {
    std::uint8_t first_bin = 0, last_bin = 0;
    std::string text;
};

// The bins of one document's motions, in stream order (PathBuffers asks motion after motion), and the legend.
class ColourBins {
public:
    ColourBins(const Document& doc, ColourBy by, const ColourSources* sources = nullptr);
    // The bin of motion i (asked in increasing order) when it is drawn by its value, else none (its kind's colour).
    [[nodiscard]] std::optional<std::uint8_t> bin(std::size_t i);
    [[nodiscard]] std::vector<ColourLegendEntry> legend(Lang lang) const;

private:
    // A run of source lines and the value its motions are coloured by (a part's cut and its group; a line and the
    // highest speed planned on it).
    struct LineValue {
        std::uint32_t first_line = 0, last_line = 0;
        float value = 0;
    };
    void take_feeds();
    void take_groups(const PartsList& parts);
    void take_speeds(const std::vector<PlannedMotion>& planned);
    void take_range(std::vector<float> values);
    [[nodiscard]] std::optional<float> line_value(std::uint32_t line) const;
    [[nodiscard]] std::uint8_t value_bin(float value) const;
    [[nodiscard]] std::uint8_t order_bin(std::size_t cut) const;
    [[nodiscard]] static std::uint8_t group_bin(unsigned group);

    const Document& doc_;
    ColourBy by_;
    bool by_line_ = false;                // the value of a motion is its line's (lines_): part group, planned speed
    std::vector<LineValue> lines_;        // by first_line, not overlapping
    std::vector<float> values_;           // the distinct values drawn, ascending (up to kColourBins of them)
    float low_ = 0, high_ = 0;            // the values' range (more distinct values than bins: binned linearly)
    std::vector<unsigned> group_counts_;  // by group number - 1: its parts
    std::size_t feed_at_ = 0;             // the feeds table's entry in force at the motion asked last
    std::size_t pierce_at_ = 0;           // the pierces at or before the motion asked last
};

}  // namespace essi::viewer
