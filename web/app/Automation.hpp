// The viewer's side of window.essikit (docs/viewer.md, "The page's API"; web/platform/ApiEmscripten.cpp turns the
// page's calls into these, and the desktop viewer's --state writes state_json): what the page reads — the state and
// a motion as JSON, where a point is drawn, the tape exported — and what it asks the viewer to do. The JSON's
// content is what tests/e2e and docs/viewer.md rely on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/ProblemList.hpp"
#include "app/ViewerParts.hpp"
#include "essi/share_link.hpp"
#include "essi/text_encoding.hpp"

namespace essi::viewer {

class Automation {
public:
    using Parts = ViewerParts;
    explicit Automation(const Parts& parts) : p_(parts) {}

    // --- What the page reads (AutomationState.cpp) ---
    // state(): {status, name, stats, diagnostics, selection, view, ...} as JSON text; `diagnostics` the page of them
    // asked for (the first kStateProblemsPage without one), `problems` the list's total and groups.
    [[nodiscard]] std::string state_json(ProblemPage page = problem_page(-1, -1)) const;
    // One motion as JSON: {"index","line","block","kind","curve","start","end","mid","length_mm","centre","text"};
    // "null" past the end.
    [[nodiscard]] std::string motion_json(std::size_t i) const;
    // The page pixel where program point (x, y) mm is drawn (View::to_screen).
    [[nodiscard]] Point project(double x, double y) const;
    // The tape converted, drawn or reported as the Export menu makes it (Exports::export_text).
    [[nodiscard]] std::string export_text(const std::string& format) const { return p_.exports.export_text(format); }
    // The panels' font atlas has every character of `utf8` (UiFonts::has_glyphs).
    [[nodiscard]] bool has_glyphs(std::string_view utf8) const { return p_.fonts.has_glyphs(utf8); }

    // --- What the page asks for (Automation.cpp) ---
    void load(std::string name, std::string bytes) { p_.session.load(std::move(name), std::move(bytes)); }
    void load_shared(std::string name, std::string bytes, const ShareLink& link) {
        p_.session.load_shared(std::move(name), std::move(bytes), link);
    }
    void link_problem(Phrase why) { p_.session.set_link_problem(std::move(why)); }
    // `remember`: kept across sessions (the page's switch); the desktop viewer's --lang is not.
    void set_language(Lang lang, bool remember = true) { p_.preferences.set_language(lang, remember); }
    void set_view(double x, double y, double zoom) { p_.navigation.set_view(x, y, zoom); }
    void select_line(std::uint32_t line) { p_.navigation.select_line(line); }
    // setLayer's numbers: 0-3 MotionKind, 4 pierces, 5 start, 6 kerf path, 7 kerf width, 8 table.
    void set_layer(int layer, bool visible);
    void set_orientation(int quarter_turns) { p_.navigation.set_orientation(quarter_turns); }
    void set_machine_coordinates(bool machine) { p_.navigation.set_machine_coordinates(machine); }
    // The playback's speed factor (machine seconds a second, clamped to Playback's range) and whether it plays.
    void set_playback(double factor, bool playing);
    void copy(Exports::CopyWhat what, std::uint32_t index) { p_.exports.copy(what, index); }
    // Two fingers on the canvas: the view zooms by `factor` about the fingers' middle and moves with it from
    // (x0, y0) to (x1, y1), canvas pixels.
    void pinch(double x0, double y0, double x1, double y1, double factor);
    void set_layout(const panels::PanelLayout& layout) { p_.preferences.set_layout(layout); }
    void compare_with(std::string name, const std::string& bytes) { p_.session.compare_with(std::move(name), bytes); }
    void end_compare() { p_.compare.end(); }
    void print_job_sheet() { p_.exports.print_job_sheet(); }
    // The keyboard's focus is on the drawing, the last stop of the viewer's Tab order (the page lets Tab leave).
    [[nodiscard]] bool keyboard_at_drawing() const { return p_.ui.keyboard == KeyboardMode::Drawing; }
    // Colour by (ColourBy.hpp): "kind", "feed" or "order"; false for another name.
    bool set_colour_by(std::string_view name) {
        const std::optional<ColourBy> by = colour_by_named(name);
        if (by) p_.layers.colour_by = *by;
        return by.has_value();
    }
    // The k-th difference shown (CompareMode::show_difference).
    void show_difference(int k);
    void export_view_png() { p_.exports.export_view_png(); }
    void set_text_encoding(std::optional<TextEncoding> chosen) { p_.comments.choose(chosen, p_.session.document()); }
    void set_problems_only(bool on) { p_.preferences.set_problems_only(on); }
    void set_light_theme(bool light) { p_.preferences.set_light_theme(light); }
    // The examples the server offers (their names), for the start screen.
    void set_examples(std::vector<std::string> names);
    void set_profile(const std::string& name) { p_.session.set_profile(name); }
    void require_glyphs(std::string_view utf8) { p_.fonts.require_glyphs(utf8); }
    void share() { p_.shares.share(); }
    void share_done(std::string url) { p_.shares.done(std::move(url)); }
    void share_failed(Phrase why) { p_.shares.failed(std::move(why)); }

private:
    Parts p_;
};

}  // namespace essi::viewer
