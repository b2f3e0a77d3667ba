// The message catalogue's texts and the template formatter (essi/i18n.hpp).
#include "essi/i18n.hpp"
#include "essi/text.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace essi {
namespace {

struct Row {
    std::string_view name;
    std::array<const char*, 3> texts;  // by Lang
};

constexpr Row kRows[] = {
    {"None", {"", "", ""}},
#define ESSI_MSG(id, en, de, zh) {#id, {en, de, zh}},
#include "messages/all.def"
#undef ESSI_MSG
};
static_assert(std::size(kRows) == static_cast<std::size_t>(Msg::Count), "one row per Msg");

constexpr char kArgSep = '\x1f';    // between two packed arguments
constexpr char kArgMsg = '\x1e';    // starts an argument that is a catalogue message (its number follows)
constexpr char kArgList = '\x1c';   // starts an argument that is a list ('o' alternatives, '+' joined; then items)
constexpr char kListItem = '\x1d';  // between two alternatives of a list
// Arg::messages: a list (kind ';') whose items are "ID" kArgMsg "ARGS", ARGS a message's packed arguments with
// these two in place of its kArgSep and kListItem (so that neither ends the outer argument or item).
constexpr char kNestedSep = '\x18';
constexpr char kNestedItem = '\x19';

// A text argument into the packed form as safe text (essi::display_text): every byte that is not part of valid
// UTF-8, and every control character (the packing bytes among them), is written \xNN, so that no message ever
// carries raw input bytes (a tape's, a file name's) into a report, a terminal or a markup file.
void append_text_arg(std::string& packed, std::string_view text) {
    const bool plain = std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
    if (plain) packed += text;
    else packed += display_text(text);
}

std::string argument_text(std::string_view a, Lang lang);

// One item of Arg::messages ("ID" kArgMsg "ARGS") in `lang`.
std::string nested_message_text(std::string_view item, Lang lang) {
    const std::size_t mark = item.find(kArgMsg);
    unsigned id = 0;
    for (char c : item.substr(0, mark)) id = id * 10 + static_cast<unsigned>(c - '0');
    std::string args(mark == std::string_view::npos ? std::string_view{} : item.substr(mark + 1));
    for (char& c : args) c = c == kNestedSep ? kArgSep : c == kNestedItem ? kListItem : c;
    return format_message(static_cast<Msg>(id), lang, MessageArgs::from_packed(std::move(args)));
}

// "a, b or c" (kind 'o'), "a+b+c" (kind '+') or "a; b; c" (kind ';', messages) in `lang` from "a\x1db\x1dc".
std::string list_text(char kind, std::string_view items, Lang lang) {
    std::string out;
    std::size_t begin = 0;
    while (true) {
        const std::size_t end = items.find(kListItem, begin);
        if (begin > 0) {
            if (kind == '+') out += '+';
            else if (kind == ';') out += text(Msg::ListSemicolon, lang);
            else out += text(end == std::string_view::npos ? Msg::ListOr : Msg::ListSeparator, lang);
        }
        const std::string_view item =
            items.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
        out += kind == ';' ? nested_message_text(item, lang) : argument_text(item, lang);
        if (end == std::string_view::npos) break;
        begin = end + 1;
    }
    return out;
}

// One packed argument (text, a catalogue message or a list) in `lang`.
std::string argument_text(std::string_view a, Lang lang) {
    if (!a.empty() && a.front() == kArgMsg) {
        unsigned id = 0;
        for (char c : a.substr(1)) id = id * 10 + static_cast<unsigned>(c - '0');
        return std::string(text(static_cast<Msg>(id), lang));
    }
    if (a.size() >= 2 && a.front() == kArgList) return list_text(a[1], a.substr(2), lang);
    return std::string(a);
}

const Row& row(Msg id) {
    const auto i = static_cast<std::size_t>(id);
    return kRows[i < std::size(kRows) ? i : 0];
}

std::string lower_ascii(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// Argument `n` of the packed arguments ("" when there are fewer), in `lang`.
std::string argument(std::string_view packed, std::size_t n, Lang lang) {
    std::size_t begin = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t sep = packed.find(kArgSep, begin);
        if (sep == std::string_view::npos) return {};
        begin = sep + 1;
    }
    const std::size_t end = packed.find(kArgSep, begin);
    return argument_text(packed.substr(begin, end == std::string_view::npos ? packed.size() - begin : end - begin),
                         lang);
}

}  // namespace

std::string_view lang_code(Lang lang) {
    switch (lang) {
        case Lang::De: return "de";
        case Lang::Zh: return "zh";
        case Lang::En: break;
    }
    return "en";
}

std::string_view lang_native_name(Lang lang) {
    switch (lang) {
        case Lang::De: return "Deutsch";
        case Lang::Zh: return "中文";
        case Lang::En: break;
    }
    return "English";
}

std::optional<Lang> parse_lang(std::string_view tag) {
    const std::string t = lower_ascii(tag);
    const std::string primary = t.substr(0, t.find_first_of("-_.@"));
    if (primary == "en" || primary == "c" || primary == "posix") return Lang::En;
    if (primary == "de") return Lang::De;
    if (primary == "zh") return Lang::Zh;
    return std::nullopt;
}

Lang lang_from_environment(const char* lc_all, const char* lc_messages, const char* lang) {
    for (const char* v : {lc_all, lc_messages, lang})
        if (v && *v) return parse_lang(v).value_or(Lang::En);
    return Lang::En;
}

std::string_view text(Msg id, Lang lang) { return row(id).texts[static_cast<std::size_t>(lang)]; }
const char* c_text(Msg id, Lang lang) { return row(id).texts[static_cast<std::size_t>(lang)]; }
std::string_view msg_name(Msg id) { return row(id).name; }

MessageArgs::MessageArgs(std::initializer_list<Arg> args) {
    bool first = true;
    for (const Arg& a : args) {
        if (!first) packed_ += kArgSep;
        first = false;
        if (a.msg != Msg::None) {
            packed_ += kArgMsg;
            packed_ += std::to_string(static_cast<unsigned>(a.msg));
            continue;
        }
        if (a.list) {
            packed_ += kArgList;
            packed_ += a.list;
            packed_ += a.owned;
            continue;
        }
        append_text_arg(packed_, a.text);
    }
}

namespace {
// An argument that is a list of the kind `kind` whose items `packed` holds (MessageArgs::Arg::list).
MessageArgs::Arg list_arg(char kind, std::string packed) {
    MessageArgs::Arg a("");
    a.owned = std::move(packed);
    a.text = std::string_view{};
    a.list = kind;
    return a;
}
}  // namespace

MessageArgs::Arg MessageArgs::Arg::alternatives(const std::vector<std::string>& items) {
    std::string packed;
    for (const std::string& item : items) {
        if (!packed.empty()) packed += kListItem;
        append_text_arg(packed, item);
    }
    return list_arg('o', std::move(packed));
}

MessageArgs::Arg MessageArgs::Arg::combined(const std::vector<Msg>& words) {
    std::string packed;
    for (Msg m : words) {
        if (!packed.empty()) packed += kListItem;
        packed += kArgMsg;
        packed += std::to_string(static_cast<unsigned>(m));
    }
    return list_arg('+', std::move(packed));
}

MessageArgs::Arg MessageArgs::Arg::messages(const std::vector<Message>& items) {
    std::string packed;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) packed += kListItem;
        packed += std::to_string(static_cast<unsigned>(items[i].msg));
        packed += kArgMsg;
        for (char c : items[i].args.packed()) {
            if (c == kNestedSep || c == kNestedItem) packed += '?';  // (a text's own byte, or a second level)
            else packed += c == kArgSep ? kNestedSep : c == kListItem ? kNestedItem : c;
        }
    }
    return list_arg(';', std::move(packed));
}

MessageArgs::Arg::Arg(const Message& m) : Arg(messages({m})) {}

MessageArgs MessageArgs::from_packed(std::string packed) {
    MessageArgs a;
    a.packed_ = std::move(packed);
    return a;
}

std::string format_template(std::string_view tmpl, Lang lang, const MessageArgs& args) {
    std::string out;
    out.reserve(tmpl.size() + args.packed().size());
    for (std::size_t i = 0; i < tmpl.size();) {
        const std::size_t open = tmpl.find('{', i);
        out.append(tmpl.substr(i, open == std::string_view::npos ? std::string_view::npos : open - i));
        if (open == std::string_view::npos) break;
        const std::size_t close = tmpl.find('}', open);
        if (close == std::string_view::npos || open + 1 >= close ||
            !std::isdigit(static_cast<unsigned char>(tmpl[open + 1]))) {
            out += '{';
            i = open + 1;
            continue;
        }
        const std::size_t n = static_cast<std::size_t>(tmpl[open + 1] - '0');
        const std::string value = argument(args.packed(), n, lang);
        const std::string_view inner = tmpl.substr(open + 2, close - open - 2);  // "" or "|one|other"
        if (inner.empty()) {
            out += value;
        } else {
            const std::size_t bar = inner.find('|', 1);
            const std::string_view one =
                inner.substr(1, bar == std::string_view::npos ? std::string_view::npos : bar - 1);
            const std::string_view other = bar == std::string_view::npos ? std::string_view{} : inner.substr(bar + 1);
            out += value == "1" ? one : other;
        }
        i = close + 1;
    }
    return out;
}

std::string format_message(Msg id, Lang lang, const MessageArgs& args) {
    return format_template(text(id, lang), lang, args);
}

}  // namespace essi
