// Share links (docs/viewer.md, "Share links"): the URL fragment that carries a tape and its view to another
// browser. One decoder for the page's two kinds of link, `#c=X,Y,ZOOM&l=LINE&n=NAME&t=DATA` (the tape itself:
// deflate-raw, base64url) and `#share=ID&c=...&l=...&n=NAME` (a tape in `essi serve`'s store), and the maker of the
// view part. The page inflates DATA (the browser's DecompressionStream); everything else is read here. A link also
// carries how the sender read the tape (p=PROFILE, pj=PROFILE JSON for a user profile, i=essi|eia), so that the
// receiver sees the same verdict, and the tape's length (b=BYTES) before its data, so that a link cut off in the
// data says so.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/i18n.hpp"
#include "essi/read.hpp"

namespace essi {

struct ShareView {
    double x = 0, y = 0;  // the view's centre, machine mm
    double zoom = 0;      // pixels per mm, > 0
};

struct ShareLink {
    std::optional<ShareView> view;     // c=X,Y,ZOOM (finite numbers, zoom > 0)
    std::uint32_t line = 0;            // l=LINE: the selected line (0: none)
    std::string name;                  // n=NAME, decoded (%XX and '+'); empty: none given
    std::string store_id;              // share=ID: 64 lower-case hex digits (SHA-256)
    std::string packed;                // t=DATA, base64url-decoded: the deflate-raw bytes of the tape
    std::string profile;               // p=NAME: the profile to read the tape with (is_valid_profile_name)
    std::string profile_json;          // pj=DATA, base64url-decoded: a user profile (its JSON), when p names it
    std::optional<InputFormat> input;  // i=essi|eia: the format the sender read the tape as; nullopt: from the content
    std::optional<std::uint64_t> tape_bytes;  // b=BYTES: the tape's length, to tell a whole tape from a cut one
    std::vector<std::string> problems;        // each field that could not be read, in words (the rest is still used)
    std::vector<Message> problem_messages;    // the same problems, to be worded in any language (problems: English)
    [[nodiscard]] bool has_tape() const { return !packed.empty() || !store_id.empty(); }
};

// Fragments longer than this are refused whole (browsers take URLs of up to 2 MB).
constexpr std::size_t kMaxShareFragmentBytes = 3'000'000;
// A name longer than this is cut (at a character boundary) and reported.
constexpr std::size_t kMaxShareNameBytes = 255;
// A user profile in a link: a profile file is a few KB; more is refused (reported, the link's profile unused).
constexpr std::size_t kMaxShareProfileBytes = 64 * 1024;

// A tape's id in `essi serve`'s store (share=ID): its SHA-256, 64 lower-case hex digits; anything else is not one.
constexpr std::size_t kStoreIdDigits = 64;
[[nodiscard]] bool is_store_id(std::string_view s);

// Reads a fragment (with or without its leading '#'). Never throws; unknown keys are ignored (newer links).
[[nodiscard]] ShareLink parse_share_fragment(std::string_view fragment);

// "c=X,Y,ZOOM&l=LINE": the view part of a link.
[[nodiscard]] std::string share_view_query(const ShareView& view, std::uint32_t line);

// "p=PROFILE[&pj=JSON][&i=FORMAT]": how the tape was read. `profile_json` non-empty for a user profile (`profile`
// is then its name); `input` the format it was read as, or nullopt (the content decides).
[[nodiscard]] std::string share_reading_query(std::string_view profile, std::string_view profile_json,
                                              std::optional<InputFormat> input);

// RFC 4648 base64url without padding, and its decoder (padding and line breaks refused: nullopt).
[[nodiscard]] std::string base64url_encode(std::string_view bytes);
[[nodiscard]] std::optional<std::string> base64url_decode(std::string_view text);

}  // namespace essi
