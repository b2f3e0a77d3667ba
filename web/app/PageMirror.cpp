#include "app/PageMirror.hpp"

#include <algorithm>

#include "app/Describe.hpp"
#include "app/Language.hpp"

namespace essi::viewer {

std::string verdict_text(const Document& doc) {
    const std::size_t e = doc.count(Severity::Error), w = doc.count(Severity::Warning);
    if (e == 0 && w == 0) return tr(Msg::UiVerdictOk);
    if (e == 0) return tr(Msg::UiVerdictWarnings, {w});
    return tr(Msg::UiVerdictErrors, {e, w});
}

namespace {

// A problem as the Diagnostics list says it: "E301 line 12:5: the arc's end is off its circle ...".
std::string problem_text(const Diagnostic& d) {
    return tr(Msg::UiMirrorProblem,
              {tr(Msg::UiDiagLabel, {code_name(d.code), d.line, d.column}), diagnostic_message(d, ui_lang())});
}

// The selected line's first problem, else its motion in words, else the line.
std::string selection_text(const Document& doc, const Selection& s) {
    if (s.line == 0) return {};
    const auto first = std::lower_bound(doc.diagnostics.begin(), doc.diagnostics.end(), s.line,
                                        [](const Diagnostic& d, std::uint32_t line) { return d.line < line; });
    if (first != doc.diagnostics.end() && first->line == s.line)
        return tr(Msg::UiMirrorSelectedProblem,
                  {tr(Msg::UiDiagLabel, {code_name(first->code), first->line, first->column}),
                   diagnostic_message(*first, ui_lang())});
    if (s.motion < doc.motions.size())
        return tr(Msg::UiMirrorSelectedSegment, {s.line, describe_motion(doc.record(s.motion), ui_lang())});
    return tr(Msg::UiMirrorSelectedLine, {s.line});
}

}  // namespace

PageMirror page_mirror(const Document* doc, const Selection& selection, const std::string* loading) {
    PageMirror m;
    m.lang = std::string(lang_code(ui_lang()));
    m.label = tr(Msg::UiCanvasLabel);
    m.heading = tr(Msg::UiMirrorHeading);
    m.problems_heading = tr(Msg::UiDiagnostics);
    if (loading != nullptr) {
        m.title = tr(Msg::UiPageTitleEmpty);
        m.status = tr(Msg::UiMirrorLoading, {*loading});
        return m;
    }
    if (doc == nullptr) {
        m.title = tr(Msg::UiPageTitleEmpty);
        m.status = std::string(tr(Msg::UiWelcomeTitle)) + " " + tr(Msg::UiWelcomeDrop);
        return m;
    }
    const std::string verdict = verdict_text(*doc);
    m.title = tr(Msg::UiPageTitle, {doc->name, verdict});
    m.status = tr(Msg::UiMirrorTape, {doc->name, verdict});
    if (const std::string s = selection_text(*doc, selection); !s.empty()) m.status += " " + s;
    const std::size_t n = doc->diagnostics.size();
    if (n == 0) m.problems.emplace_back(tr(Msg::UiNoProblems));
    for (std::size_t i = 0; i < std::min(n, kMirrorProblems); ++i)
        m.problems.push_back(problem_text(doc->diagnostics[i]));
    if (n > kMirrorProblems) m.more = tr(Msg::UiMirrorMore, {n - kMirrorProblems});
    return m;
}

const PageMirror& PageMirrorKeeper::update(const Document* doc, std::uint64_t load, const Selection& selection,
                                           const std::string* loading, bool* changed) {
    const Key key{doc,
                  load,
                  doc ? doc->diagnostics.size() : 0,
                  selection.line,
                  selection.motion,
                  ui_lang(),
                  loading ? *loading : std::string(),
                  loading != nullptr};
    *changed = false;
    if (made_ && key == key_) return mirror_;
    key_ = key;
    made_ = true;
    PageMirror next = page_mirror(doc, selection, loading);
    if (next != mirror_) {
        mirror_ = std::move(next);
        *changed = true;
    }
    return mirror_;
}

}  // namespace essi::viewer
