#include "app/ShareLinks.hpp"

#include <optional>
#include <utility>

#include "essi/share_link.hpp"

namespace essi::viewer {

void ShareLinks::share() {
    const Document* d = session_.document();
    if (!d) return notices_.notify(Msg::UiLoadFirst);
    if (!platform_.has_share_links()) return notices_.notify(Msg::UiShareBrowserOnly);
    platform_.share(d->name, d->bytes, query());  // (the page says when a tape is too large)
}

void ShareLinks::done(std::string url) {
    url_ = std::move(url);
    problem_ = {};
    ui_.share_popup = true;
    notices_.notify(Msg::UiShareCopied);
}

void ShareLinks::failed(Phrase why) {
    url_.clear();
    problem_ = std::move(why);
    ui_.share_popup = true;
    notices_.notify(problem_.id, problem_.args);
}

std::string ShareLinks::text() const { return problem_.empty() ? url_ : problem_.text(); }

std::string ShareLinks::query() const {
    const Document* d = session_.document();
    const std::optional<Profile>& dropped = session_.dropped_profile();
    const bool user_profile = dropped && session_.profile_name() == dropped->name;
    const ViewRequest v = navigation_.current();
    return share_view_query({v.x, v.y, v.zoom}, v.line) + "&" +
           share_reading_query(session_.profile_name(), user_profile ? profile_to_json(*dropped) : std::string(),
                               d ? std::optional(d->setup.format) : std::nullopt);
}

}  // namespace essi::viewer
