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
    }
    return Msg::UiColourByKind;
}

namespace {

// A motion coloured by its feed: a cut or a mark at a programmed feed.
bool drawn_by_value(const Motion& m) {
    return (m.kind == MotionKind::Cut || m.kind == MotionKind::Mark) && !(m.flags & Motion::kFlagRapidFeed);
}

}  // namespace

ColourBins::ColourBins(const Document& doc, ColourBy by) : doc_(doc), by_(by) {
    if (by != ColourBy::Feed) return;
    // The feeds some cut or mark is made at (a feed in force over travel only is not drawn in a bin's colour).
    std::vector<float> all;
    for (std::size_t k = 0; k < doc.feeds.size(); ++k) {
        const auto [first, feed] = doc.feeds[k];
        const std::size_t end = k + 1 < doc.feeds.size() ? doc.feeds[k + 1].first : doc.motions.size();
        if (!(feed > 0)) continue;
        for (std::size_t i = first; i < end; ++i) {
            if (!drawn_by_value(doc.motions[i])) continue;
            all.push_back(feed);
            break;
        }
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (all.empty()) return;
    low_ = all.front();
    high_ = all.back();
    if (all.size() <= kColourBins) feeds_ = std::move(all);
}

// A feed's bin: its place among the distinct feeds spread over the ramp, or its place in the range.
std::uint8_t ColourBins::feed_bin(float feed) const {
    constexpr double last = kColourBins - 1;
    if (!feeds_.empty()) {
        const auto k = static_cast<double>(std::lower_bound(feeds_.begin(), feeds_.end(), feed) - feeds_.begin());
        return static_cast<std::uint8_t>(
            feeds_.size() == 1 ? last / 2 : std::lround(k * last / static_cast<double>(feeds_.size() - 1)));
    }
    if (!(high_ > low_)) return static_cast<std::uint8_t>(last / 2);
    const double t = std::clamp((feed - low_) / static_cast<double>(high_ - low_), 0.0, 1.0);
    return static_cast<std::uint8_t>(std::min(last, std::floor(t * kColourBins)));
}

// The bin of the cut-th cut (1: the first pierce's) of the tape's cuts.
std::uint8_t ColourBins::order_bin(std::size_t cut) const {
    const std::size_t cuts = doc_.pierces.size();
    if (cuts <= 1 || cut == 0) return 0;
    return static_cast<std::uint8_t>((cut - 1) * (kColourBins - 1) / (cuts - 1));
}

std::optional<std::uint8_t> ColourBins::bin(std::size_t i) {
    const Motion& m = doc_.motions[i];
    if (by_ == ColourBy::Kind || (m.kind != MotionKind::Cut && m.kind != MotionKind::Mark)) return std::nullopt;
    if (by_ == ColourBy::Feed) {
        if (!drawn_by_value(m)) return std::nullopt;
        while (feed_at_ + 1 < doc_.feeds.size() && doc_.feeds[feed_at_ + 1].first <= i) ++feed_at_;
        if (doc_.feeds.empty() || doc_.feeds[feed_at_].first > i || !(doc_.feeds[feed_at_].second > 0))
            return std::nullopt;
        return feed_bin(doc_.feeds[feed_at_].second);
    }
    while (pierce_at_ < doc_.pierces.size() && doc_.pierces[pierce_at_] <= i) ++pierce_at_;
    return order_bin(pierce_at_);
}

std::vector<ColourLegendEntry> ColourBins::legend(Lang lang) const {
    std::vector<ColourLegendEntry> out;
    const auto feed_text = [](double f) { return fmt("%.0f mm/min", f); };
    if (by_ == ColourBy::Feed) {
        if (!feeds_.empty()) {
            for (const float f : feeds_) {
                const std::uint8_t b = feed_bin(f);
                out.push_back({b, b, feed_text(f)});
            }
        } else if (high_ > low_) {
            const double step = (high_ - low_) / kColourBins;
            for (std::size_t b = 0; b < kColourBins; ++b)
                out.push_back({static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(b),
                               feed_text(low_ + step * static_cast<double>(b)) + " - " +
                                   feed_text(low_ + step * static_cast<double>(b + 1))});
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
