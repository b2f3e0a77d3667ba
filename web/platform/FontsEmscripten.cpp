// The CJK font in the browser: fetched from the page's folder (essi_cjk.ttc, beside index.html: the build copies
// it there, essi serve serves it) once, when a text first needs it; its bytes go straight into a malloc'ed buffer
// that UiFonts keeps (no second copy of its 5 MB).
#include <emscripten.h>

#include <cstddef>

#include "platform/Platform.hpp"
#include "render/UiFonts.hpp"

// The page's fetch is done: `fonts` is the UiFonts that asked.
extern "C" EMSCRIPTEN_KEEPALIVE void essi_font_loaded(essi::viewer::UiFonts* fonts, unsigned char* data, int size) {
    fonts->cjk_loaded(size > 0 ? data : nullptr, size > 0 ? static_cast<std::size_t>(size) : 0);
}

namespace essi::viewer::platform {

bool Platform::has_cjk_font() const {
#if defined(ESSI_CJK_FONT)
    return true;  // (the build put it beside the page)
#else
    return false;
#endif
}

void Platform::load_cjk_font(UiFonts& fonts) {
    // clang-format off
    EM_ASM({
        var fonts = $0;
        fetch('essi_cjk.ttc')
            .then(function(res) {
                if (!res.ok) throw new Error('HTTP ' + res.status);
                return res.arrayBuffer();
            })
            .then(function(buf) {
                var bytes = new Uint8Array(buf);
                var ptr = Module._malloc(bytes.length);
                if (!ptr) throw new Error('no memory for ' + bytes.length + ' bytes');
                Module.HEAPU8.set(bytes, ptr);
                Module._essi_font_loaded(fonts, ptr, bytes.length);
            })
            .catch(function(e) {
                console.warn('essikit: the CJK font (essi_cjk.ttc) could not be loaded: ' + e.message);
                Module._essi_font_loaded(fonts, 0, 0);
            });
    }, &fonts);
    // clang-format on
}

}  // namespace essi::viewer::platform
