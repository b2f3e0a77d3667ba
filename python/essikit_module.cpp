// The Python module's native part (`essikit._essikit`, pybind11): the core's check, trace and convert on bytes,
// the reports as the JSON text `essi` writes (python/essikit/__init__.py makes them dicts). No files here: the
// Python side reads them.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/report_json.hpp"
#include "essi/trace.hpp"
#include "essi/write.hpp"

namespace py = pybind11;

namespace {

// A profile failure or a bad argument: the Python side raises essikit.Error with the diagnostics' JSON.
struct SetupError : std::runtime_error {
    SetupError(const std::string& what, std::string diagnostics_json)
        : std::runtime_error(what), diagnostics(std::move(diagnostics_json)) {}
    std::string diagnostics;
};

essi::Lang lang_of(const std::string& lang) {
    if (lang.empty()) return essi::Lang::En;
    const auto l = essi::parse_lang(lang);
    if (!l) throw SetupError("lang '" + lang + "': expected en, de or zh", "[]");
    return *l;
}

// `profile`: a built-in name, "auto" or "" (the default, iso6582); `profile_json`: a profile file's text (then it
// is used). `input`: "essi", "eia" or "auto"/"" (from the content).
essi::TapeSetup setup_of(std::string_view bytes, const std::string& profile, const std::string& profile_json,
                         const std::string& input) {
    std::optional<essi::InputFormat> format;
    if (!essi::parse_input_choice(input, format))
        throw SetupError("input '" + input + "': expected essi, eia or auto", "[]");
    std::optional<essi::Profile> p;
    if (!profile_json.empty()) {
        essi::ProfileResult r = essi::parse_profile(profile_json);
        if (!r.profile) throw SetupError("the profile cannot be used", essi::diagnostics_to_json(r.diagnostics).dump());
        p = std::move(*r.profile);
    } else if (profile != "auto") {
        p = essi::builtin_profile(profile.empty() ? "iso6582" : profile);
        if (!p)
            throw SetupError("unknown profile '" + profile + "'; expected a built-in name, auto or a JSON file", "[]");
    }
    return essi::setup_tape(bytes, format, p);
}

std::string check(py::bytes data, const std::string& name, const std::string& profile, const std::string& profile_json,
                  const std::string& input, const std::string& lang) {
    const std::string bytes = data;
    const essi::Lang l = lang_of(lang);
    const essi::TapeSetup setup = setup_of(bytes, profile, profile_json, input);
    essi::FileReport report;
    report.path = name;
    report.result = essi::check_tape(bytes, setup);
    const essi::FileReport one[] = {std::move(report)};
    return essi::report_to_json(one, profile == "auto" ? "auto" : setup.profile.name, l).dump(2);
}

std::vector<std::string> trace(py::bytes data, const std::string& profile, const std::string& profile_json,
                               const std::string& input, int decimals, bool kerf, bool machine) {
    const std::string bytes = data;
    const essi::TapeSetup setup = setup_of(bytes, profile, profile_json, input);
    std::string text;
    essi::TraceView view;
    view.kerf = kerf;
    view.machine = machine;
    (void)essi::trace_tape(
        bytes, setup.profile, [&](std::string_view piece) { text += piece; }, setup.format, decimals, view);
    std::vector<std::string> lines;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = text.find('\n', at);
        lines.push_back(text.substr(at, end == std::string::npos ? std::string::npos : end - at));
        if (end == std::string::npos) break;
        at = end + 1;
    }
    return lines;
}

// (text, diagnostics' JSON, refused)
py::tuple convert(py::bytes data, const std::string& to, const std::string& profile, const std::string& profile_json,
                  const std::string& input, bool absolute, bool force, const std::string& lang) {
    const std::string bytes = data;
    const essi::Lang l = lang_of(lang);
    const essi::TapeSetup setup = setup_of(bytes, profile, profile_json, input);
    essi::ConvertOptions o;
    if (const auto format = essi::parse_output_format(to)) o.to = *format;
    else throw SetupError("to '" + to + "': expected essi, eia or gcode", "[]");
    o.target = setup.profile;
    o.absolute = absolute;
    o.force = force;
    const essi::ConvertResult r = essi::convert_tape(bytes, setup, o);
    return py::make_tuple(r.text, essi::diagnostics_to_json(r.diagnostics, l).dump(), r.refused);
}

}  // namespace

PYBIND11_MODULE(_essikit, m) {
    m.doc() = "essikit's core: check, trace and convert ESSI and EIA cutting tapes (use the essikit package)";
    static py::exception<SetupError> setup_error(m, "SetupError");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SetupError& e) {
            py::tuple args = py::make_tuple(std::string(e.what()), e.diagnostics);
            PyErr_SetObject(setup_error.ptr(), args.ptr());
        }
    });
    m.def("check", &check);
    m.def("trace", &trace);
    m.def("convert", &convert);
    m.def("profiles", &essi::builtin_profile_names);
}
