#include "app/Exports.hpp"

#include <ctime>
#include <span>

#include "app/Describe.hpp"
#include "app/Language.hpp"
#include "essi/dxf.hpp"
#include "essi/render_svg.hpp"
#include "essi/sha256.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "essi/write.hpp"

namespace essi::viewer {

namespace {

// The file name's ending of each export format ("essi": .esi).
const char* export_extension(const std::string& format) {
    return format == "dxf"           ? ".dxf"
           : format == "eia"         ? ".eia"
           : format == "gcode"       ? ".ngc"
           : format == "report-text" ? ".report.txt"
           : format == "report-json" ? ".report.json"
           : format == "report-csv"  ? ".problems.csv"
           : format == "view-svg"    ? ".view.svg"
           : format == "job-html"    ? ".job.html"
                                     : ".esi";
}

// The name without its last extension.
std::string stem_of(const std::string& name) { return name.substr(0, name.find_last_of('.')); }

}  // namespace

FileReport Exports::report() const {
    FileReport r;
    const Document* d = session_.document();
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

std::string Exports::copy_text(CopyWhat what, std::uint32_t index) const {
    const Document* d = session_.document();
    if (!d) return {};
    switch (what) {
        case CopyWhat::Report: {
            const FileReport r = report();
            return file_report_text(r, false, ui_lang()) +
                   summary_line(std::span<const FileReport>(&r, 1), session_.profile_name(), ui_lang()) + "\n";
        }
        case CopyWhat::Diagnostic:
            return index < d->diagnostics.size()
                       ? diagnostic_line(display_text(d->name), d->diagnostics[index], ui_lang()) + "\n"
                       : "";
        case CopyWhat::Line: return std::string(d->line(index)) + "\n";
        case CopyWhat::Inspector: return inspector_text(*d);
    }
    return {};
}

// The selected line, its inspector's sentences and its diagnostics.
std::string Exports::inspector_text(const Document& d) const {
    const std::uint32_t line = navigation_.selection().line;
    std::string s = display_text(d.name) + ":" + std::to_string(line) + ": " + std::string(d.line(line)) + "\n";
    for (const InspectorLine& l : inspector_lines(d, line, ui_lang())) s += l.text + "\n";
    for (const Diagnostic& diag : d.diagnostics)
        if (diag.line == line) s += diagnostic_line(display_text(d.name), diag, ui_lang()) + "\n";
    return s;
}

void Exports::copy(CopyWhat what, std::uint32_t index) {
    const std::string text = copy_text(what, index);
    if (text.empty()) return notices_.notify(Msg::UiNothingToCopy);
    platform_.copy_text(text);
    copied_ = text;
    static constexpr Msg kCopied[] = {Msg::UiCopiedReport, Msg::UiCopiedProblem, Msg::UiCopiedLine,
                                      Msg::UiCopiedInspector};
    notices_.notify(kCopied[static_cast<int>(what)]);
}

std::string Exports::export_text(const std::string& format) const {
    const Document* d = session_.document();
    if (!d) return {};
    if (format == "dxf") return render_dxf(d->bytes, d->setup).text;
    if (format == "report-text") return copy_text(CopyWhat::Report);
    if (format == "view-svg") {
        RenderOptions o;
        o.title = display_text(d->name);
        o.view = navigation_.visible_box();
        return render_svg(d->bytes, d->profile, o, d->setup.format).svg;
    }
    if (format == "job-html") {
        JobSheetInput in = job_input(*d);
        in.sha256 = sha256_hex(d->bytes);
        return job_sheet_html(job_sheet_of(d->bytes, d->setup, job_result(true), in));
    }
    if (format == "report-json" || format == "report-csv") {
        const FileReport r = report();
        const std::span<const FileReport> one(&r, 1);
        return format == "report-csv" ? diagnostics_csv(one, ui_lang())
                                      : report_to_json(one, session_.profile_name(), ui_lang()).dump(2) + "\n";
    }
    ConvertOptions o;
    o.to = parse_output_format(format).value_or(OutputFormat::Essi);
    o.target = d->profile;
    o.absolute = format == "gcode";  // (G-code for LinuxCNC: absolute, as CAM posts write it)
    return convert_tape(d->bytes, d->setup, o).text;
}

void Exports::export_file(const std::string& format) {
    const Document* d = session_.document();
    if (!d) return notices_.notify(Msg::UiLoadFirst);
    platform_.save_file(stem_of(d->name) + export_extension(format), export_text(format));
}

// The sheet's heading as `essi report` makes it: the tape's file name, the date now, the UI's language.
JobSheetInput Exports::job_input(const Document& d) const {
    JobSheetInput in;
    in.tape_name = d.name;
    in.created_unix = static_cast<std::int64_t>(std::time(nullptr));
    in.lang = ui_lang();
    return in;
}

CheckResult Exports::job_result(bool make_parts) const {
    CheckResult result = report().result;
    if (const PartsList* parts = make_parts ? facts_.parts() : facts_.parts_made()) result.parts = *parts;
    return result;
}

const std::vector<SheetSection>& Exports::job_sections() {
    const Document* d = session_.document();
    const JobSectionsOf now{d ? session_.documents_read() : 0, d ? d->diagnostics.size() : 0, ui_lang(),
                            facts_.parts_made() != nullptr};
    if (now.load == job_of_.load && now.diagnostics == job_of_.diagnostics && now.lang == job_of_.lang &&
        now.parts == job_of_.parts)
        return job_sections_;
    job_of_ = now;
    job_sections_.clear();
    if (!d) return job_sections_;
    const CheckResult result = job_result(false);
    JobSheet sheet = make_job_sheet(result, d->profile, SheetDrawing{}, sheet_parts(result), job_input(*d));
    for (SheetSection& s : sheet.sections)
        if (s.id == "time" || s.id == "parts" || s.id == "plates") job_sections_.push_back(std::move(s));
    return job_sections_;
}

void Exports::print_job_sheet() {
    const Document* d = session_.document();
    if (!d) return notices_.notify(Msg::UiLoadFirst);
    const std::string name = stem_of(d->name) + export_extension("job-html");
    if (!platform_.show_html(name, export_text("job-html"))) notices_.notify(Msg::UiJobSaved, {display_text(name)});
}

void Exports::export_view_png() {
    if (!session_.document()) return notices_.notify(Msg::UiLoadFirst);
    png_pending_ = true;  // (taken in the next frame, right after it is drawn)
}

void Exports::save_view_png(PixelRect area) {
    png_pending_ = false;
    platform_.save_view_png(stem_of(session_.document()->name) + ".view.png", area);
}

}  // namespace essi::viewer
