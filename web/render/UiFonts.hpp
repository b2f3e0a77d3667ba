// The panels' fonts: ImGui's font atlas made from a real TTF at the screen's pixels, and the CJK glyphs added when a
// text needs them.
//
//   - The font is DejaVu Sans (fonts-dejavu-core), cut down at build time to Latin, Greek, punctuation, arrows and
//     mathematical signs (web/CMakeLists.txt) and embedded in the program. It is rasterised at kCssPixels x the
//     device pixel ratio (26 px on a ratio of 2) and drawn with io.FontGlobalScale = 1 / ratio, so that a texel of
//     the atlas is a pixel of the screen: sharp text on hi-DPI screens. A new ratio (the window moved to another
//     screen, the browser's zoom) makes the atlas again.
//   - The atlas holds Latin-1 and a few signs from the start; any other character of the embedded font, and every
//     character it lacks (Chinese), is added when require_glyphs() sees it. Characters the embedded font lacks come
//     from the CJK font, WenQuanYi Micro Hei (fonts-wqy-microhei), merged into the main font (ImFontConfig::
//     MergeMode): only the glyphs asked for so far (an ImFontGlyphRangesBuilder over the texts seen). That font
//     (5 MB) is read once, the first time it is needed: the browser fetches essi_cjk.ttc from the page's folder
//     (asynchronously: the text shows U+FFFD until it is there), the desktop reads it from the file system.
//   - The atlas is only changed between frames (update(), called by App::render after ImGui::Render): ImGui locks
//     it from NewFrame to Render.
#pragma once

#include <bitset>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <imgui.h>

#include "essi/i18n.hpp"

namespace essi::viewer {

class UiFonts;

// Where the CJK font comes from (the platform: web/platform/Fonts*.cpp).
class CjkFontSource {
public:
    virtual ~CjkFontSource() = default;
    // This build has a CJK font to load (scripts/setup installs fonts-wqy-microhei).
    [[nodiscard]] virtual bool has_cjk_font() const = 0;
    // Loads it and hands its bytes to fonts.cjk_loaded (null when it cannot be had): the browser fetches
    // essi_cjk.ttc from the page's folder and calls back later, between frames; the desktop reads the file the build
    // found (ESSI_CJK_FONT; the environment's ESSI_CJK_FONT overrides it) before it returns.
    virtual void load_cjk_font(UiFonts& fonts) = 0;
};

class UiFonts {
public:
    static constexpr float kCssPixels = 13;  // the font's size in CSS pixels (ImGui's default font had 13)

    explicit UiFonts(CjkFontSource& cjk_source);
    ~UiFonts();
    UiFonts(const UiFonts&) = delete;
    UiFonts& operator=(const UiFonts&) = delete;

    // Text the UI shows or is about to show (UTF-8, any length; invalid bytes are skipped). Its characters that
    // the atlas lacks are added before the next frames: from the embedded font at once, from the CJK font once it
    // is loaded (the first such call starts loading it). Cheap when nothing is missing (a bit test a character):
    // call it with a text each time it is drawn — the translator's helper for texts in the chosen language, the
    // source view and the inspector for tape comments, names of files. Until its glyphs are there a character is
    // drawn as U+FFFD. Safe during a frame (it only notes what is missing).
    void require_glyphs(std::string_view utf8);
    // Every text of the message catalogue in `lang` (essi::text(m, lang) for each Msg from 1 to Msg::Count): for
    // Lang::Zh the Chinese UI's glyphs (loads the CJK font). Call it when the language becomes `lang`; once per
    // language is enough (later calls return at once).
    void require_language(Lang lang);
    // True when every character of `utf8` has its glyph in the atlas (what the next frame can draw).
    [[nodiscard]] bool has_glyphs(std::string_view utf8) const;

    // Makes the atlas (first call) or makes it again when the pixel ratio changed or glyphs were asked for that can
    // be had now. Only between frames (not between ImGui::NewFrame and ImGui::Render). True when the atlas changed:
    // its texture must be uploaded again (UiRenderer::upload_fonts).
    bool update(float pixel_ratio);

    // The CJK font: not asked for yet, being loaded, loaded, could not be loaded, or not in this build.
    enum class Cjk : std::uint8_t { None, Loading, Loaded, Failed, Unavailable };
    [[nodiscard]] Cjk cjk() const { return cjk_; }
    [[nodiscard]] static const char* cjk_name(Cjk c);
    [[nodiscard]] float pixel_size() const { return pixel_size_; }  // the atlas' font size in device pixels
    [[nodiscard]] float pixel_ratio() const { return ratio_; }      // the ratio it was made for
    [[nodiscard]] int glyphs() const;                               // glyphs in the atlas
    struct Counts {
        int glyphs = 0;      // in the atlas
        int cjk_glyphs = 0;  // of them from the CJK font
        int missing = 0;     // characters asked for that no font has (drawn as U+FFFD)
    };
    [[nodiscard]] Counts counts() const;  // (goes over every character asked for: for the state, not each frame)
    [[nodiscard]] int builds() const { return builds_; }        // atlases made so far
    [[nodiscard]] int cjk_loads() const { return cjk_loads_; }  // times the CJK font was asked for (0 or 1)
    [[nodiscard]] bool real_font() const;                       // false: ImGui's bitmap font (no TTF built in)
    // Glyphs asked for wait for the next update() or for the CJK font.
    [[nodiscard]] bool pending() const { return main_dirty_ || cjk_dirty_; }

    // The CJK font's bytes have arrived (malloc'ed, owned from now on; null when it could not be read). Called by
    // the platform (CjkFontSource::load_cjk_font).
    void cjk_loaded(unsigned char* data, std::size_t size);

private:
    void build(float pixel_ratio);

    CjkFontSource& cjk_source_;
    float ratio_ = 0, pixel_size_ = 0;
    bool built_ = false, main_dirty_ = false, cjk_dirty_ = false;
    std::bitset<0x10000> asked_;                  // characters looked at: in the atlas, asked for, or missing
    ImFontGlyphRangesBuilder main_extra_;         // characters of the embedded font beyond the first ranges
    ImFontGlyphRangesBuilder cjk_wanted_;         // characters asked of the CJK font
    ImVector<ImWchar> main_ranges_, cjk_ranges_;  // (ImGui keeps pointers to these until the atlas is built)
    Cjk cjk_ = Cjk::None;
    unsigned char* cjk_data_ = nullptr;
    std::size_t cjk_size_ = 0;
    int builds_ = 0, cjk_loads_ = 0;
    std::bitset<3> languages_;  // require_language done for these (by Lang)
};

}  // namespace essi::viewer
