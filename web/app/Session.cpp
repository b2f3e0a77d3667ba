#include "app/Session.hpp"

#include <algorithm>
#include <utility>

#include <nlohmann/json.hpp>

#include "app/Display.hpp"
#include "app/Problems.hpp"
#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "essi/sniff.hpp"
#include "essi/text.hpp"
#include "essi/text_encoding.hpp"

namespace essi::viewer {

namespace {

// A problem with the whole file, shown over the drawing area (None when there is none; Session::banner_text).
Msg banner_for(const Document& d) {
    if (d.bytes.empty()) return Msg::UiBannerEmpty;
    if (looks_binary(d.bytes)) return Msg::UiBannerBinary;  // essi/sniff.hpp
    if (d.motions.empty() && d.has_errors()) return Msg::UiBannerNotTape;
    if (d.motions.empty()) return Msg::UiBannerNoMotion;
    return Msg::None;
}

// The recent names as one setting: a JSON array (one line).
std::vector<std::string> recent_from_setting(const std::optional<std::string>& text) {
    std::vector<std::string> names;
    if (!text) return names;
    const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
    if (!j.is_array()) return names;
    for (const auto& n : j)
        if (n.is_string() && names.size() < Session::kRecentNames) names.push_back(display_text(n.get<std::string>()));
    return names;
}

// The first diagnostic's message, or "?" (a profile that could not be read).
std::string first_problem(const std::vector<Diagnostic>& diagnostics) {
    return diagnostics.empty() ? std::string("?") : diagnostic_message(diagnostics.front(), ui_lang());
}

}  // namespace

Session::Session(const Parts& parts)
    : load_(parts.load), navigation_(parts.navigation), playback_(parts.playback), measure_(parts.measure),
      compare_(parts.compare), comments_(parts.comments), notices_(parts.notices), fonts_(parts.fonts), ui_(parts.ui),
      settings_(parts.settings) {
    recent_ = recent_from_setting(settings_.load_setting(kRecentSetting));
    for (const std::string& name : recent_) fonts_.require_glyphs(name);
}

void Session::load(std::string name, std::string bytes) {
    if (use_profile_file(name, bytes)) return;
    if (!take_tape_text(name, bytes)) return;
    if (compare_.pending() && document()) return compare_with(std::move(name), bytes);
    compare_.forget();      // (a new tape: a comparison was of the one before)
    input_format_.reset();  // (a new tape: its content says what it is)
    link_problem_ = {};
    read(std::move(name), std::move(bytes), std::nullopt);
}

void Session::load_shared(std::string name, std::string bytes, const ShareLink& link) {
    use_link_profile(link);
    input_format_ = link.input;
    link_problem_ = {};
    read(std::move(name), std::move(bytes), std::nullopt);
}

void Session::compare_with(std::string name, const std::string& bytes) {
    compare_.compare_with(document(), profile_name_ == kAutoProfile, std::move(name), bytes);
}

// The text of a file opened as a tape (essi::decode_tape_text: UTF-16 becomes UTF-8), or false when the core says
// it is no tape (essi::not_a_tape: empty, a picture, an archive, binary): the toolbar says so, the open tape stays.
bool Session::take_tape_text(const std::string& name, std::string& bytes) {
    TapeText text = decode_tape_text(bytes);
    const Message problem = text.ok() ? not_a_tape(text.decoded ? *text.decoded : bytes) : text.problem;
    if (problem.msg != Msg::None) {
        if (const Document* d = document())
            notices_.notify(Msg::UiNotATapeKept, {display_text(name), problem, display_text(d->name)});
        else notices_.notify(Msg::UiNotATape, {display_text(name), problem});
        return false;
    }
    if (text.decoded) bytes = std::move(*text.decoded);
    return true;
}

// A dropped `.json` file is a profile (as `essi check --profile FILE` reads one): the tape is checked again with
// it. True when `name` is such a file (used or refused, with a message).
bool Session::use_profile_file(const std::string& name, const std::string& bytes) {
    const bool json = name.size() > 5 && (name.ends_with(".json") || name.ends_with(".JSON"));
    if (!json) return false;
    const ProfileResult r = parse_profile(bytes);
    if (!r.profile) {
        notices_.notify(Msg::UiNotAProfile, {display_text(name), first_problem(r.diagnostics)});
        return true;
    }
    dropped_profile_ = r.profile;
    notices_.notify(Msg::UiProfileFrom, {display_text(r.profile->name), display_text(name)});
    set_profile(r.profile->name);
    return true;
}

// The link's profile becomes the choice: a user profile it carries, a built-in name, or auto (a name this viewer
// does not know is said, and auto used).
void Session::use_link_profile(const ShareLink& link) {
    if (!link.profile_json.empty()) {
        const ProfileResult r = parse_profile(link.profile_json);
        if (r.profile) {
            dropped_profile_ = r.profile;
            profile_name_ = r.profile->name;
            return;
        }
        notices_.notify(Msg::UiLinkProfileUnreadable, {first_problem(r.diagnostics)});
        profile_name_ = std::string(kAutoProfile);
        return;
    }
    if (link.profile.empty() || link.profile == kAutoProfile || builtin_profile(link.profile)) {
        profile_name_ = link.profile.empty() ? std::string(kAutoProfile) : link.profile;
        return;
    }
    notices_.notify(Msg::UiLinkProfileUnknown, {display_text(link.profile)});
    profile_name_ = std::string(kAutoProfile);
}

void Session::set_profile(const std::string& name) {
    profile_name_ = name;
    if (const Document* d = document()) read(d->name, d->bytes, navigation_.current());
}

void Session::read(std::string name, std::string bytes, std::optional<ViewRequest> view) {
    // "auto": the dialect the tape's evidence shows (essi/dialect.hpp), as `essi check --profile auto`.
    std::optional<Profile> profile;
    if (dropped_profile_ && profile_name_ == dropped_profile_->name) profile = dropped_profile_;
    else if (profile_name_ != kAutoProfile) profile = builtin_profile(profile_name_);
    TapeSetup setup = setup_tape(bytes, input_format_, profile);
    load_.start(std::move(name), std::move(bytes), std::move(setup));
    navigation_.request(view);
    playback_.stop();
    measure_.points = 0;
    // A tape loaded at once (LoadController::kAtOnceBytes) handed over between frames (a drop, the page's API) is
    // read, checked and its drawing made and uploaded here, so the next frame shows it. Inside a frame (the
    // panels may hold the document this replaces) or before the first one (no drawing area to fit the view to
    // yet), the next frame's step does it before anything is drawn.
    if (load_.at_once() && !in_frame_ && frames_ > 0) step();
}

void Session::begin_frame() {
    load_.begin_frame(++frames_);
    in_frame_ = true;
    step();
}

bool Session::background_step() {
    if (!load_.may_step_outside_frame()) return true;
    step();
    return load_.has_work();
}

void Session::step() {
    if (load_.step()) document_loaded();
}

// A new document was read: the selection, the view and the playback start over, then its drawing is made.
void Session::document_loaded() {
    const Document& d = *document();
    remember_name(display_text(d.name));
    comments_.detect(d);
    ui_.hovered_mark = kNoMark;
    banner_ = banner_for(d);
    navigation_.document_loaded(d);
    playback_.position = static_cast<double>(d.motions.size());
    const View& view = navigation_.view();
    load_.begin_drawing(view.chord_tolerance_mm(), view.zoom, framebuffer_scale());
}

// The name first among the recent ones (names only: the tapes themselves are not kept).
void Session::remember_name(const std::string& name) {
    fonts_.require_glyphs(name);  // (a Chinese file name: the CJK font)
    std::erase(recent_, name);
    recent_.insert(recent_.begin(), name);
    if (recent_.size() > kRecentNames) recent_.resize(kRecentNames);
    settings_.save_setting(kRecentSetting, nlohmann::json(recent_).dump(-1, ' ', true));
}

std::string Session::banner_text() const {
    const Document* d = document();
    if (!d || banner_ == Msg::None) return {};
    if (banner_ != Msg::UiBannerNotTape) return tr(banner_);
    const Diagnostic& first = d->diagnostics.front();
    return tr(banner_, {d->count(Severity::Error), first.line, diagnostic_message(first, ui_lang())});
}

}  // namespace essi::viewer
