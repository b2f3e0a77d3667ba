// The viewer's language (docs/viewer.md, "Languages"): every text it shows is a row of the core's catalogue
// (essi/i18n.hpp; the viewer's own rows are core/i18n/messages/ui.def) in the language chosen
// (Preferences::set_language: the browser's or the environment's, or the user's switch, kept as the setting "lang").
#pragma once

#include <string>

#include "essi/i18n.hpp"

namespace essi::viewer {

// The language the panels are drawn in (English until Preferences sets it).
[[nodiscard]] Lang ui_lang();
void set_ui_lang(Lang lang);

// A catalogue row in the viewer's language.
[[nodiscard]] inline const char* tr(Msg id) { return c_text(id, ui_lang()); }
[[nodiscard]] inline std::string tr(Msg id, const MessageArgs& args) { return format_message(id, ui_lang(), args); }
// "Text###id": an ImGui label in the viewer's language whose id (and so the window's or widget's place and state)
// stays the same in every language.
[[nodiscard]] std::string tr_id(Msg id, const char* stable_id);
// A row as an ImGui slider format for one number: {0} becomes `spec` ("%d", "%.0f"), any other '%' "%%".
[[nodiscard]] std::string tr_format(Msg id, const char* spec);

// A text to show later, in the language of that moment: a row and its arguments (a toolbar message, a share
// link's problem).
struct Phrase {
    Msg id = Msg::None;
    MessageArgs args;
    [[nodiscard]] bool empty() const { return id == Msg::None; }
    [[nodiscard]] std::string text() const { return empty() ? std::string() : tr(id, args); }
};

}  // namespace essi::viewer
