#include "app/ColourBy.hpp"

#include <algorithm>
#include <cmath>

#include "app/Format.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

std::string_view colour_by_name(ColourBy by) {
    switch (by) {
        case ColourBy::Kind: return "kind";
        case ColourBy::Feed: return "feed";
        case ColourBy::CutOrder: return "order";
        case ColourBy::PartGroup: return "group";
        case ColourBy::Speed: return "speed";
    }
    return "kind";
}

std::optional<ColourBy> colour_by_named(std::string_view name) {
    for (const ColourBy by : kColourByModes)
        if (colour_by_name(by) == name) return by;
    return std::nullopt;
}

Msg colour_by_label(ColourBy by) {
    switch (by) {
        case ColourBy::Kind: return Msg::UiColourByKind;
        case ColourBy::Feed: return Msg::UiColourByFeed;
        case ColourBy::CutOrder: return Msg::UiColourByOrder;
        case ColourBy::PartGroup: return Msg::UiColourByGroup;
        case ColourBy::Speed: return Msg::UiColourBySpeed;
    }
    return Msg::UiColourByKind;
}

namespace {

// A motion coloured by its feed: a cut or a mark at a programmed feed.
bool drawn_by_value(const Motion& m) {
    return (m.kind == MotionKind::Cut || m.kind == MotionKind::Mark) && !(m.flags & Motion::kFlagRapidFeed);
}

bool cuts_or_marks(MotionKind k) { return k == MotionKind::Cut || k == MotionKind::Mark; }

// Consecutive groups this many bins apart on the ramp (coprime with kColourBins: the first kColourBins groups
// take every colour once), so that neighbours in the cutting order do not look alike.
constexpr unsigned kGroupBinStride = 7;
static_assert(kColourBins % kGroupBinStride != 0);

// The groups a legend names one by one; past that, each colour lists the first of its groups.
constexpr std::size_t kLegendGroupsListed = 3;

}  // namespace

ColourBins::ColourBins(const Document& doc, ColourBy by, const ColourSources* sources) : doc_(doc), by_(by) {
    const PartsList* parts = sources && by == ColourBy::PartGroup ? sources->parts() : nullptr;
    const std::vector<PlannedMotion>* planned = sources && by == ColourBy::Speed ? sources->planned() : nullptr;
    if (parts) take_groups(*parts);
    else if (planned && !planned->empty()) take_speeds(*planned);
    else if (by == ColourBy::Feed || by == ColourBy::Speed) take_feeds();  // (speed without a planner: the feed)
}

// The feeds some cut or mark is made at (a feed in force over travel only is not drawn in a bin's colour).
void ColourBins::take_feeds() {
    std::vector<float> all;
    for (std::size_t k = 0; k < doc_.feeds.size(); ++k) {
        const auto [first, feed] = doc_.feeds[k];
        const std::size_t end = k + 1 < doc_.feeds.size() ? doc_.feeds[k + 1].first : doc_.motions.size();
        if (!(feed > 0)) continue;
        for (std::size_t i = first; i < end; ++i) {
            if (!drawn_by_value(doc_.motions[i])) continue;
            all.push_back(feed);
            break;
        }
    }
    take_range(std::move(all));
}

// Each cut of a part: its lines and its part's group.
void ColourBins::take_groups(const PartsList& parts) {
    by_line_ = true;
    for (const Part& p : parts.parts)
        for (const PartCut& c : p.cuts) lines_.push_back({c.first_line, c.last_line, static_cast<float>(p.group)});
    std::sort(lines_.begin(), lines_.end(),
              [](const LineValue& a, const LineValue& b) { return a.first_line < b.first_line; });
    for (const PartGroup& g : parts.groups) group_counts_.push_back(g.count);
}

// Each line that cuts or marks: the highest speed planned on it (mm/min, whole).
void ColourBins::take_speeds(const std::vector<PlannedMotion>& planned) {
    by_line_ = true;
    for (const PlannedMotion& p : planned)
        if (cuts_or_marks(p.kind)) lines_.push_back({p.line, p.line, std::round(p.peak_mm_min)});
    std::sort(lines_.begin(), lines_.end(), [](const LineValue& a, const LineValue& b) {
        return a.first_line < b.first_line || (a.first_line == b.first_line && a.value > b.value);
    });
    lines_.erase(std::unique(lines_.begin(), lines_.end(),
                             [](const LineValue& a, const LineValue& b) { return a.first_line == b.first_line; }),
                 lines_.end());  // (the highest of a line's)
    std::vector<float> all;
    all.reserve(lines_.size());
    for (const LineValue& l : lines_) all.push_back(l.value);
    take_range(std::move(all));
}

// The values drawn: their range, and the values themselves when there are no more than bins.
void ColourBins::take_range(std::vector<float> all) {
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (all.empty()) return;
    low_ = all.front();
    high_ = all.back();
    if (all.size() <= kColourBins) values_ = std::move(all);
}

std::optional<float> ColourBins::line_value(std::uint32_t line) const {
    auto it = std::upper_bound(lines_.begin(), lines_.end(), line,
                               [](std::uint32_t l, const LineValue& v) { return l < v.first_line; });
    if (it == lines_.begin()) return std::nullopt;
    --it;
    if (line > it->last_line) return std::nullopt;
    return it->value;
}

// A value's bin: its place among the distinct values spread over the ramp, or its place in the range.
std::uint8_t ColourBins::value_bin(float value) const {
    constexpr double last = kColourBins - 1;
    if (!values_.empty()) {
        const auto k = static_cast<double>(std::lower_bound(values_.begin(), values_.end(), value) - values_.begin());
        return static_cast<std::uint8_t>(
            values_.size() == 1 ? last / 2 : std::lround(k * last / static_cast<double>(values_.size() - 1)));
    }
    if (!(high_ > low_)) return static_cast<std::uint8_t>(last / 2);
    const double t = std::clamp((value - low_) / static_cast<double>(high_ - low_), 0.0, 1.0);
    return static_cast<std::uint8_t>(std::min(last, std::floor(t * kColourBins)));
}

// The bin of the cut-th cut (1: the first pierce's) of the tape's cuts.
std::uint8_t ColourBins::order_bin(std::size_t cut) const {
    const std::size_t cuts = doc_.pierces.size();
    if (cuts <= 1 || cut == 0) return 0;
    return static_cast<std::uint8_t>((cut - 1) * (kColourBins - 1) / (cuts - 1));
}

std::uint8_t ColourBins::group_bin(unsigned group) {
    return static_cast<std::uint8_t>(((group - 1) * kGroupBinStride) % kColourBins);
}

std::optional<std::uint8_t> ColourBins::bin(std::size_t i) {
    const Motion& m = doc_.motions[i];
    if (by_ == ColourBy::Kind || !cuts_or_marks(m.kind)) return std::nullopt;
    if (by_line_) {
        const std::optional<float> v = line_value(m.line);
        if (!v) return std::nullopt;
        return by_ == ColourBy::PartGroup ? group_bin(static_cast<unsigned>(*v)) : value_bin(*v);
    }
    if (by_ == ColourBy::Feed || by_ == ColourBy::Speed) {
        if (!drawn_by_value(m)) return std::nullopt;
        while (feed_at_ + 1 < doc_.feeds.size() && doc_.feeds[feed_at_ + 1].first <= i) ++feed_at_;
        if (doc_.feeds.empty() || doc_.feeds[feed_at_].first > i || !(doc_.feeds[feed_at_].second > 0))
            return std::nullopt;
        return value_bin(doc_.feeds[feed_at_].second);
    }
    if (by_ == ColourBy::PartGroup) return std::nullopt;  // (no parts list)
    while (pierce_at_ < doc_.pierces.size() && doc_.pierces[pierce_at_] <= i) ++pierce_at_;
    return order_bin(pierce_at_);
}

std::vector<ColourLegendEntry> ColourBins::legend(Lang lang) const {
    std::vector<ColourLegendEntry> out;
    if (by_ == ColourBy::PartGroup) {
        // A colour per group while there are no more groups than colours; else each colour and its first groups.
        const std::string word = format_message(Msg::SheetPartGroup, lang, {});
        const std::size_t groups = group_counts_.size();
        for (std::size_t b = 0; b < std::min<std::size_t>(groups, kColourBins); ++b) {
            const std::uint8_t bin = group_bin(static_cast<unsigned>(b + 1));
            std::string text = word + " " + std::to_string(b + 1);
            if (groups <= kColourBins) {
                text += fmt(" (%u\u00d7)", group_counts_[b]);
            } else {
                for (std::size_t k = 1; k < kLegendGroupsListed; ++k)
                    if (b + 1 + k * kColourBins <= groups) text += ", " + std::to_string(b + 1 + k * kColourBins);
                if (b + 1 + kLegendGroupsListed * kColourBins <= groups) text += ", ...";
            }
            out.push_back({bin, bin, text});
        }
        return out;
    }
    if (by_ == ColourBy::Feed || by_ == ColourBy::Speed) {
        const auto speed_text = [](double f) { return fmt("%.0f mm/min", f); };
        if (!values_.empty()) {
            for (const float v : values_) {
                const std::uint8_t b = value_bin(v);
                out.push_back({b, b, speed_text(v)});
            }
        } else if (high_ > low_) {
            const double step = (high_ - low_) / kColourBins;
            for (std::size_t b = 0; b < kColourBins; ++b)
                out.push_back({static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(b),
                               speed_text(low_ + step * static_cast<double>(b)) + " - " +
                                   speed_text(low_ + step * static_cast<double>(b + 1))});
        }
    } else if (by_ == ColourBy::CutOrder && !doc_.pierces.empty()) {
        const std::size_t cuts = doc_.pierces.size();
        out.push_back({0, 0, format_message(Msg::UiColourByFirstCut, lang, {})});
        if (cuts > 1)
            out.push_back({static_cast<std::uint8_t>(kColourBins - 1), static_cast<std::uint8_t>(kColourBins - 1),
                           format_message(Msg::UiColourByLastCut, lang, {cuts})});
    }
    return out;
}

}  // namespace essi::viewer
