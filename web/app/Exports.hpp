// What the viewer gives away: the report (as `essi check` makes it), a problem, a source line or the inspector's text
// copied to the clipboard; the tape converted or drawn saved as a file (the Export menu); the view as a PNG picture;
// the job sheet (essi report's, essi/job_sheet.hpp): its sections for the Job panel and its page to print.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/Navigation.hpp"
#include "app/Notices.hpp"
#include "app/PlatformServices.hpp"
#include "app/Session.hpp"
#include "app/TapeFacts.hpp"
#include "essi/job_sheet.hpp"
#include "essi/report_json.hpp"

namespace essi::viewer {

class Exports {
public:
    Exports(const Session& session, const TapeFacts& facts, const Navigation& navigation, Notices& notices,
            PlatformServices& platform)
        : session_(session), facts_(facts), navigation_(navigation), notices_(notices), platform_(platform) {}

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
    // "view-svg"), its report ("report-text", "report-json", "report-csv") or its job sheet as `essi report`
    // writes it ("job-html"); empty without a tape. export_file saves it (a download in the browser).
    [[nodiscard]] std::string export_text(const std::string& format) const;
    void export_file(const std::string& format);

    // The view as a PNG picture (the drawing area as drawn, the browser's download), taken after the next frame.
    void export_view_png();
    [[nodiscard]] bool png_pending() const { return png_pending_ && session_.document() != nullptr; }
    // Right after that frame is drawn: its drawing area (framebuffer pixels) saved.
    void save_view_png(PixelRect area);

    // The job sheet's sections the Job panel shows (time and cost; parts and plates once the parts list is made:
    // TapeFacts::parts_made), in the UI's language: made again when the tape, its diagnostics (the cut plan's join
    // later), the parts list or the language change.
    [[nodiscard]] const std::vector<SheetSection>& job_sections();
    // The job sheet in a new tab of the browser, to read and print (saved as a file where no tab opens).
    void print_job_sheet();

private:
    [[nodiscard]] std::string inspector_text(const Document& d) const;
    [[nodiscard]] JobSheetInput job_input(const Document& d) const;
    // The report's result with the tape's parts list, as `essi report` makes the sheet from (`make_parts`: made
    // now if need be; else only when made already).
    [[nodiscard]] CheckResult job_result(bool make_parts) const;

    const Session& session_;
    const TapeFacts& facts_;
    const Navigation& navigation_;
    Notices& notices_;
    PlatformServices& platform_;
    std::string copied_;
    bool png_pending_ = false;
    struct JobSectionsOf {       // what job_sections() were made for
        std::uint64_t load = 0;  // Session::documents_read when it was made (0: never)
        std::size_t diagnostics = 0;
        Lang lang = Lang::En;
        bool parts = false;  // with the parts list
    } job_of_;
    std::vector<SheetSection> job_sections_;
};

}  // namespace essi::viewer
