// essi/charset.hpp through ICU's converters (native builds). ICU links statically with its data, so the static
// `essi` converts in an empty root; glibc's iconv would load gconv modules from the file system at run time.
#include <unicode/ucnv.h>
#include <unicode/ucnv_err.h>
#include <unicode/ustring.h>

#include <memory>
#include <vector>

#include "charset_platform.hpp"
#include "essi/charset.hpp"

namespace essi {
namespace {

struct ConverterClose {
    void operator()(UConverter* c) const { ucnv_close(c); }
};
using Converter = std::unique_ptr<UConverter, ConverterClose>;

// A converter for `charset` that stops at the first byte or character it cannot convert (no substitution).
Converter strict_converter(const char* charset) {
    UErrorCode err = U_ZERO_ERROR;
    Converter c(ucnv_open(charset, &err));
    if (U_FAILURE(err)) return nullptr;
    ucnv_setToUCallBack(c.get(), UCNV_TO_U_CALLBACK_STOP, nullptr, nullptr, nullptr, &err);
    ucnv_setFromUCallBack(c.get(), UCNV_FROM_U_CALLBACK_STOP, nullptr, nullptr, nullptr, &err);
    return U_SUCCESS(err) ? std::move(c) : nullptr;
}

constexpr char16_t kQuestionMark = u'?';

}  // namespace

std::optional<std::string> detail::gb18030_two_byte_to_utf8(std::string_view character) {
    // One converter a thread, opened on first use: a comment is decoded a character at a time.
    thread_local const Converter gb = strict_converter("GB18030");
    if (!gb) return std::nullopt;
    ucnv_resetToUnicode(gb.get());  // (after a character it refused)
    UChar utf16[4];
    UErrorCode err = U_ZERO_ERROR;
    const int32_t n16 =
        ucnv_toUChars(gb.get(), utf16, 4, character.data(), static_cast<int32_t>(character.size()), &err);
    if (U_FAILURE(err) || n16 <= 0) return std::nullopt;
    char utf8[16];
    int32_t n8 = 0;
    u_strToUTF8(utf8, sizeof utf8, &n8, utf16, n16, &err);
    if (U_FAILURE(err)) return std::nullopt;
    return std::string(utf8, static_cast<std::size_t>(n8));
}

std::optional<std::string> utf8_to_charset(std::string_view utf8, const char* charset) {
    const Converter to = strict_converter(charset);
    if (!to) return std::nullopt;
    // UTF-8 -> UTF-16, each malformed byte as '?'.
    UErrorCode err = U_ZERO_ERROR;
    int32_t n16 = 0;
    std::vector<UChar> utf16(utf8.size() + 1);
    u_strFromUTF8WithSub(utf16.data(), static_cast<int32_t>(utf16.size()), &n16, utf8.data(),
                         static_cast<int32_t>(utf8.size()), kQuestionMark, nullptr, &err);
    if (U_FAILURE(err)) return std::nullopt;
    // UTF-16 -> the charset, character by character where the converter stops: '?' for what it has no code for.
    std::string out;
    out.reserve(utf8.size() + 16);
    char buf[64];
    const UChar* in = utf16.data();
    const UChar* const end = utf16.data() + n16;
    while (in < end) {
        char* o = buf;
        err = U_ZERO_ERROR;
        ucnv_fromUnicode(to.get(), &o, buf + sizeof buf, &in, end, nullptr, true, &err);
        out.append(buf, static_cast<std::size_t>(o - buf));
        if (err == U_BUFFER_OVERFLOW_ERROR) continue;
        if (U_FAILURE(err)) {  // (the character it stopped at was consumed: write '?' for it)
            out += '?';
            ucnv_resetFromUnicode(to.get());
        }
    }
    return out;
}

}  // namespace essi
