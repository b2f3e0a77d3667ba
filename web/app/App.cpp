#include "app/App.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "app/Language.hpp"
#include "app/Problems.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/geom.hpp"
#include "essi/lines.hpp"
#include "essi/profile.hpp"
#include "essi/render_svg.hpp"
#include "essi/share_link.hpp"
#include "essi/dxf.hpp"
#include "essi/write.hpp"
#include "essi/sniff.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer {

namespace {

App* g_app = nullptr;

constexpr double kMessageSeconds = 4;  // a toolbar message shows this long

// A problem with the whole file, shown over the drawing area (None when there is none; App::banner_text).
Msg banner_for(const Document& d) {
    if (d.bytes.empty()) return Msg::UiBannerEmpty;
    if (looks_binary(d.bytes)) return Msg::UiBannerBinary;  // essi/sniff.hpp
    if (d.motions.empty() && d.has_errors()) return Msg::UiBannerNotTape;
    if (d.motions.empty()) return Msg::UiBannerNoMotion;
    return Msg::None;
}

// The side panels as one setting: {"left", "right", "left_shown", "right_shown"} (one line).
panels::PanelLayout layout_from_setting(const std::optional<std::string>& text) {
    panels::PanelLayout l;
    if (!text) return l;
    const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
    if (!j.is_object()) return l;
    const auto width = [&](const char* k, float& to) {
        if (j.contains(k) && j[k].is_number() && j[k].get<double>() >= panels::kMinPanelWidth && j[k].get<double>() <= 4000)
            to = j[k].get<float>();
    };
    width("left", l.left);
    width("right", l.right);
    if (j.contains("left_shown") && j["left_shown"].is_boolean()) l.left_shown = j["left_shown"].get<bool>();
    if (j.contains("right_shown") && j["right_shown"].is_boolean()) l.right_shown = j["right_shown"].get<bool>();
    return l;
}
std::string layout_setting(const panels::PanelLayout& l) {
    return nlohmann::json{{"left", l.left}, {"right", l.right}, {"left_shown", l.left_shown}, {"right_shown", l.right_shown}}.dump();
}

// The recent names as one setting: a JSON array (one line).
std::vector<std::string> recent_from_setting(const std::optional<std::string>& text) {
    std::vector<std::string> names;
    if (!text) return names;
    const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
    if (!j.is_array()) return names;
    for (const auto& n : j)
        if (n.is_string() && names.size() < App::kRecentNames) names.push_back(display_text(n.get<std::string>()));
    return names;
}
}  // namespace

App::App(GLFWwindow* window) : window_(window) {
    g_app = this;
    view_.turns = ((platform::load_setting(kOrientationSetting).value_or(0) % 4) + 4) % 4;  // (kept across sessions)
    ui_.recent = recent_from_setting(platform::load_text_setting(kRecentSetting));
    for (const std::string& name : ui_.recent) fonts_.require_glyphs(name);
    ui_.layout = layout_from_setting(platform::load_text_setting(kLayoutSetting));
    machine_coordinates_ = platform::load_setting(kCoordinatesSetting).value_or(0) == 1;
    layers_.problems_only = platform::load_setting(kProblemsOnlySetting).value_or(0) == 1;
    set_language(startup_language(), false);
}

void App::set_problems_only(bool on) {
    layers_.problems_only = on;
    platform::save_setting(kProblemsOnlySetting, on ? 1 : 0);
}

void App::set_orientation(int quarter_turns) {
    view_.turns = ((quarter_turns % 4) + 4) % 4;
    platform::save_setting(kOrientationSetting, view_.turns);
}

void App::set_machine_coordinates(bool machine) {
    machine_coordinates_ = machine;
    platform::save_setting(kCoordinatesSetting, machine ? 1 : 0);
    view_.plate = coordinates().plate();  // (the drawing turns about the view's centre)
}

Coordinates App::coordinates() const {
    const Document* d = document();
    return machine_coordinates_ && d ? Coordinates(d->profile) : Coordinates();
}
App::~App() {
    if (g_app == this) g_app = nullptr;
}
App* App::instance() { return g_app; }

bool App::init_graphics() {
    fonts_.update(framebuffer_scale());  // (the atlas, before ui_renderer_ uploads it)
    graphics_ok_ = renderer_.init() && ui_renderer_.init();
    load_.set_graphics(graphics_ok_);
    ImGuiIO& io = ImGui::GetIO();
    if (!io.Fonts->IsBuilt()) io.Fonts->Build();  // (ui_renderer_.init() makes the atlas unless the GPU refused it)
    io.IniFilename = nullptr;  // no imgui.ini: the layout is fixed
    set_light_theme(platform::load_setting(kThemeSetting).value_or(0) == 1);
    chosen_encoding_ = parse_text_encoding(platform::load_text_setting(kTextEncodingSetting).value_or("auto"));
    return graphics_ok_;
}

void App::set_light_theme(bool light) {
    if (light) ImGui::StyleColorsLight();
    else ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0;
    st.FrameRounding = 3;
    st.WindowBorderSize = 0;
    if (graphics_ok_) renderer_.set_theme(light ? kLightTheme : kDarkTheme);
    platform::save_setting(kThemeSetting, light ? 1 : 0);
}

// ---------------------------------------------------------------------------------------------------------
// Loading
// ---------------------------------------------------------------------------------------------------------
// A dropped `.json` file is a profile (as `essi check --profile FILE` reads one): the tape is checked again with
// it. True when `name` is such a file (used or refused, with a message).
bool App::use_profile_file(const std::string& name, const std::string& bytes) {
    const bool json = name.size() > 5 && (name.ends_with(".json") || name.ends_with(".JSON"));
    if (!json) return false;
    const ProfileResult r = parse_profile(bytes);
    if (!r.profile) {
        notify(Msg::UiNotAProfile, {display_text(name), r.diagnostics.empty() ? std::string("?") : diagnostic_message(r.diagnostics.front(), ui_lang())});
        return true;
    }
    dropped_profile_ = r.profile;
    notify(Msg::UiProfileFrom, {display_text(r.profile->name), display_text(name)});
    set_profile(r.profile->name);
    return true;
}

void App::load(std::string name, std::string bytes, std::optional<ViewRequest> view) {
    if (use_profile_file(name, bytes)) return;
    if (compare_next_ && document()) return compare_with(std::move(name), bytes);
    compare_.reset();  // (a new tape: a comparison was of the one before)
    input_format_.reset();  // (a new tape: its content says what it is)
    ui_.link_problem = {};
    read(std::move(name), std::move(bytes), view);
}

void App::load_shared(std::string name, std::string bytes, const ShareLink& link) {
    use_link_profile(link);
    input_format_ = link.input;
    ui_.link_problem = {};
    read(std::move(name), std::move(bytes), std::nullopt);
}

// The link's profile becomes the choice: a user profile it carries, a built-in name, or auto (a name this viewer
// does not know is said, and auto used).
void App::use_link_profile(const ShareLink& link) {
    if (!link.profile_json.empty()) {
        const ProfileResult r = parse_profile(link.profile_json);
        if (r.profile) {
            dropped_profile_ = r.profile;
            profile_name_ = r.profile->name;
            return;
        }
        notify(Msg::UiLinkProfileUnreadable, {r.diagnostics.empty() ? std::string("?") : diagnostic_message(r.diagnostics.front(), ui_lang())});
        profile_name_ = std::string(kAutoProfile);
        return;
    }
    if (link.profile.empty() || link.profile == kAutoProfile || builtin_profile(link.profile)) {
        profile_name_ = link.profile.empty() ? std::string(kAutoProfile) : link.profile;
        return;
    }
    notify(Msg::UiLinkProfileUnknown, {display_text(link.profile)});
    profile_name_ = std::string(kAutoProfile);
}

void App::link_problem(Phrase why) { ui_.link_problem = std::move(why); }

void App::begin_compare() {
    const Document* d = document();
    if (!d) return notify(Msg::UiLoadFirstCompare);
    compare_next_ = true;
    notify(Msg::UiDropOtherRevision, {display_text(d->name)});
}

void App::compare_with(std::string name, const std::string& bytes) {
    compare_next_ = false;
    const Document* d = document();
    if (!d) return;
    fonts_.require_glyphs(name);
    compare_ = make_compare(*d, profile_name_ == kAutoProfile, std::move(name), bytes);
    notify(Msg::UiComparedWith, {display_text(compare_->name), diff_counts_message(compare_->diff)});
}

void App::end_compare() {
    compare_.reset();
    compare_next_ = false;
}

void App::show_contour(std::size_t index, bool of_b) {
    if (!compare_) return;
    const auto& contours = of_b ? compare_->b.contours : compare_->a.contours;
    if (index >= contours.size()) return;
    const DiffContour& c = contours[index];
    if (!of_b) select_line(c.first_line, false);
    const Document* d = document();
    if (d) view_.fit(c.box, d->origin, 80);
}

void App::set_examples(std::vector<std::string> names) {
    for (const std::string& name : names) fonts_.require_glyphs(name);
    ui_.examples = std::move(names);
}

void App::set_layout(const panels::PanelLayout& layout) {
    panels::PanelLayout l = layout;
    if (!(l.left > 0)) l.left = ui_.layout.left;
    if (!(l.right > 0)) l.right = ui_.layout.right;
    l.left = std::max(l.left, panels::kMinPanelWidth);
    l.right = std::max(l.right, panels::kMinPanelWidth);
    ui_.layout = l;
    platform::save_text_setting(kLayoutSetting, layout_setting(l));
}


void App::read(std::string name, std::string bytes, std::optional<ViewRequest> view) {
    // "auto": the dialect the tape's evidence shows (essi/dialect.hpp), as `essi check --profile auto`.
    std::optional<Profile> profile;
    if (dropped_profile_ && profile_name_ == dropped_profile_->name) profile = dropped_profile_;
    else if (profile_name_ != kAutoProfile) profile = builtin_profile(profile_name_);
    TapeSetup setup = setup_tape(bytes, input_format_, profile);
    load_.start(std::move(name), std::move(bytes), std::move(setup));
    pending_view_ = view;
    playback_.stop();
    input_.measure.points = 0;
    // A tape loaded at once (LoadController::kAtOnceBytes) handed over between frames (a drop, the page's API) is
    // read, checked and its drawing made and uploaded here, so the next frame shows it. Inside a frame (the
    // panels may hold the document this replaces) or before the first one (no drawing area to fit the view to
    // yet), the next frame's step_loading does it before anything is drawn.
    if (load_.at_once() && !in_frame_ && frames_ > 0) step_loading();
}

void App::set_profile(const std::string& name) {
    profile_name_ = name;
    if (const Document* d = document()) {
        const ViewRequest keep{view_.cx + d->origin.x, view_.cy + d->origin.y, view_.zoom, selection_.line};
        read(d->name, d->bytes, keep);
    }
}

void App::step_loading() {
    if (load_.step()) document_loaded();
}

bool App::background_step() {
    if (!load_.may_step_outside_frame()) return true;
    step_loading();
    return has_background_work();
}

// A new document was read: the selection, the view and the playback start over, then its drawing is made.
void App::document_loaded() {
    const Document& d = *document();
    // The name first among the recent ones (names only: the tapes themselves are not kept).
    const std::string name = display_text(d.name);
    fonts_.require_glyphs(name);  // (a Chinese file name: the CJK font)
    detected_encoding_ = detect_text_encoding(d.bytes);
    require_comment_glyphs(d);
    std::erase(ui_.recent, name);
    ui_.recent.insert(ui_.recent.begin(), name);
    if (ui_.recent.size() > kRecentNames) ui_.recent.resize(kRecentNames);
    platform::save_text_setting(kRecentSetting, nlohmann::json(ui_.recent).dump(-1, ' ', true));
    selection_.clear();
    ui_.hovered_mark = kNoMark;
    ui_.banner = banner_for(d);
    view_.plate = coordinates().plate();
    view_.fit(d.bbox, d.origin);
    apply_pending_view(d);
    playback_.position = static_cast<double>(d.motions.size());
    load_.begin_drawing(desired_tolerance(), view_.zoom, framebuffer_scale());
}

// The glyphs of the tape's text beyond ASCII (Chinese comments: the CJK font), from the lines that have such
// bytes (at most kMaxLineBytes of each), up to kMaxGlyphText bytes of text.
void App::require_comment_glyphs(const Document& d) {
    constexpr std::size_t kMaxGlyphText = 256 * 1024, kMaxLineBytes = 4096;
    std::string text;
    for (std::size_t at = 0; text.size() < kMaxGlyphText;) {
        const auto high = std::find_if(d.bytes.begin() + static_cast<std::ptrdiff_t>(at), d.bytes.end(),
                                       [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
        if (high == d.bytes.end()) break;
        const std::string_view bytes = d.bytes;
        const std::size_t i = static_cast<std::size_t>(high - d.bytes.begin());
        const std::size_t begin = find_line_start(bytes, i), end = find_line_end(bytes, i);
        text += decode_text(bytes.substr(begin, std::min(end - begin, kMaxLineBytes)), text_encoding());
        at = end;
    }
    if (!text.empty()) fonts_.require_glyphs(text);
}

void App::set_text_encoding(std::optional<TextEncoding> chosen) {
    chosen_encoding_ = chosen;
    platform::save_text_setting(kTextEncodingSetting, chosen ? std::string(text_encoding_name(*chosen)) : "auto");
    if (const Document* d = document()) require_comment_glyphs(*d);
}

std::string App::line_text(const Document& d, std::size_t line, std::size_t max) const {
    const std::string_view bytes = d.line(line);
    const std::string_view shown = bytes.substr(0, max);
    const bool ascii = std::all_of(shown.begin(), shown.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
    if (ascii) return printable(bytes, max);
    std::string text = decode_text(shown, text_encoding());
    std::replace(text.begin(), text.end(), '\t', ' ');
    if (bytes.size() > max) text += " ...";
    return text;
}

void App::apply_pending_view(const Document& d) {
    if (!pending_view_) return;
    const ViewRequest v = *pending_view_;
    if (v.zoom > 0) {
        view_.zoom = std::clamp(v.zoom, View::kMinZoom, View::kMaxZoom);
        view_.cx = v.x - d.origin.x;
        view_.cy = v.y - d.origin.y;
    }
    if (v.line > 0) select_line(v.line, false);
    pending_view_.reset();
}

double App::desired_tolerance() const { return view_.chord_tolerance_mm(); }

// The window's pixels: its size times the framebuffer scale (a hi-DPI screen's device pixel ratio: the browser's
// canvas is that much larger than the page's CSS pixels, MainLoopEmscripten.cpp).
std::pair<int, int> App::framebuffer_size() const {
    const ImGuiIO& io = ImGui::GetIO();
    return {static_cast<int>(std::lround(io.DisplaySize.x * framebuffer_scale())),
            static_cast<int>(std::lround(io.DisplaySize.y * framebuffer_scale()))};
}

float App::framebuffer_scale() const {
    const float s = ImGui::GetIO().DisplayFramebufferScale.x;
    return s > 0 ? s : 1.f;
}

// ---------------------------------------------------------------------------------------------------------
// Frame
// ---------------------------------------------------------------------------------------------------------
void App::frame() {
    ImGuiIO& io = ImGui::GetIO();
    if (ui_.layout_changed && !ImGui::IsMouseDown(0)) {  // (a drag of a panel's edge is saved once, at its end)
        ui_.layout_changed = false;
        platform::save_text_setting(kLayoutSetting, layout_setting(ui_.layout));
    }
    view_.area = panels::drawing_area(io.DisplaySize.x, io.DisplaySize.y, ui_.layout);
    load_.begin_frame(++frames_);
    in_frame_ = true;
    step_loading();
    view_.plate = coordinates().plate();
    if (const Document* d = document(); d && playback_.playing) {
        playback_.advance(io.DeltaTime, *d);
        follow_playback(*d);
    }
    input_.handle_shortcuts(*this);
    input_.handle_canvas(*this);
    load_.maybe_rebuild(desired_tolerance());
    draw_panels();

    // The scene (drawn by render(), below the panels)
    const auto [fb_w, fb_h] = framebuffer_size();
    const SceneInputs in{view_,     fb_w,      fb_h,       framebuffer_scale(), panels::panel_color(renderer_.theme().background),
                         layers_,   playback_, selection_, load_,           coordinates().shown(origin()),
                         ui_.hovered_mark};
    const bool prepared = scene_.prepare(in, renderer_, graphics_ok_);
    load_.note_frame(prepared && scene_.tape_drawn());
    in_frame_ = false;
    if (selection_.line != announced_.line || selection_.motion != announced_.motion) {
        announced_ = selection_;
        platform::selection_changed(selection_.line, selection_.motion == Selection::npos
                                                         ? -1 : static_cast<long long>(selection_.motion));
    }
}

void App::draw_panels() {
    panels::toolbar(*this);
    panels::tape_panel(*this);
    panels::source_panel(*this);
    panels::overlays(*this);
    panels::messages(*this);
    if (ui_.help) panels::help(*this);
}

void App::render(bool keep_unchanged) {
    if (!graphics_ok_) return;
    const auto [fb_w, fb_h] = framebuffer_size();
    const bool png = png_pending_ && document();
    scene_.render(renderer_, ui_renderer_, fb_w, fb_h, keep_unchanged && !png && !fonts_changed_);
    load_.note_rendered(scene_.tape_drawn(), renderer_.filling());
    // Between frames: the atlas at the screen's pixel ratio, with the glyphs asked for (UiFonts); the next frame
    // draws with it.
    fonts_.require_language(ui_lang());
    fonts_changed_ = fonts_.update(framebuffer_scale());
    if (fonts_changed_) ui_renderer_.upload_fonts();
    if (!png) return;
    png_pending_ = false;
    // The drawing area of the frame just drawn, in the framebuffer's pixels (top-left origin).
    const float s = framebuffer_scale();
    const Rect& a = view_.area;
    const std::string& name = document()->name;
    platform::save_view_png(*this, name.substr(0, name.find_last_of('.')) + ".view.png",
                            {a.x * s, a.y * s, a.w * s, a.h * s});
}

void App::export_view_png() {
    if (!document()) return notify(Msg::UiLoadFirst);
    png_pending_ = true;  // (taken in the next frame, right after it is drawn)
}

Box App::visible_box() const {
    const Rect& a = view_.area;
    const Point o = origin();
    Box b;
    for (const auto& [x, y] : {std::pair{a.x, a.y}, {a.x + a.w, a.y}, {a.x, a.y + a.h}, {a.x + a.w, a.y + a.h}}) {
        const Point w = view_.to_world(x, y);
        b.add(Point{w.x + o.x, w.y + o.y});
    }
    return b;
}

// ---------------------------------------------------------------------------------------------------------
// View and selection
// ---------------------------------------------------------------------------------------------------------
void App::fit() {
    if (const Document* d = document()) view_.fit(d->bbox, d->origin);
}

void App::set_view(double x, double y, double zoom) {
    const Document* d = document();
    if (load_.reading() || !d) {
        ViewRequest v = pending_view_.value_or(ViewRequest{});
        v.x = x;
        v.y = y;
        v.zoom = zoom;
        pending_view_ = v;
        return;
    }
    view_.zoom = std::clamp(zoom, View::kMinZoom, View::kMaxZoom);
    view_.cx = x - d->origin.x;
    view_.cy = y - d->origin.y;
}

void App::follow_playback(const Document& d) {
    if (d.motions.empty()) return;
    const std::uint32_t line = d.motions[playback_.at(d.motions.size()).motion].line;
    if (line != selection_.line) select_line(line, false);  // (the view stays where the user put it)
}

void App::select_line(std::uint32_t line, bool reveal) {
    const Document* d = document();
    if (load_.reading() || !d) {
        ViewRequest v = pending_view_.value_or(ViewRequest{});
        v.line = line;
        pending_view_ = v;
        return;
    }
    selection_.line = line;
    selection_.motion = npos;
    selection_.scroll_source = true;
    const auto [a, b] = d->motions_of_line(line);
    if (a >= b) return;
    selection_.motion = a;
    if (!reveal) return;
    // The line's motions into view when they are not all in it.
    Box box;
    for (std::size_t i = a; i < b; ++i) box.add(bounding_box(d->record(i)));
    const Rect& r = view_.area;
    bool inside = true;  // (every corner: the view may be turned)
    for (const double x : {box.min_x, box.max_x})
        for (const double y : {box.min_y, box.max_y}) {
            const Point p = view_.to_screen({x - d->origin.x, y - d->origin.y});
            inside = inside && r.contains(static_cast<float>(p.x), static_cast<float>(p.y));
        }
    if (!inside) {
        view_.cx = (box.min_x + box.max_x) / 2 - d->origin.x;
        view_.cy = (box.min_y + box.max_y) / 2 - d->origin.y;
    }
}

void App::select_diagnostic(std::size_t index) {
    const Document* d = document();
    if (d && index < d->diagnostics.size() && d->diagnostics[index].line > 0) select_line(d->diagnostics[index].line);
}

void App::select_motion(std::size_t motion) {
    const Document* d = document();
    if (!d || motion >= d->motions.size()) {
        selection_.clear();
        return;
    }
    selection_.motion = motion;
    selection_.line = d->motions[motion].line;
    selection_.scroll_source = true;
}

// ---------------------------------------------------------------------------------------------------------
// Messages and share links
// ---------------------------------------------------------------------------------------------------------
void App::notify(Msg id, const MessageArgs& args) {
    ui_.message = {id, args};
    fonts_.require_glyphs(ui_.message.text());  // (a name in it)
    ui_.message_until = glfwGetTime() + kMessageSeconds;
}

std::string App::banner_text() const {
    const Document* d = document();
    if (!d || ui_.banner == Msg::None) return {};
    if (ui_.banner != Msg::UiBannerNotTape) return tr(ui_.banner);
    const Diagnostic& first = d->diagnostics.front();
    return tr(ui_.banner, {d->count(Severity::Error), first.line, diagnostic_message(first, ui_lang())});
}

std::string App::share_query() const {
    const Point o = origin();
    const Document* d = document();
    const bool user_profile = dropped_profile_ && profile_name_ == dropped_profile_->name;
    return share_view_query({view_.cx + o.x, view_.cy + o.y, view_.zoom}, selection_.line) + "&" +
           share_reading_query(profile_name_, user_profile ? profile_to_json(*dropped_profile_) : std::string(),
                               d ? std::optional(d->setup.format) : std::nullopt);
}

FileReport App::report() const {
    FileReport r;
    const Document* d = document();
    if (!d) return r;
    r.path = d->name;
    r.result.stats = d->stats;
    r.result.diagnostics = d->diagnostics;
    r.result.input = d->setup.format;
    r.result.profile = d->profile.name;
    r.result.auto_profile = d->setup.auto_profile;
    r.result.dialect_evidence = d->setup.evidence;
    return r;
}

std::string App::copy_text(CopyWhat what, std::uint32_t index) const {
    const Document* d = document();
    if (!d) return {};
    switch (what) {
        case CopyWhat::Report: {
            const FileReport r = report();
            return file_report_text(r, false, ui_lang()) + summary_line(std::span<const FileReport>(&r, 1), profile_name_, ui_lang()) + "\n";
        }
        case CopyWhat::Diagnostic:
            return index < d->diagnostics.size() ? diagnostic_line(display_text(d->name), d->diagnostics[index], ui_lang()) + "\n" : "";
        case CopyWhat::Line: return std::string(d->line(index)) + "\n";
        case CopyWhat::Inspector: {
            const std::uint32_t line = selection_.line;
            std::string s = display_text(d->name) + ":" + std::to_string(line) + ": " + std::string(d->line(line)) + "\n";
            for (const Document::InspectorLine& l : d->inspector_lines(line, ui_lang())) s += l.text + "\n";
            for (const Diagnostic& diag : d->diagnostics)
                if (diag.line == line) s += diagnostic_line(display_text(d->name), diag, ui_lang()) + "\n";
            return s;
        }
    }
    return {};
}

void App::copy(CopyWhat what, std::uint32_t index) {
    const std::string text = copy_text(what, index);
    if (text.empty()) return notify(Msg::UiNothingToCopy);
    platform::copy_text(text);
    ui_.copied = text;
    static constexpr Msg kCopied[] = {Msg::UiCopiedReport, Msg::UiCopiedProblem, Msg::UiCopiedLine, Msg::UiCopiedInspector};
    notify(kCopied[static_cast<int>(what)]);
}

std::string App::export_text(const std::string& format) const {
    const Document* d = document();
    if (!d) return {};
    if (format == "dxf") return render_dxf(d->bytes, d->setup).text;
    if (format == "report-text") return copy_text(CopyWhat::Report);
    if (format == "view-svg") {
        RenderOptions o;
        o.title = display_text(d->name);
        o.view = visible_box();
        return render_svg(d->bytes, d->profile, o, d->setup.format).svg;
    }
    if (format == "report-json" || format == "report-csv") {
        const FileReport r = report();
        const std::span<const FileReport> one(&r, 1);
        return format == "report-csv" ? diagnostics_csv(one, ui_lang()) : report_to_json(one, profile_name_, ui_lang()).dump(2) + "\n";
    }
    ConvertOptions o;
    o.to = parse_output_format(format).value_or(OutputFormat::Essi);
    o.target = d->profile;
    o.absolute = format == "gcode";  // (G-code for LinuxCNC: absolute, as CAM posts write it)
    return convert_tape(d->bytes, d->setup, o).text;
}

void App::export_file(const std::string& format) {
    const Document* d = document();
    if (!d) return notify(Msg::UiLoadFirst);
    const std::string stem = d->name.substr(0, d->name.find_last_of('.'));
    const char* ext = format == "dxf"           ? ".dxf"
                      : format == "eia"         ? ".eia"
                      : format == "gcode"       ? ".ngc"
                      : format == "report-text" ? ".report.txt"
                      : format == "report-json" ? ".report.json"
                      : format == "report-csv"  ? ".problems.csv"
                      : format == "view-svg"    ? ".view.svg"
                                                : ".esi";
    platform::save_file(*this, stem + ext, export_text(format));
}

void App::share() {
    const Document* d = document();
    if (!d) return notify(Msg::UiLoadFirst);
    if (!platform::has_share_links()) return notify(Msg::UiShareBrowserOnly);
    platform::share(*this, d->name, d->bytes, share_query());  // (the page says when a tape is too large)
}

void App::share_done(std::string url) {
    ui_.share_url = std::move(url);
    ui_.share_problem = {};
    ui_.share_popup = true;
    notify(Msg::UiShareCopied);
}

void App::share_failed(Phrase why) {
    ui_.share_url.clear();
    ui_.share_problem = std::move(why);
    ui_.share_popup = true;
    notify(ui_.share_problem.id, ui_.share_problem.args);
}

std::string App::share_text() const { return ui_.share_problem.empty() ? ui_.share_url : ui_.share_problem.text(); }

}  // namespace essi::viewer
