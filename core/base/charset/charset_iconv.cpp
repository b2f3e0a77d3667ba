// essi/charset.hpp through the C library's iconv (the Emscripten build: musl decodes GBK and GB 18030's two-byte
// characters; it has no encoder for them, so utf8_to_charset gives nullopt and the text stays UTF-8).
#include <iconv.h>

#include <cerrno>

#include "charset_platform.hpp"
#include "essi/charset.hpp"

namespace essi {
namespace {

const auto kNoConverter = reinterpret_cast<iconv_t>(-1);  // (iconv_open's failure)
constexpr auto kIconvFailed = static_cast<std::size_t>(-1);

// An iconv descriptor closed when it goes out of scope.
class Iconv {
public:
    Iconv(const char* to, const char* from) : cd_(iconv_open(to, from)) {}
    ~Iconv() {
        if (ok()) iconv_close(cd_);
    }
    Iconv(const Iconv&) = delete;
    Iconv& operator=(const Iconv&) = delete;
    [[nodiscard]] bool ok() const { return cd_ != kNoConverter; }
    [[nodiscard]] iconv_t get() const { return cd_; }

private:
    iconv_t cd_;
};

}  // namespace

std::optional<std::string> detail::gb18030_two_byte_to_utf8(std::string_view character) {
    // One descriptor a thread, opened on first use: a comment is decoded a character at a time.
    thread_local const Iconv cd("UTF-8", "GB18030");
    if (!cd.ok()) return std::nullopt;
    iconv(cd.get(), nullptr, nullptr, nullptr, nullptr);  // (the initial state, after a character it refused)
    char buf[16];
    char* in = const_cast<char*>(character.data());
    std::size_t in_left = character.size();
    char* out = buf;
    std::size_t out_left = sizeof buf;
    if (iconv(cd.get(), &in, &in_left, &out, &out_left) == kIconvFailed || in_left != 0) return std::nullopt;
    return std::string(buf, static_cast<std::size_t>(out - buf));
}

std::optional<std::string> utf8_to_charset(std::string_view utf8, const char* charset) {
    const Iconv cd(charset, "UTF-8");
    if (!cd.ok()) return std::nullopt;
    std::string out(utf8.size() * 2 + 16, '\0');
    char* in = const_cast<char*>(utf8.data());
    std::size_t in_left = utf8.size();
    char* o = out.data();
    std::size_t out_left = out.size();
    const auto grow = [&] {
        const std::size_t used = static_cast<std::size_t>(o - out.data());
        out.resize(out.size() * 2);
        o = out.data() + used;
        out_left = out.size() - used;
    };
    while (in_left > 0) {
        if (iconv(cd.get(), &in, &in_left, &o, &out_left) != kIconvFailed) break;
        if (errno == E2BIG || out_left == 0) {  // (grow the output and go on)
            grow();
            continue;
        }
        // A character the charset has no code for (or bytes that are not UTF-8): '?' and past it.
        std::size_t skip = 1;
        while (skip < in_left && (static_cast<unsigned char>(in[skip]) & 0xC0) == 0x80) ++skip;
        *o++ = '?';
        --out_left;
        in += skip;
        in_left -= skip;
        iconv(cd.get(), nullptr, nullptr, nullptr, nullptr);
    }
    out.resize(static_cast<std::size_t>(o - out.data()));
    return out;
}

}  // namespace essi
