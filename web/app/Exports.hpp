// What the viewer gives away: the report (as `essi check` makes it), a problem, a source line or the inspector's text
// copied to the clipboard; the tape converted or drawn saved as a file (the Export menu); the view as a PNG picture.
#pragma once

#include <cstdint>
#include <string>

#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "app/PlatformServices.hpp"
#include "app/Session.hpp"
#include "essi/report_json.hpp"

namespace essi::viewer {

class Exports {
public:
    Exports(const Session& session, const Navigation& navigation, Notices& notices, PlatformServices& platform)
        : session_(session), navigation_(navigation), notices_(notices), platform_(platform) {}

    // The tape's report: as `essi check` makes it (its path the tape's name).
    [[nodiscard]] FileReport report() const;
    // Copies to the clipboard: the report as `essi check` prints it, one problem (`index` in the diagnostics) as
    // its line, one source line (`index` its number) or the inspector's text of the selected line.
    enum class CopyWhat { Report, Diagnostic, Line, Inspector };
    [[nodiscard]] std::string copy_text(CopyWhat what, std::uint32_t index = 0) const;
    void copy(CopyWhat what, std::uint32_t index = 0);
    // The last text copied (state().copied).
    [[nodiscard]] const std::string& copied() const { return copied_; }

    // The tape converted (`essi convert`: "essi", "eia", "gcode" in the profile it is read with), drawn ("dxf",
    // "view-svg") or its report ("report-text", "report-json", "report-csv"); empty without a tape. export_file
    // saves it (a download in the browser).
    [[nodiscard]] std::string export_text(const std::string& format) const;
    void export_file(const std::string& format);

    // The view as a PNG picture (the drawing area as drawn, the browser's download), taken after the next frame.
    void export_view_png();
    [[nodiscard]] bool png_pending() const { return png_pending_ && session_.document() != nullptr; }
    // Right after that frame is drawn: its drawing area (framebuffer pixels) saved.
    void save_view_png(PixelRect area);

private:
    [[nodiscard]] std::string inspector_text(const Document& d) const;

    const Session& session_;
    const Navigation& navigation_;
    Notices& notices_;
    PlatformServices& platform_;
    std::string copied_;
    bool png_pending_ = false;
};

}  // namespace essi::viewer
