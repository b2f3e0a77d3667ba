// `essi report`'s PDF: the job sheet (essi/job_sheet.hpp) on A4 pages with its fonts embedded, CJK included. The
// writer (pdf/job_sheet_pdf_cairo.cpp: cairo and pango) is a module of its own, essi-pdf.so, that essi loads only
// when it writes a PDF (pdf/job_sheet_pdf_module.cpp), so that every other command starts without cairo, pango,
// fontconfig and what they link. Builds without cairo and pango (the static essi, since Debian ships no static pango,
// and the npm package's WebAssembly) have none (pdf/job_sheet_pdf_none.cpp): there `essi report` writes HTML only.
//
// Where essi looks for the module, first found: $ESSI_PDF_MODULE (a file), then beside the essi binary
// (<dir>/essi-pdf.so: the build tree), then <dir>/../lib/essikit/essi-pdf.so (the Debian package).
#pragma once

#include <string>

#include "essi/job_sheet.hpp"
#include "essi_version.hpp"

namespace essi::native {

// The module's file name, and the environment variable that names another.
inline constexpr const char* kPdfModuleName = "essi-pdf.so";
inline constexpr const char* kPdfModuleVariable = "ESSI_PDF_MODULE";
// The build a module and essi must share: the JobSheet they pass is the same type only within one build.
inline constexpr const char* kPdfModuleBuild = kBuild;

// Whether this build has a PDF writer (its module may still be missing).
[[nodiscard]] bool pdf_writer_built();
// Whether this build writes PDF (its module can be loaded); `why` says why not.
[[nodiscard]] bool pdf_available(std::string* why = nullptr);

// The sheet as a PDF document into `pdf`; false with `error` (cairo's words, or why there is no writer) when it
// cannot be made.
[[nodiscard]] bool job_sheet_pdf(const JobSheet& sheet, std::string& pdf, std::string& error);

}  // namespace essi::native
