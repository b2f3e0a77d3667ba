// essi report: a tape's job sheet as PDF or HTML (essi/job_sheet.hpp, native/job_sheet_pdf.hpp; docs/cli.md).
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/job_sheet.hpp"
#include "essi/sha256.hpp"
#include "essi/text.hpp"
#include "job_sheet_pdf.hpp"

namespace essi::cli {
namespace {

struct ReportOptions {
    std::string path;
    std::string output;
    std::string format;  // pdf or html; "" = by the output's extension
    std::string profile;
    std::string input = "auto";
    long long max_diagnostics = static_cast<long long>(kSheetDefaultMaxDiagnostics);
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

enum class SheetFormat { Pdf, Html };

void say(Msg m, MessageArgs args) { err("essi report: " + format_message(m, lang(), args) + "\n"); }

bool has_extension(const std::string& path, std::initializer_list<const char*> extensions) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* e : extensions)
        if (ext == e) return true;
    return false;
}

// --format, else the output's extension, else (no -o) PDF where this build has it and HTML where not. Nullopt
// after the message for an output whose format cannot be told.
std::optional<SheetFormat> sheet_format(const ReportOptions& o) {
    if (o.format == "pdf") return SheetFormat::Pdf;
    if (o.format == "html") return SheetFormat::Html;
    if (o.output.empty()) return native::pdf_available() ? SheetFormat::Pdf : SheetFormat::Html;
    if (has_extension(o.output, {".pdf"})) return SheetFormat::Pdf;
    if (has_extension(o.output, {".html", ".htm"})) return SheetFormat::Html;
    say(Msg::ReportFormatUnknown, {display_text(o.output)});
    return std::nullopt;
}

// -o, else the tape's file name (stdin: "stdin") with the format's extension.
std::string output_path(const ReportOptions& o, SheetFormat format) {
    if (!o.output.empty()) return o.output;
    const std::string base = o.path == "-" ? std::string("stdin") : std::filesystem::path(o.path).filename().string();
    return base + (format == SheetFormat::Pdf ? ".pdf" : ".html");
}

// The sheet's date: SOURCE_DATE_EPOCH when it is set (reproducible sheets), else now.
std::int64_t sheet_time() {
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch && *epoch) {
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(epoch, &end, 10);
        if (errno == 0 && end && *end == '\0') return v;
    }
    return static_cast<std::int64_t>(std::time(nullptr));
}

int run_report(const ReportOptions& o) {
    const std::optional<SheetFormat> format = sheet_format(o);
    if (!format) return kExitUsage;
    if (std::string why; *format == SheetFormat::Pdf && !native::pdf_available(&why)) {
        if (native::pdf_writer_built()) say(Msg::ReportPdfFailed, {display_text(output_path(o, *format)), why});
        else say(Msg::ReportNoPdf, {});
        return kExitUsage;
    }
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;

    JobSheetInput in;
    in.tape_name = o.path == "-" ? std::string("-") : std::filesystem::path(o.path).filename().string();
    in.sha256 = sha256_hex(tape->file.bytes);
    in.created_unix = sheet_time();
    in.lang = lang();
    const auto max_diagnostics = static_cast<unsigned long long>(o.max_diagnostics);  // (0 .. 2^40, checked)
    in.max_diagnostics = static_cast<std::size_t>(
        std::min<unsigned long long>(max_diagnostics, std::numeric_limits<std::size_t>::max()));
    const JobSheetResult sheet = job_sheet(tape->file.bytes, tape->setup, in);

    const std::string output = output_path(o, *format);
    std::string bytes;
    if (*format == SheetFormat::Html) {
        bytes = job_sheet_html(sheet.sheet);
    } else if (std::string error; !native::job_sheet_pdf(sheet.sheet, bytes, error)) {
        say(Msg::ReportPdfFailed, {display_text(output), error});
        return kExitUsage;
    }
    if (!write_file(output, bytes)) {
        say(Msg::CliCannotWrite, {display_text(output), std::strerror(errno)});
        return kExitUsage;
    }
    if (output != "-") say(Msg::RenderWrote, {display_text(output)});
    return finish(sheet.result.ok() ? kExitOk : kExitTapeErrors);
}

}  // namespace

Subcommand define_report(CLI::App& essi) {
    auto o = std::make_shared<ReportOptions>();
    CLI::App* report = essi.add_subcommand(
        "report", "A tape's job sheet as PDF or HTML: drawing, statistics, time, profile, open diagnostics");
    report->add_option("PATH", o->path, "Tape file ('-' reads standard input)")->required();
    report->add_option("-o,--output", o->output,
                       "Output file ('-' = stdout; default NAME.pdf, or NAME.html without PDF)");
    report->add_option("--format", o->format, "pdf or html (default: by OUT's extension)")
        ->check(CLI::IsMember({"pdf", "html"}))
        ->type_name("pdf|html");
    add_profile_option(report, o->profile);
    add_input_option(report, o->input);
    report
        ->add_option("--max-diagnostics", o->max_diagnostics,
                     "At most N diagnostics listed and marked (the rest are counted in a note)")
        ->check(CLI::Range(0LL, 1LL << 40))
        ->type_name("N")
        ->capture_default_str();
    add_max_size_option(report, o->max_size);
    return {report, [o] { return run_report(*o); }};
}

}  // namespace essi::cli
