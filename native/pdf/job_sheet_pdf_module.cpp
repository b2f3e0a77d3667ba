// The builds with cairo and pango: the PDF writer is the module essi-pdf.so (pdf/job_sheet_pdf_cairo.cpp), loaded
// the first time a PDF is asked for (native/job_sheet_pdf.hpp says where it is looked for).
#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include "job_sheet_pdf.hpp"

namespace essi::native {

namespace {

using BuildFunction = const char* (*)();
using WriterFunction = bool (*)(const JobSheet&, std::string&, std::string&);

// The module's writer once loaded, or why it could not be.
struct Module {
    WriterFunction write = nullptr;
    std::string why;
};

// The places to look, in order.
std::vector<std::filesystem::path> module_paths() {
    std::vector<std::filesystem::path> paths;
    if (const char* named = std::getenv(kPdfModuleVariable); named && *named) {
        paths.emplace_back(named);
        return paths;
    }
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return paths;
    paths.push_back(exe.parent_path() / kPdfModuleName);
    paths.push_back(exe.parent_path().parent_path() / "lib" / "essikit" / kPdfModuleName);
    return paths;
}

// Loads the first module found that is of this build; the module stays loaded until essi ends.
Module load_module() {
    Module m;
    for (const std::filesystem::path& path : module_paths()) {
        if (!std::filesystem::exists(path)) {
            m.why += (m.why.empty() ? "" : "; ") + path.string() + ": not found";
            continue;
        }
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            m.why += (m.why.empty() ? "" : "; ") + std::string(::dlerror());
            continue;
        }
        const auto build = reinterpret_cast<BuildFunction>(::dlsym(handle, "essi_pdf_module_build"));
        const auto write = reinterpret_cast<WriterFunction>(::dlsym(handle, "essi_job_sheet_pdf"));
        if (!build || !write || std::strcmp(build(), kPdfModuleBuild) != 0) {
            m.why += (m.why.empty() ? "" : "; ") + path.string() + ": built for essi " +
                     (build ? std::string(build()) : std::string("?")) + ", not " + kPdfModuleBuild;
            ::dlclose(handle);
            continue;
        }
        m.write = write;
        m.why.clear();
        return m;
    }
    if (m.why.empty()) m.why = std::string(kPdfModuleName) + ": no place to look for it";
    return m;
}

const Module& module() {
    static std::once_flag once;
    static Module m;
    std::call_once(once, [] { m = load_module(); });
    return m;
}

}  // namespace

bool pdf_writer_built() { return true; }

bool pdf_available(std::string* why) {
    const Module& m = module();
    if (!m.write && why) *why = m.why;
    return m.write != nullptr;
}

bool job_sheet_pdf(const JobSheet& sheet, std::string& pdf, std::string& error) {
    const Module& m = module();
    if (!m.write) {
        error = m.why;
        return false;
    }
    return m.write(sheet, pdf, error);
}

}  // namespace essi::native
