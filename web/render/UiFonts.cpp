#include "render/UiFonts.hpp"

#include <imgui_internal.h>  // ImTextCharFromUtf8

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "essi_cjk_seed.hpp"
#include "essi_ui_font.hpp"

namespace essi::viewer {

namespace {

// What the atlas holds from the start: Latin-1 and the signs the UI's texts use in the three languages (the figure
// space that aligns numbers, dashes, quotes, ellipsis, bullet, per mille, euro, arrows, minus, <= >= != ~, diameter,
// check marks, U+FFFD).
constexpr ImWchar kFirstRanges[] = {0x0020, 0x00FF, 0x0152, 0x0153, 0x2007, 0x2007, 0x2013, 0x2014, 0x2018, 0x201E,
                                    0x2022, 0x2022, 0x2026, 0x2026, 0x2030, 0x2030, 0x2039, 0x203A, 0x20AC, 0x20AC,
                                    0x2190, 0x2193, 0x2212, 0x2212, 0x2248, 0x2248, 0x2260, 0x2260, 0x2264, 0x2265,
                                    0x2300, 0x2300, 0x2713, 0x2713, 0x2717, 0x2717, 0xFFFD, 0xFFFD, 0};

bool in_ranges(const unsigned short* r, unsigned c) {
    for (; r[0] != 0; r += 2)
        if (c >= r[0] && c <= r[1]) return true;
    return false;
}

// An embedded font has the character: the panels' font (cut to fonts::kUiFontRanges) or the CJK seed (the few CJK
// characters every page shows, fonts::kCjkSeedRanges).
bool in_embedded_font(unsigned c) {
    if (!fonts::kHaveUiFont) return c >= 0x20 && c <= 0xFF;  // (ImGui's ProggyClean)
    return in_ranges(fonts::kUiFontRanges, c) || (fonts::kHaveCjkSeed && in_ranges(fonts::kCjkSeedRanges, c));
}

// The atlas' font (the main font, with the CJK glyphs merged in); null before the first build.
const ImFont* atlas_font() {
    const ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    return atlas != nullptr && atlas->Fonts.Size > 0 && atlas->IsBuilt() ? atlas->Fonts[0] : nullptr;
}

// Calls fn(c) for each character of `utf8` (invalid bytes skipped, characters beyond U+FFFF as U+FFFD: ImGui's
// ImWchar is 16 bits).
template <class Fn>
void each_char(std::string_view utf8, Fn fn) {
    const char* p = utf8.data();
    const char* end = p + utf8.size();
    while (p < end) {
        if (static_cast<unsigned char>(*p) < 0x80) {  // (ASCII: always in the atlas)
            ++p;
            continue;
        }
        unsigned c = 0;
        const int n = ImTextCharFromUtf8(&c, p, end);
        p += n > 0 ? n : 1;
        fn(c > 0xFFFF ? 0xFFFDu : c);
    }
}

}  // namespace

UiFonts::UiFonts(CjkFontSource& cjk_source) : cjk_source_(cjk_source) {
    for (const unsigned c : {0u, 0xFFFDu}) asked_.set(c);
    if (!cjk_source_.has_cjk_font()) cjk_ = Cjk::Unavailable;
}

UiFonts::~UiFonts() { std::free(cjk_data_); }

const char* UiFonts::cjk_name(Cjk c) {
    switch (c) {
        case Cjk::None: return "none";
        case Cjk::Loading: return "loading";
        case Cjk::Loaded: return "loaded";
        case Cjk::Failed: return "failed";
        case Cjk::Unavailable: return "unavailable";
    }
    return "?";
}

bool UiFonts::real_font() const { return fonts::kHaveUiFont; }

UiFonts::Counts UiFonts::counts() const {
    Counts n;
    const ImFont* font = atlas_font();
    if (font == nullptr) return n;
    n.glyphs = font->Glyphs.Size;
    const bool cjk_settled = cjk_ != Cjk::None && cjk_ != Cjk::Loading;
    for (std::size_t c = 0x80; c < asked_.size(); ++c) {
        if (!asked_.test(c) || c == 0xFFFD) continue;
        const bool there = font->FindGlyphNoFallback(static_cast<ImWchar>(c)) != nullptr;
        const bool of_cjk = cjk_wanted_.GetBit(c);
        if (there && of_cjk) ++n.cjk_glyphs;
        if (!there && (of_cjk ? cjk_settled && !cjk_dirty_ : !main_dirty_)) ++n.missing;
    }
    return n;
}

int UiFonts::glyphs() const {
    const ImFont* f = atlas_font();
    return f != nullptr ? f->Glyphs.Size : 0;
}

void UiFonts::require_glyphs(std::string_view utf8) {
    const ImFont* font = atlas_font();
    each_char(utf8, [&](unsigned c) {
        if (asked_.test(c)) return;
        asked_.set(c);
        if (font != nullptr && font->FindGlyphNoFallback(static_cast<ImWchar>(c)) != nullptr) return;
        if (in_embedded_font(c)) {
            main_extra_.AddChar(static_cast<ImWchar>(c));
            main_dirty_ = true;
        } else {
            cjk_wanted_.AddChar(static_cast<ImWchar>(c));
            cjk_dirty_ = true;
        }
    });
}

void UiFonts::require_language(Lang lang) {
    const auto k = static_cast<std::size_t>(lang);
    if (k >= languages_.size() || languages_.test(k)) return;
    languages_.set(k);
    if (lang == Lang::En) return;  // (ASCII)
    for (auto m = std::uint16_t{1}; m < static_cast<std::uint16_t>(Msg::Count); ++m)
        require_glyphs(text(static_cast<Msg>(m), lang));
}

bool UiFonts::has_glyphs(std::string_view utf8) const {
    const ImFont* font = atlas_font();
    if (font == nullptr) return false;
    bool all = true;
    each_char(utf8, [&](unsigned c) { all = all && font->FindGlyphNoFallback(static_cast<ImWchar>(c)) != nullptr; });
    return all;
}

void UiFonts::cjk_loaded(unsigned char* data, std::size_t size) {
    std::free(cjk_data_);
    cjk_data_ = data;
    cjk_size_ = size;
    cjk_ = data != nullptr && size > 0 ? Cjk::Loaded : Cjk::Failed;
}

bool UiFonts::update(float pixel_ratio) {
    const float ratio = std::clamp(pixel_ratio > 0 ? pixel_ratio : 1.f, 0.5f, 4.f);
    bool rebuild = !built_ || std::fabs(ratio - ratio_) > 0.01f || main_dirty_;
    if (cjk_dirty_) {
        if (cjk_ == Cjk::None) {
            cjk_ = Cjk::Loading;
            ++cjk_loads_;
            cjk_source_.load_cjk_font(*this);  // (the desktop reads it at once: cjk_ is Loaded or Failed after it)
        }
        if (cjk_ == Cjk::Loaded) rebuild = true;
        if (cjk_ == Cjk::Failed || cjk_ == Cjk::Unavailable) cjk_dirty_ = false;  // (they stay U+FFFD)
    }
    if (!rebuild) return false;
    build(ratio);
    return true;
}

void UiFonts::build(float ratio) {
    ImGuiIO& io = ImGui::GetIO();
    ImFontAtlas& atlas = *io.Fonts;
    atlas.Clear();
    ratio_ = ratio;
    // A texel a device pixel: the font at its CSS size x the ratio, drawn at 1 / ratio (ImGui lays out in CSS
    // pixels; DisplayFramebufferScale draws them at the ratio). Whole pixels: no oversampling and advances snapped,
    // so that glyphs start on pixel edges (the sharpest stb_truetype gives without hinting); below a ratio of 1.75
    // the glyphs are oversampled twice across instead (positions between pixels look smoother there).
    pixel_size_ = std::round(kCssPixels * ratio);
    const bool snap = ratio >= 1.75f;
    if (fonts::kHaveUiFont) {
        ImFontGlyphRangesBuilder ranges;
        ranges.AddRanges(kFirstRanges);
        for (int c = 0; c < 0x10000; ++c)  // (the extra characters: a bit each)
            if (main_extra_.GetBit(static_cast<std::size_t>(c))) ranges.AddChar(static_cast<ImWchar>(c));
        main_ranges_.clear();
        ranges.BuildRanges(&main_ranges_);
        ImFontConfig main;
        main.FontDataOwnedByAtlas = false;  // (the program's bytes)
        main.OversampleH = snap ? 1 : 2;
        main.OversampleV = 1;
        main.PixelSnapH = snap;
        ImFormatString(main.Name, sizeof main.Name, "DejaVu Sans %.0f px", static_cast<double>(pixel_size_));
        atlas.AddFontFromMemoryTTF(const_cast<unsigned char*>(fonts::kUiFontTtf),
                                   static_cast<int>(sizeof fonts::kUiFontTtf), pixel_size_, &main, main_ranges_.Data);
    } else {
        ImFontConfig proggy;  // ImGui's 13 px bitmap font, magnified at the ratio (no TTF in this build)
        proggy.SizePixels = 13;
        atlas.AddFontDefault(&proggy);
        pixel_size_ = 13;
    }
    if (fonts::kHaveUiFont && fonts::kHaveCjkSeed) {  // (中文: the language switch, on every page)
        ImFontConfig seed;
        seed.MergeMode = true;
        seed.FontDataOwnedByAtlas = false;
        seed.OversampleH = snap ? 1 : 2;
        seed.OversampleV = 1;
        seed.PixelSnapH = snap;
        atlas.AddFontFromMemoryTTF(const_cast<unsigned char*>(fonts::kCjkSeedTtf),
                                   static_cast<int>(sizeof fonts::kCjkSeedTtf), pixel_size_, &seed,
                                   fonts::kCjkSeedRanges);
    }
    cjk_ranges_.clear();
    if (cjk_ == Cjk::Loaded && fonts::kHaveUiFont) {
        cjk_wanted_.BuildRanges(&cjk_ranges_);
        if (cjk_ranges_.Size > 1) {
            ImFontConfig merge;
            merge.MergeMode = true;
            merge.FontNo = 0;  // (WenQuanYi Micro Hei; 1 is its monospaced face)
            merge.FontDataOwnedByAtlas = false;
            merge.OversampleH = snap ? 1 : 2;
            merge.OversampleV = 1;
            merge.PixelSnapH = snap;
            atlas.AddFontFromMemoryTTF(cjk_data_, static_cast<int>(cjk_size_), pixel_size_, &merge, cjk_ranges_.Data);
        }
        cjk_dirty_ = false;
    }
    atlas.Build();
    io.FontGlobalScale = fonts::kHaveUiFont ? 1.f / ratio_ : 1.f;
    built_ = true;
    main_dirty_ = false;
    ++builds_;
}

}  // namespace essi::viewer
