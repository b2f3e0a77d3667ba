// The exit, the language and the output of `essi` (cli_io.hpp).
#include "cli/cli_io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "terminal_text.hpp"

namespace essi::cli {
namespace {

Lang g_lang = Lang::En;

const native::TerminalText& terminal() {
    static const native::TerminalText text(std::getenv("LC_ALL"), std::getenv("LC_CTYPE"), std::getenv("LANG"));
    return text;
}

void write_to(std::FILE* stream, std::string_view s) { std::fwrite(s.data(), 1, s.size(), stream); }

}  // namespace

Lang lang() { return g_lang; }
void set_lang(Lang lang) { g_lang = lang; }

void out(std::string_view s) { write_to(stdout, s); }
void out_text(std::string_view s) { write_to(stdout, terminal()(s)); }
void err(std::string_view s) { write_to(stderr, terminal()(s)); }

bool write_file(const std::string& path, std::string_view bytes) {
    if (path == "-") {
        out(bytes);
        return true;
    }
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    return std::fclose(f) == 0 && ok;
}

int finish(int code) {
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        err(std::string("essi: cannot write output: ") + std::strerror(errno) + "\n");
        return kExitUsage;
    }
    return code;
}

}  // namespace essi::cli
