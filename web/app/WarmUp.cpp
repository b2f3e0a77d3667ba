#include "app/WarmUp.hpp"

#include <GLFW/glfw3.h>

#include <iterator>
#include <string>

#include "app/Language.hpp"
#include "app/View.hpp"
#include "essi/diagnostics.hpp"
#include "essi/dialect.hpp"
#include "essi_warm_up_tapes.hpp"

namespace essi::viewer {

void WarmUp::start(bool graphics) {
    if (state_ != State::Off) return;
    graphics_ = graphics;
    state_ = State::Running;
}

void WarmUp::step(double budget_ms) {
    if (state_ != State::Running) return;
    // A tape of the viewer's own is being loaded or shown: its load is warm enough now, and the renderer's markers
    // and level of detail are its own.
    if (app_load_.documents_read() > 0 || app_load_.busy()) {
        state_ = State::Stopped;
        return;
    }
    const double start = glfwGetTime(), until = start + budget_ms / 1000.0;
    do {
        run_one();
    } while (bytes_ < kBytes && glfwGetTime() < until);
    seconds_ += glfwGetTime() - start;
    if (bytes_ >= kBytes) state_ = State::Done;
}

void WarmUp::run_one() {
    constexpr std::size_t kTapes = std::size(warm_up_tapes::kFiles);
    const warm_up_tapes::EmbeddedFile& file = warm_up_tapes::kFiles[tapes_ % kTapes];
    const bool draw = graphics_ && tapes_ < kTapes * kDrawnRounds;
    ++tapes_;
    std::string bytes = file.text;
    bytes_ += bytes.size();
    TapeSetup setup = setup_tape(bytes, std::nullopt, std::nullopt);
    LoadController load(renderer_);
    load.set_graphics(draw);
    load.start(file.name, std::move(bytes), std::move(setup));
    while (!load.step()) {
    }
    const Document& d = *load.document();
    for (const Diagnostic& diagnostic : d.diagnostics) (void)diagnostic_message(diagnostic, ui_lang());
    if (d.bbox.empty) return;
    View view;  // fitted as a dropped tape's view is
    view.area = {0, 0, kViewPx, kViewPx};
    view.fit(d.bbox, d.origin);
    load.begin_drawing(view.chord_tolerance_mm(), view.zoom, 1.0);
    while (load.has_work()) (void)load.step();
    if (!draw) return;
    if (const GpuPath* path = load.drawn_path())
        renderer_.warm_up(*path, {view.cx, view.cy}, view.zoom * Renderer::kWarmUpImagePx / kViewPx);
    load.release_drawing();
    renderer_.upload_markers({});  // (the markers are the shown tape's: none yet)
}

const char* warm_up_state_name(WarmUp::State s) {
    switch (s) {
        case WarmUp::State::Off: return "off";
        case WarmUp::State::Running: return "running";
        case WarmUp::State::Done: return "done";
        case WarmUp::State::Stopped: return "stopped";
    }
    return "off";
}

}  // namespace essi::viewer
