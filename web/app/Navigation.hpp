// Where the drawing is looked at and what is selected: the View (centre, zoom, the machine's orientation, the plate's
// turn in machine coordinates), the Selection, program or machine coordinates. A view or a selection asked for while
// a tape is being read waits for it (ViewRequest) and replaces the fit then.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "app/Coordinates.hpp"
#include "app/PlatformServices.hpp"
#include "app/Selection.hpp"
#include "app/View.hpp"
#include "essi/geom.hpp"

namespace essi::viewer {

class LoadController;
class Playback;
struct Document;

struct ViewRequest {
    double x = 0, y = 0, zoom = 0;  // machine mm at the centre, pixels per mm (zoom 0: fit)
    std::uint32_t line = 0;         // selected line (0: none)
};

class Navigation {
public:
    static constexpr const char* kOrientationSetting = "orientation";
    static constexpr const char* kCoordinatesSetting = "coordinates";
    static constexpr float kContourMarginPx = 80;  // show_box's margin around the box
    static constexpr double kProblemViewMm = 20;   // a problem shown: at least this much of the tape around it

    // The orientation and the coordinates as they were kept.
    Navigation(const LoadController& load, SettingsStore& settings);

    [[nodiscard]] View& view() { return view_; }
    [[nodiscard]] const View& view() const { return view_; }
    [[nodiscard]] Selection& selection() { return selection_; }
    [[nodiscard]] const Selection& selection() const { return selection_; }

    void fit();
    void set_view(double x, double y, double zoom);  // machine mm, px/mm; kept until a load completes
    void select_line(std::uint32_t line, bool reveal = true);
    void select_motion(std::size_t motion);
    // A diagnostic chosen (its mark clicked, as a click in the problems list): its block selected and in view.
    void select_diagnostic(std::size_t index);
    // A diagnostic shown ("next problem", "previous problem"): its block selected and the view zoomed to what it
    // concerns (its block and contour, else its mark), at least kProblemViewMm across.
    void show_problem(std::size_t index);
    // The diagnostic after (step 1) or before (-1) the one shown last, going round (N, Shift+N).
    void step_problem(int step);
    // The diagnostic shown last (npos: none since the tape was loaded).
    [[nodiscard]] std::size_t problem() const { return problem_; }
    // The box (program mm) in view with a margin (a compared contour).
    void show_box(const Box& box);
    // The source view and the inspector show the playback's line (the view stays where the user put it).
    void follow(const Document& d, const Playback& playback);

    // The machine's view orientation (View::turns, Orientation): kept across sessions.
    void set_orientation(int quarter_turns);
    // Program or machine coordinates (Coordinates): the numbers, the grid and the drawing's turn; kept across
    // sessions.
    void set_machine_coordinates(bool machine);
    [[nodiscard]] bool machine_coordinates() const { return machine_coordinates_; }
    // The coordinates shown: the machine's through the document's profile, or the program's.
    [[nodiscard]] Coordinates coordinates() const;
    // The document's origin (GPU and view coordinates are relative to it).
    [[nodiscard]] Point origin() const;
    // The part of the program the drawing area shows (program mm; its box when the view is turned).
    [[nodiscard]] Box visible_box() const;

    // The view and the selected line as they are (kept when the tape is read again).
    [[nodiscard]] ViewRequest current() const;
    // The view to give the document being read (none: fitted).
    void request(std::optional<ViewRequest> view) { pending_ = view; }
    // A new document is read: the selection cleared, the view fitted to it or as requested.
    void document_loaded(const Document& d);

private:
    // The document, when no other is being read (a view or a selection asked for waits for that one then).
    [[nodiscard]] const Document* settled_document() const;
    void apply_request(const Document& d);
    void reveal_motions(const Document& d, std::size_t first, std::size_t last);

    const LoadController& load_;
    SettingsStore& settings_;
    View view_;
    Selection selection_;
    bool machine_coordinates_ = false;
    std::optional<ViewRequest> pending_;     // set_view / select_line before the document is there
    std::size_t problem_ = Selection::npos;  // the diagnostic shown last (show_problem)
};

}  // namespace essi::viewer
