// The C functions behind window.essikit: index.html calls them as Module._essi_* (or through ccall when they take
// a string); essi_heap is for the tests and benchmarks. (essi_background_slice is in MainLoopEmscripten.cpp.)
#include <algorithm>
#include <cmath>
#include <emscripten.h>
#include <malloc.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "essi/share_link.hpp"
#include "essi/text.hpp"
#include "platform/ApiEmscripten.hpp"

using essi::viewer::Automation;

namespace {

// The app's side of the page's API (serve_page_api); null until the main loop has made the app.
Automation* g_api = nullptr;

// The link last read by essi_parse_share (below): its tape is loaded as the sender read it (essi_load_commit_shared),
// its problems are worded in the viewer's language (page_phrase).
essi::ShareLink g_share_link;

// What the page says went wrong with a share link, as {"kind": ..., "args": [...]} (index.html, share_store.js): the
// sentence is the catalogue's, in the viewer's language.
essi::viewer::Phrase page_phrase(const char* json) {
    using essi::Msg;
    static constexpr struct {
        const char* kind;
        Msg msg;
        Msg arg;  // its argument when it is a catalogue word (else the page's arguments)
    } kKinds[] = {
        {"cut", Msg::UiLinkCut, Msg::None},
        {"no-tape", Msg::UiLinkCut, Msg::UiLinkNoTape},
        {"no-stored-tape", Msg::UiLinkCut, Msg::UiLinkNoStoredTape},
        {"unpack", Msg::UiLinkCut, Msg::UiLinkNoUnpack},
        {"length", Msg::UiLinkCutLength, Msg::None},
        {"store-down", Msg::UiLinkStoreDown, Msg::None},
        {"gone", Msg::UiLinkGone, Msg::None},
        {"store-error", Msg::UiLinkStoreError, Msg::None},
        {"too-large", Msg::UiLinkTooLarge, Msg::None},
        {"make-failed", Msg::UiLinkMakeFailed, Msg::None},
        {"store-too-large", Msg::UiLinkStoreTooLarge, Msg::None},
        {"store-failed", Msg::UiLinkStoreFailed, Msg::None},
    };
    const nlohmann::json j = nlohmann::json::parse(json ? json : "", nullptr, false);
    const std::string kind =
        j.is_object() && j.contains("kind") && j["kind"].is_string() ? j["kind"].get<std::string>() : "";
    std::vector<std::string> args;
    if (j.is_object() && j.contains("args") && j["args"].is_array())
        for (const auto& a : j["args"]) args.push_back(a.is_string() ? a.get<std::string>() : a.dump());
    args.resize(2);
    // "cut" with the problems of the link read last, as essi_parse_share gave them to the page (joined with "; "):
    // those problems in the viewer's language, also when it is switched later.
    if (kind == "cut" && !g_share_link.problems.empty()) {
        std::string joined;
        for (const std::string& p : g_share_link.problems) joined += (joined.empty() ? "" : "; ") + p;
        if (args[0] == joined)
            return {Msg::UiLinkCut, {essi::MessageArgs::Arg::messages(g_share_link.problem_messages)}};
    }
    for (const auto& k : kKinds) {
        if (kind != k.kind) continue;
        if (k.arg != Msg::None) return {k.msg, {k.arg}};
        return {k.msg, {args[0], args[1]}};
    }
    return {Msg::UiLinkMakeFailed, {kind}};  // (a kind this viewer does not know)
}

}  // namespace

namespace essi::viewer::platform {
void serve_page_api(Automation& automation) { g_api = &automation; }
}  // namespace essi::viewer::platform

extern "C" {

// Loading without a second copy: the page asks for a buffer of `len` bytes (essi_load_buffer), writes the file
// into it and commits it under its name (essi_load_commit): the buffer becomes the document's bytes.
namespace {
std::string g_pending;
}

EMSCRIPTEN_KEEPALIVE char* essi_load_buffer(int len) {
    g_pending = std::string();
    try {
        g_pending.resize(static_cast<std::size_t>(len > 0 ? len : 0));
    } catch (...) {
        return nullptr;
    }
    return g_pending.data();
}

EMSCRIPTEN_KEEPALIVE void essi_load_commit(const char* name) {
    if (g_api) g_api->load(name, std::move(g_pending));
    g_pending = std::string();
}

EMSCRIPTEN_KEEPALIVE void essi_load_commit_shared(const char* name) {
    if (g_api) g_api->load_shared(name, std::move(g_pending), g_share_link);
    g_pending = std::string();
}

// A share link that could not be opened ({"kind", "args"}: page_phrase): shown over the start screen.
EMSCRIPTEN_KEEPALIVE void essi_link_problem(const char* json) {
    if (g_api) g_api->link_problem(page_phrase(json));
}

// The panels' language: "en", "de", "zh" (or a tag such as "de-AT"); kept across sessions. Another is ignored.
EMSCRIPTEN_KEEPALIVE void essi_set_language(const char* tag) {
    if (!g_api || !tag) return;
    if (const auto lang = essi::parse_lang(tag)) g_api->set_language(*lang);
}

// The state as JSON (Automation::state_json); valid until the next call.
EMSCRIPTEN_KEEPALIVE const char* essi_state() {
    static std::string s;
    s = g_api ? g_api->state_json() : "{\"status\":\"starting\"}";
    return s.c_str();
}

// state({problems: {offset, limit}}): the page of the diagnostics asked for (-1: the default offset or limit).
EMSCRIPTEN_KEEPALIVE const char* essi_state_page(double offset, double limit) {
    static std::string s;
    s = g_api ? g_api->state_json(
                    essi::viewer::problem_page(static_cast<long long>(offset), static_cast<long long>(limit)))
              : "{\"status\":\"starting\"}";
    return s.c_str();
}

// The WASM heap as malloc sees it (tests and benchmarks): {"footprint": bytes taken from the heap's end (sbrk),
// "peak": the largest footprint so far, "in_use": bytes in allocated blocks}. The page's memory (HEAPU8.length)
// grows to hold the peak footprint and never shrinks.
EMSCRIPTEN_KEEPALIVE const char* essi_heap() {
    static std::string s;
    const struct mallinfo m = mallinfo();
    s = "{\"footprint\":" + std::to_string(static_cast<unsigned>(m.arena)) +
        ",\"peak\":" + std::to_string(static_cast<unsigned>(m.usmblks)) +
        ",\"in_use\":" + std::to_string(static_cast<unsigned>(m.uordblks)) + "}";
    return s.c_str();
}

// One motion as JSON (Automation::motion_json), "null" past the end; valid until the next call.
EMSCRIPTEN_KEEPALIVE const char* essi_motion(int index) {
    static std::string s;
    s = g_api && index >= 0 ? g_api->motion_json(static_cast<std::size_t>(index)) : "null";
    return s.c_str();
}

// View centre in machine mm and zoom in pixels per mm; applied after the load in progress, if any.
EMSCRIPTEN_KEEPALIVE void essi_set_view(double x, double y, double zoom) {
    if (g_api) g_api->set_view(x, y, zoom);
}

EMSCRIPTEN_KEEPALIVE void essi_select_line(int line) {
    if (g_api) g_api->select_line(static_cast<std::uint32_t>(line > 0 ? line : 0));
}

// layer: 0 rapid, 1 travel, 2 cut, 3 mark (essi::MotionKind), 4 pierces, 5 start, 6 kerf path, 7 kerf width, 8 table, 9
// parts
EMSCRIPTEN_KEEPALIVE void essi_set_layer(int layer, int visible) {
    if (g_api) g_api->set_layer(layer, visible != 0);
}

EMSCRIPTEN_KEEPALIVE void essi_set_orientation(int quarter_turns) {
    if (g_api) g_api->set_orientation(quarter_turns);
}

// 1: machine coordinates, 0: program coordinates (Coordinates).
EMSCRIPTEN_KEEPALIVE void essi_set_coordinates(int machine) {
    if (g_api) g_api->set_machine_coordinates(machine != 0);
}

// The page pixel where program point (x, y) mm is drawn (View::to_screen), as JSON [px, py].
EMSCRIPTEN_KEEPALIVE const char* essi_project(double x, double y) {
    static std::string s;
    if (!g_api) return "null";
    const essi::Point p = g_api->project(x, y);
    s = nlohmann::json::array({p.x, p.y}).dump();
    return s.c_str();
}

// The playback: its speed factor (machine seconds a second, 1-1000) and whether it plays (from where it is).
EMSCRIPTEN_KEEPALIVE void essi_set_playback(double factor, int playing) {
    if (g_api) g_api->set_playback(factor, playing != 0);
}

// Copies as the panels' Copy buttons and menus do: 0 the report, 1 the diagnostic `index`, 2 the source line
// `index`, 3 the inspector's text of the selected line (Exports::CopyWhat).
EMSCRIPTEN_KEEPALIVE void essi_copy(int what, int index) {
    if (g_api && what >= 0 && what <= 3)
        g_api->copy(static_cast<essi::viewer::Exports::CopyWhat>(what), static_cast<std::uint32_t>(std::max(index, 0)));
}

// Two fingers on the canvas (index.html): the view zooms by `factor` about the fingers' middle and moves with it
// from (x0, y0) to (x1, y1), canvas pixels.
EMSCRIPTEN_KEEPALIVE void essi_pinch(double x0, double y0, double x1, double y1, double factor) {
    if (g_api) g_api->pinch(x0, y0, x1, y1, factor);
}

// The side panels shown or hidden, and their widths (0: as they are); kept across sessions.
EMSCRIPTEN_KEEPALIVE void essi_set_layout(int left_shown, int right_shown, double left, double right) {
    if (g_api)
        g_api->set_layout({static_cast<float>(left), static_cast<float>(right), left_shown != 0, right_shown != 0});
}

// Compare mode: the tape in the load buffer (essi_load_buffer) is compared with the loaded one (essikit.compare);
// essi_end_compare leaves the mode; essi_show_difference shows the k-th difference's contour.
EMSCRIPTEN_KEEPALIVE void essi_compare_commit(const char* name) {
    if (g_api) g_api->compare_with(name ? name : "B", g_pending);
    g_pending = std::string();
}
EMSCRIPTEN_KEEPALIVE void essi_end_compare() {
    if (g_api) g_api->end_compare();
}
// The job sheet's print view (the Job panel's Print view button): a new tab, or a download where none opens.
EMSCRIPTEN_KEEPALIVE void essi_print_job_sheet() {
    if (g_api) g_api->print_job_sheet();
}
EMSCRIPTEN_KEEPALIVE void essi_show_difference(int k) {
    if (g_api) g_api->show_difference(k);
}

// 1 when the keyboard's focus is on the drawing, the viewer's last Tab stop: the page lets Tab leave the canvas there.
EMSCRIPTEN_KEEPALIVE int essi_keyboard_at_drawing() { return g_api && g_api->keyboard_at_drawing() ? 1 : 0; }

// The view as PNG after the next frame (window.essikitLastPng gets its data URL).
EMSCRIPTEN_KEEPALIVE void essi_export_png() {
    if (g_api) g_api->export_view_png();
}

// The comments' text encoding: "utf-8", "gb18030" (or "gbk"), anything else detects it (kept across sessions).
EMSCRIPTEN_KEEPALIVE void essi_set_comment_encoding(const char* name) {
    if (g_api) g_api->set_text_encoding(essi::parse_text_encoding(name ? name : ""));
}

// The problems-only view: 1 on (what no diagnostic concerns drawn faint), 0 off (kept across sessions).
EMSCRIPTEN_KEEPALIVE void essi_set_problems_only(int on) {
    if (g_api) g_api->set_problems_only(on != 0);
}

// Colour by: "kind", "feed" or "order" (1: done, 0: no such name).
EMSCRIPTEN_KEEPALIVE int essi_set_colour_by(const char* name) {
    return g_api && g_api->set_colour_by(name ? name : "") ? 1 : 0;
}

// The theme: 1 light, 0 dark (kept across sessions).
EMSCRIPTEN_KEEPALIVE void essi_set_theme(int light) {
    if (g_api) g_api->set_light_theme(light != 0);
}

// The examples the server offers: a JSON array of names (essi serve's /examples/index.json).
EMSCRIPTEN_KEEPALIVE void essi_set_examples(const char* json_names) {
    if (!g_api || !json_names) return;
    const nlohmann::json j = nlohmann::json::parse(json_names, nullptr, false);
    std::vector<std::string> names;
    if (j.is_array())
        for (const auto& n : j)
            if (n.is_string()) names.push_back(essi::display_text(n.get<std::string>()));
    g_api->set_examples(std::move(names));
}

// Reads the tape again with another profile: a built-in name or "auto".
EMSCRIPTEN_KEEPALIVE void essi_set_profile(const char* name) {
    if (g_api) g_api->set_profile(name ? name : "auto");
}

// Reads a share link's fragment (essi/share_link.hpp) for the page: {name, line, view: [x, y, zoom] | null, share,
// profile, problems: [...], packed_len}; the tape's packed (deflate-raw) bytes stay at essi_share_packed() until
// the next call, for the page to inflate.
namespace {
std::string g_share_packed;
std::string g_share_json;
}  // namespace

EMSCRIPTEN_KEEPALIVE const char* essi_parse_share(const char* fragment) {
    essi::ShareLink link = essi::parse_share_fragment(fragment ? fragment : "");
    nlohmann::json j;
    j["name"] = essi::display_text(link.name);
    j["line"] = link.line;
    j["view"] = link.view ? nlohmann::json::array({link.view->x, link.view->y, link.view->zoom}) : nlohmann::json();
    j["share"] = link.store_id;
    j["profile"] = link.profile;
    j["input"] = link.input ? essi::input_format_name(*link.input) : "";
    j["bytes"] = link.tape_bytes ? nlohmann::json(*link.tape_bytes) : nlohmann::json();
    j["problems"] = link.problems;
    j["packed_len"] = link.packed.size();
    g_share_packed = std::move(link.packed);
    g_share_link = std::move(link);
    g_share_json = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return g_share_json.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* essi_share_packed() { return g_share_packed.data(); }

// The tape converted or drawn as the Export menu makes it ("essi", "eia", "gcode", "dxf"), for the page's tests.
namespace {
std::string g_export;
}
EMSCRIPTEN_KEEPALIVE const char* essi_export(const char* format) {
    g_export = g_api ? g_api->export_text(format ? format : "") : std::string();
    return g_export.c_str();
}

// The glyphs of a text (UTF-8) into the panels' font atlas (UiFonts::require_glyphs: the CJK font is fetched once,
// when a character needs it); essi_has_glyphs: 1 when the atlas has every character of the text.
EMSCRIPTEN_KEEPALIVE void essi_require_glyphs(const char* text) {
    if (g_api && text) g_api->require_glyphs(text);
}
EMSCRIPTEN_KEEPALIVE int essi_has_glyphs(const char* text) { return g_api && text && g_api->has_glyphs(text) ? 1 : 0; }

// Makes a share link as the Share button does; the page's essikitShare finishes it.
EMSCRIPTEN_KEEPALIVE void essi_share() {
    if (g_api) g_api->share();
}

// The page made the link (ok: `text` is the URL) or could not (`text`: {"kind", "args"}, page_phrase).
EMSCRIPTEN_KEEPALIVE void essi_share_done(int ok, const char* text) {
    if (!g_api) return;
    if (ok != 0) g_api->share_done(text ? text : "");
    else g_api->share_failed(page_phrase(text));
}

}  // extern "C"
