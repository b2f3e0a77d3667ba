// The message catalogue: every sentence essikit shows a person (diagnostics, reports, the viewer's panels) in
// English, German and Chinese (simplified), one row per message in core/i18n/messages/*.def. The CLI picks the
// language from --lang or the environment (LC_ALL, LC_MESSAGES, LANG), the viewer from the browser or the
// user's switch. Terms follow the standards' own editions: GB/T 22217-2008 for Chinese, the Woyda/DIN manuals
// for German (docs/languages.md).
//
// A template names its arguments {0} .. {9}; {N|one|other} picks a word by whether argument N is "1" (plural
// endings) and prints nothing of N itself. An argument can itself be a message (Arg(Msg::...), or one with its
// own arguments: Arg(Message), Arg::messages): it is shown in the reader's language too.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace essi {

enum class Lang : std::uint8_t { En, De, Zh };
inline constexpr std::array<Lang, 3> kLanguages{Lang::En, Lang::De, Lang::Zh};

// "en", "de", "zh" (what --lang, the share link and the viewer's setting store).
[[nodiscard]] std::string_view lang_code(Lang lang);
// The language's name in itself: "English", "Deutsch", "中文".
[[nodiscard]] std::string_view lang_native_name(Lang lang);
// A language tag or a POSIX locale: "de", "de-AT", "de_DE.UTF-8", "zh-CN", "zh_CN.GB18030", "en_US", "C".
// nullopt for one essikit has no texts for (the caller says so or falls back to English).
[[nodiscard]] std::optional<Lang> parse_lang(std::string_view tag);
// The language of the POSIX environment: the first of LC_ALL, LC_MESSAGES, LANG that is set and not empty
// (any of them may be null); English when that one is not a language essikit has.
[[nodiscard]] Lang lang_from_environment(const char* lc_all, const char* lc_messages, const char* lang);

// One id per row of the catalogue.
enum class Msg : std::uint16_t {
    None = 0,
#define ESSI_MSG(id, en, de, zh) id,
#include "messages/all.def"
#undef ESSI_MSG
    Count
};

// The row's template in `lang` (the English one for Msg::None: empty).
[[nodiscard]] std::string_view text(Msg id, Lang lang);
// text() as a NUL-terminated string (the catalogue holds literals), for ImGui and printf.
[[nodiscard]] const char* c_text(Msg id, Lang lang);
// The id's name in the catalogue ("ReadFunctionTooLong"), for tests and tools.
[[nodiscard]] std::string_view msg_name(Msg id);

struct Message;

// A message's arguments, packed in one string (one allocation, mostly none): what a Diagnostic keeps so that it
// can be shown in any language later.
class MessageArgs {
public:
    // One argument: text as it is (numbers formatted by the caller), or a catalogue message.
    struct Arg {
        Arg(std::string_view s) : text(s) {}
        Arg(const std::string& s) : text(s) {}
        Arg(const char* s) : text(s) {}
        Arg(Msg m) : msg(m) {}
        Arg(const Arg& o)
            : owned(o.owned),
              text(!o.owned.empty() && o.text.data() == o.owned.data() ? std::string_view(owned) : o.text), msg(o.msg),
              list(o.list) {}
        Arg& operator=(const Arg&) = delete;
        // Alternatives shown as a list in the reader's language: "63, 64 or /", "63、64 或 /".
        [[nodiscard]] static Arg alternatives(const std::vector<std::string>& items);
        // Catalogue words joined with '+' in any language: "oxygen+punch", "Sauerstoff+Körner".
        [[nodiscard]] static Arg combined(const std::vector<Msg>& words);
        // Catalogue messages with their own arguments, joined with "; " (Msg::ListSemicolon) in the reader's
        // language: the evidence in N403's message, a share link's problems. One level deep: an argument of these
        // messages is text, a word or a list, not messages again.
        [[nodiscard]] static Arg messages(const std::vector<Message>& items);
        // One such message.
        Arg(const Message& m);
        Arg(int v) : owned(std::to_string(v)), text(owned) {}
        Arg(unsigned v) : owned(std::to_string(v)), text(owned) {}
        Arg(long v) : owned(std::to_string(v)), text(owned) {}
        Arg(unsigned long v) : owned(std::to_string(v)), text(owned) {}
        Arg(long long v) : owned(std::to_string(v)), text(owned) {}
        Arg(unsigned long long v) : owned(std::to_string(v)), text(owned) {}
        std::string owned;
        std::string_view text;
        Msg msg = Msg::None;
        char list = 0;  // 'o': `owned` holds alternatives ("a, b or c"), '+': words joined with '+', ';': messages
                        // (packed)
    };
    MessageArgs() = default;
    MessageArgs(std::initializer_list<Arg> args);
    [[nodiscard]] const std::string& packed() const { return packed_; }
    [[nodiscard]] static MessageArgs from_packed(std::string packed);

private:
    std::string packed_;
};

// `id`'s template in `lang` with the arguments put in.
[[nodiscard]] std::string format_message(Msg id, Lang lang, const MessageArgs& args = {});
// A template with arguments (what format_message does once it has the template).
[[nodiscard]] std::string format_template(std::string_view tmpl, Lang lang, const MessageArgs& args);

// A sentence of the catalogue with its arguments, to be worded later in any language (as a Diagnostic keeps its
// message): the dialect's evidence (essi/dialect.hpp), a share link's problems (essi/share_link.hpp).
struct Message {
    Message() = default;
    Message(Msg m, MessageArgs a = {}) : msg(m), args(std::move(a)) {}
    Msg msg = Msg::None;
    MessageArgs args;
    [[nodiscard]] std::string text(Lang lang) const { return format_message(msg, lang, args); }
};

}  // namespace essi
