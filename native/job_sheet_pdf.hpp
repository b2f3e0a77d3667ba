// `essi report`'s PDF: the job sheet (essi/job_sheet.hpp) on A4 pages with its fonts embedded, CJK included. One
// file per build, chosen by native/CMakeLists.txt: cairo and pango where the build has them
// (pdf/job_sheet_pdf_cairo.cpp), else none (pdf/job_sheet_pdf_none.cpp: the static essi, since Debian ships no
// static pango, and the npm package's WebAssembly build): there `essi report` writes HTML only.
#pragma once

#include <string>

#include "essi/job_sheet.hpp"

namespace essi::native {

// Whether this build writes PDF.
[[nodiscard]] bool pdf_available();

// The sheet as a PDF document into `pdf`; false with `error` (cairo's words) when it cannot be made, or when this
// build has no PDF.
[[nodiscard]] bool job_sheet_pdf(const JobSheet& sheet, std::string& pdf, std::string& error);

}  // namespace essi::native
