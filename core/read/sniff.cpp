// "Is this a tape?" (essi/sniff.hpp).
#include "essi/sniff.hpp"

#include <algorithm>

#include "essi/lines.hpp"

namespace essi {

namespace {

constexpr std::size_t kControlBytesPerBinary = 20;  // more than 1 control byte in 20: binary
constexpr std::size_t kEssiLinesPercent = 80;       // lines that must hold only ESSI characters

bool is_essi_char(char c) { return c == '+' || c == '-' || (c >= '0' && c <= '9') || c == ' ' || c == '\t'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

bool looks_binary(std::string_view bytes) {
    const std::size_t n = std::min(bytes.size(), kBinarySniffBytes);
    std::size_t bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c == 0) return true;
        if (c < 0x09 || (c > 0x0D && c < 0x20)) ++bad;
    }
    return n > 0 && bad * kControlBytesPerBinary > n;
}

bool looks_like_essi(std::string_view head) {
    if (looks_binary(head)) return false;
    if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);  // a tape written by an editor
    // A cut-off last line says nothing: drop it when the head is a full kSniffBytes.
    if (head.size() >= kSniffBytes) {
        const std::size_t nl = head.find_last_of("\r\n");
        if (nl != std::string_view::npos) head = head.substr(0, nl + 1);
    }
    std::size_t lines = 0, good = 0;
    bool digit_seen = false, in_comment = false;
    std::size_t pos = 0;
    while (pos < head.size()) {
        const std::size_t end = find_line_end(head, pos);
        const std::string_view line = trim_blanks(head.substr(pos, end - pos));
        pos = end + 1;
        if (line.empty()) continue;
        if (in_comment) {
            in_comment = line != "4";
            continue;
        }
        ++lines;
        if (line == "3") {  // ignore ON: a comment section follows
            in_comment = true;
            ++good;
            digit_seen = true;
            continue;
        }
        if (line == "%" || line == "/") {
            ++good;
            continue;
        }
        if (std::all_of(line.begin(), line.end(), is_essi_char)) {
            ++good;
            digit_seen = digit_seen || std::any_of(line.begin(), line.end(), is_digit);
        }
    }
    return lines >= 2 && digit_seen && good * 100 >= lines * kEssiLinesPercent;
}

namespace {

// A file format's signature: the bytes it starts with, what it is and its name.
struct Signature {
    std::string_view start;
    Msg what;
    const char* name;
};
constexpr Signature kSignatures[] = {
    {"\x89PNG\r\n\x1A\n", Msg::FilePicture, "PNG"},
    {"\xFF\xD8\xFF", Msg::FilePicture, "JPEG"},
    {"GIF87a", Msg::FilePicture, "GIF"},
    {"GIF89a", Msg::FilePicture, "GIF"},
    {"PK\x03\x04", Msg::FileArchive, "ZIP"},
    {"PK\x05\x06", Msg::FileArchive, "ZIP"},  // (an empty ZIP)
    {"\x1F\x8B", Msg::FileArchive, "gzip"},
    {"%PDF-", Msg::FilePdf, "PDF"},
};

}  // namespace

Message not_a_tape(std::string_view text) {
    if (text.empty()) return {Msg::FileEmpty};
    for (const Signature& s : kSignatures)
        if (text.starts_with(s.start)) return {s.what, {s.name}};
    if (looks_binary(text)) return {Msg::FileBinary};
    return {};
}

}  // namespace essi
