// The text of a tape's comments (3 ... 4 sections, EIA "( )"): UTF-8 or GB 18030, detected per tape
// (essi::detect_text_encoding) unless the user chose one (kept across sessions); the source lines as the panels show
// them, decoded in it; the glyphs they need (Chinese: the CJK font) asked for when a tape is loaded.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "app/Document.hpp"
#include "app/PlatformServices.hpp"
#include "essi/text_encoding.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer {

class CommentText {
public:
    static constexpr const char* kTextEncodingSetting = "comment_encoding";

    // The encoding chosen as it was kept.
    CommentText(UiFonts& fonts, SettingsStore& settings);

    // The user's choice (nullopt: detect); `doc` the tape shown, if any (its glyphs in the new encoding).
    void choose(std::optional<TextEncoding> chosen, const Document* doc);
    // A new tape: its encoding detected, the glyphs of its text beyond ASCII asked for.
    void detect(const Document& doc);
    [[nodiscard]] std::optional<TextEncoding> chosen() const { return chosen_; }
    [[nodiscard]] TextEncoding detected() const { return detected_; }
    [[nodiscard]] TextEncoding used() const { return chosen_.value_or(detected_); }

    // A source line as the panels show it: decoded in the encoding used (at most `max` bytes of it).
    [[nodiscard]] std::string line_text(const Document& d, std::size_t line, std::size_t max = 400) const;

private:
    void require_glyphs(const Document& d);

    UiFonts& fonts_;
    SettingsStore& settings_;
    std::optional<TextEncoding> chosen_;
    TextEncoding detected_ = TextEncoding::Utf8;
};

}  // namespace essi::viewer
