// The builds without cairo and pango (native/job_sheet_pdf.hpp): no PDF.
#include "job_sheet_pdf.hpp"

namespace essi::native {

bool pdf_writer_built() { return false; }

bool pdf_available(std::string* why) {
    if (why) *why = "this build has no PDF writer";
    return false;
}

bool job_sheet_pdf(const JobSheet&, std::string&, std::string& error) {
    error = "this build has no PDF writer";
    return false;
}

}  // namespace essi::native
