// What the page shows beside the canvas for screen readers and the browser's tab (docs/viewer.md, "Keyboard and
// screen readers"): the page's title, a live region with the tape, its verdict and the selected problem or segment,
// and the problems as a list, in the viewer's language. Made from the document and the selection only when they or
// the language change; the platform puts it in the page (PlatformServices::show_mirror).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/Document.hpp"
#include "app/Selection.hpp"
#include "essi/i18n.hpp"

namespace essi::viewer {

// The problems the page lists at most (then "and N more"): a tape with a million findings makes no million nodes.
inline constexpr std::size_t kMirrorProblems = 100;

struct PageMirror {
    std::string lang;                   // "en", "de", "zh"
    std::string title;                  // the page's title: "plate.esi — 2 errors, 1 warning — essikit viewer"
    std::string label;                  // the canvas' accessible name
    std::string heading;                // the mirror's heading
    std::string status;                 // the live region: the tape, its verdict, the selection
    std::string problems_heading;       // the list's heading ("Diagnostics")
    std::vector<std::string> problems;  // at most kMirrorProblems, in the list's order
    std::string more;                   // "and N more ..." when the list is cut, else empty

    bool operator==(const PageMirror&) const = default;
};

// The tape's verdict as the toolbar says it: "ok", "ok, 2 warnings", "1 error, 0 warnings".
[[nodiscard]] std::string verdict_text(const Document& doc);

// What the page shows: for `doc` (none: the start screen; `loading`: the name of a tape being read) and its
// selection, in the viewer's language (ui_lang()).
[[nodiscard]] PageMirror page_mirror(const Document* doc, const Selection& selection, const std::string* loading);

// Makes the mirror again only when what it is made from changed (the document — `load` counts the tapes handed
// over —, its diagnostics, the selection, the language, the loading); `changed` is true once after each change of
// what it shows.
class PageMirrorKeeper {
public:
    // The mirror for this frame; sets `changed` when it differs from the last one handed out.
    const PageMirror& update(const Document* doc, std::uint64_t load, const Selection& selection,
                             const std::string* loading, bool* changed);

private:
    struct Key {
        const Document* doc = nullptr;
        std::uint64_t load = 0;
        std::size_t diagnostics = 0;
        std::uint32_t line = 0;
        std::size_t motion = Selection::npos;
        Lang lang = Lang::En;
        std::string loading;
        bool is_loading = false;
        bool operator==(const Key&) const = default;
    };
    bool made_ = false;
    Key key_;
    PageMirror mirror_;
};

}  // namespace essi::viewer
