// The tape the viewer shows: opening one (a file, a share link's tape, a profile file that reads it again), how it is
// read (the profile chosen, a dropped profile, a share link's input format), its loading over the frames
// (LoadController), and what a new tape starts over (the view, the selection, the playback, the measure, a
// comparison). It also keeps the names of the tapes opened last and the problem with the whole file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/CommentText.hpp"
#include "app/Compare.hpp"
#include "app/Language.hpp"
#include "app/LoadController.hpp"
#include "app/Measure.hpp"
#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "app/Playback.hpp"
#include "app/PlatformServices.hpp"
#include "app/UiState.hpp"
#include "essi/share_link.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer {

class Session {
public:
    static constexpr const char* kRecentSetting = "recent";
    static constexpr std::size_t kRecentNames = 8;

    // The parts a new tape starts over, and those that say what happened.
    struct Parts {
        LoadController& load;
        Navigation& navigation;
        Playback& playback;
        Measure& measure;
        CompareMode& compare;
        CommentText& comments;
        Notices& notices;
        UiFonts& fonts;
        UiState& ui;
        SettingsStore& settings;
    };
    // The recent names as they were kept.
    explicit Session(const Parts& parts);

    [[nodiscard]] const Document* document() const { return load_.document(); }
    [[nodiscard]] std::uint64_t documents_read() const { return load_.documents_read(); }

    // --- Opening ---
    // A file's bytes: a profile file (`.json`: the tape is read again with it), the other revision in compare
    // mode, or a tape to read (UTF-16 with a byte order mark as its text). A file that is no tape (empty, a picture,
    // an archive, binary: essi::not_a_tape) is said in the toolbar and leaves the open tape as it is.
    void load(std::string name, std::string bytes);
    // A share link's tape, read as its sender read it: the link's profile (a built-in name, or the user profile it
    // carries) and input format (essi/share_link.hpp). The page applies the link's view after it.
    void load_shared(std::string name, std::string bytes, const ShareLink& link);
    // Compare mode's other revision (CompareMode::compare_with, with the profile the tape is read with).
    void compare_with(std::string name, const std::string& bytes);
    // Reads the tape again with another profile ("auto", a built-in name or the dropped one's), keeping the view.
    void set_profile(const std::string& name);
    [[nodiscard]] const std::string& profile_name() const { return profile_name_; }
    // The profile file dropped on the page (docs/viewer.md), if any.
    [[nodiscard]] const std::optional<Profile>& dropped_profile() const { return dropped_profile_; }

    // A share link that could not be opened: why, over the start screen until a tape loads or it is closed.
    void set_link_problem(Phrase why) { link_problem_ = std::move(why); }
    [[nodiscard]] const Phrase& link_problem() const { return link_problem_; }
    void close_link_problem() { link_problem_ = {}; }

    // --- Over the frames ---
    // A frame begins: a slice of the loading (a new document read: what it starts over).
    void begin_frame();
    void end_frame() { in_frame_ = false; }
    // Frames begun so far (state().frame; the frame numbers of state().load, LoadController::LoadFrames).
    [[nodiscard]] std::uint64_t frames() const { return frames_; }
    // One slice of the loading outside a frame; returns whether work is left (LoadController::has_work).
    bool background_step();

    // A problem with the whole file ("not an ESSI tape ...") or None, and its sentence in the viewer's language.
    [[nodiscard]] Msg banner() const { return banner_; }
    [[nodiscard]] std::string banner_text() const;
    // The names of the last tapes opened (newest first), kept across sessions.
    [[nodiscard]] const std::vector<std::string>& recent() const { return recent_; }

private:
    bool use_profile_file(const std::string& name, const std::string& bytes);
    bool take_tape_text(const std::string& name, std::string& bytes);
    void use_link_profile(const ShareLink& link);
    void read(std::string name, std::string bytes,
              std::optional<ViewRequest> view);  // with the profile and format chosen
    void step();
    void document_loaded();
    void remember_name(const std::string& name);

    LoadController& load_;
    Navigation& navigation_;
    Playback& playback_;
    Measure& measure_;
    CompareMode& compare_;
    CommentText& comments_;
    Notices& notices_;
    UiFonts& fonts_;
    UiState& ui_;
    SettingsStore& settings_;

    std::string profile_name_ = std::string(kAutoProfile);  // a built-in profile, the dropped one, or "auto"
    std::optional<Profile> dropped_profile_;   // a profile file dropped on the page (its name is a choice too)
    std::optional<InputFormat> input_format_;  // the format a share link said the tape was read as (else the content's)
    Phrase link_problem_;
    Msg banner_ = Msg::None;
    std::vector<std::string> recent_;
    std::uint64_t frames_ = 0;  // frames begun
    bool in_frame_ = false;     // inside a frame: the panels may hold the document
};

}  // namespace essi::viewer
