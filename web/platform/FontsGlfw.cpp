// The CJK font on the desktop: read from the file system when a text first needs it (the file the build found,
// ESSI_CJK_FONT, e.g. fonts-wqy-microhei's; the environment's ESSI_CJK_FONT names another).
#include <cstdio>
#include <cstdlib>

#include "platform/Platform.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer::platform {

namespace {
const char* cjk_font_path() {
    const char* path = std::getenv("ESSI_CJK_FONT");
#if defined(ESSI_CJK_FONT)
    if (path == nullptr || *path == '\0') path = ESSI_CJK_FONT;
#endif
    return path != nullptr && *path != '\0' ? path : nullptr;
}
}  // namespace

bool Platform::has_cjk_font() const { return cjk_font_path() != nullptr; }

void Platform::load_cjk_font(UiFonts& fonts) {
    const char* path = cjk_font_path();
    if (path == nullptr) return fonts.cjk_loaded(nullptr, 0);
    std::FILE* f = std::fopen(path, "rb");
    unsigned char* data = nullptr;
    long size = -1;
    if (f != nullptr && std::fseek(f, 0, SEEK_END) == 0 && (size = std::ftell(f)) > 0 &&
        std::fseek(f, 0, SEEK_SET) == 0) {
        data = static_cast<unsigned char*>(std::malloc(static_cast<std::size_t>(size)));
        if (data != nullptr &&
            std::fread(data, 1, static_cast<std::size_t>(size), f) != static_cast<std::size_t>(size)) {
            std::free(data);
            data = nullptr;
        }
    }
    if (f != nullptr) std::fclose(f);
    if (data == nullptr) std::fprintf(stderr, "essi_viewer: cannot read the CJK font %s\n", path);
    fonts.cjk_loaded(data, data != nullptr ? static_cast<std::size_t>(size) : 0);
}

}  // namespace essi::viewer::platform
