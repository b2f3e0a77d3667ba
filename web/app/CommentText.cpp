#include "app/CommentText.hpp"

#include <algorithm>
#include <string_view>

#include "app/panels/UiText.hpp"
#include "essi/lines.hpp"

namespace essi::viewer {

CommentText::CommentText(UiFonts& fonts, SettingsStore& settings) : fonts_(fonts), settings_(settings) {
    chosen_ = parse_text_encoding(settings_.load_setting(kTextEncodingSetting).value_or("auto"));
}

void CommentText::choose(std::optional<TextEncoding> chosen, const Document* doc) {
    chosen_ = chosen;
    settings_.save_setting(kTextEncodingSetting, chosen ? std::string(text_encoding_name(*chosen)) : "auto");
    if (doc) require_glyphs(*doc);
}

void CommentText::detect(const Document& doc) {
    detected_ = detect_text_encoding(doc.bytes);
    require_glyphs(doc);
}

// The glyphs of the tape's text beyond ASCII (Chinese comments: the CJK font), from the lines that have such
// bytes (at most kMaxLineBytes of each), up to kMaxGlyphText bytes of text.
void CommentText::require_glyphs(const Document& d) {
    constexpr std::size_t kMaxGlyphText = 256 * 1024, kMaxLineBytes = 4096;
    std::string text;
    for (std::size_t at = 0; text.size() < kMaxGlyphText;) {
        const auto high = std::find_if(d.bytes.begin() + static_cast<std::ptrdiff_t>(at), d.bytes.end(),
                                       [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
        if (high == d.bytes.end()) break;
        const std::string_view bytes = d.bytes;
        const std::size_t i = static_cast<std::size_t>(high - d.bytes.begin());
        const std::size_t begin = find_line_start(bytes, i), end = find_line_end(bytes, i);
        text += decode_text(bytes.substr(begin, std::min(end - begin, kMaxLineBytes)), used());
        at = end;
    }
    if (!text.empty()) fonts_.require_glyphs(text);
}

std::string CommentText::line_text(const Document& d, std::size_t line, std::size_t max) const {
    const std::string_view bytes = d.line(line);
    const std::string_view shown = bytes.substr(0, max);
    const bool ascii =
        std::all_of(shown.begin(), shown.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
    if (ascii) return printable(bytes, max);
    std::string text = decode_text(shown, used());
    std::replace(text.begin(), text.end(), '\t', ' ');
    if (bytes.size() > max) text += " ...";
    return text;
}

}  // namespace essi::viewer
