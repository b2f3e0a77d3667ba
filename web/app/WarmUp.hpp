// The load path run before the first tape, on tapes built into the viewer (examples/, web/CMakeLists.txt), with
// what it made thrown away.
//
// A browser runs WebAssembly first with a baseline compiler, compiling each function on its first call, then
// compiles the hot ones again with its optimising compiler on other threads; SwiftShader compiles a GL program's
// code on its first draw. Left to the first tape dropped, all of that lands between the drop and its first frame,
// on the same two cores as the drawing (docs/performance.md, "Small tapes"). So after the page's start (the
// platform's choice: App::start_warm_up) WarmUp reads, checks and draws these tapes a slice at a time between
// frames, through the same code as a dropped tape: a LoadController of its own (DocumentLoader, the document,
// PathBuffers, the upload), the diagnostics' text, and Renderer::warm_up (the path and marker programs, into an
// image of their own). Nothing of it shows. It stops for good once the viewer has a tape of its own to load.
#pragma once

#include <cstddef>

#include "app/LoadController.hpp"
#include "render/Renderer.hpp"

namespace essi::viewer {

class WarmUp {
public:
    // Tape bytes read in all (the built-in tapes over and over): enough to make the reading, the check and the
    // drawing's loops hot enough to be optimised (the size of a 14 000-motion nesting tape).
    static constexpr std::size_t kBytes = 200000;
    // Rounds over the built-in tapes whose tapes are drawn as well (the GPU's part is done after one draw each).
    static constexpr std::size_t kDrawnRounds = 1;
    // The view each tape is fitted to: a square drawing area this many pixels wide (its chord tolerance).
    static constexpr float kViewPx = 1000;

    enum class State { Off, Running, Done, Stopped };

    // `app_load`: the viewer's own loads (WarmUp stops when one starts).
    WarmUp(Renderer& renderer, const LoadController& app_load) : renderer_(renderer), app_load_(app_load) {}
    // Starts it (once; `graphics`: the drawing programs compiled, so the drawing is warmed up too).
    void start(bool graphics);
    [[nodiscard]] bool has_work() const { return state_ == State::Running; }
    // One slice: tapes until `budget_ms` have passed (at least one).
    void step(double budget_ms);

    [[nodiscard]] State state() const { return state_; }
    [[nodiscard]] std::size_t tapes() const { return tapes_; }
    [[nodiscard]] std::size_t bytes() const { return bytes_; }
    [[nodiscard]] double seconds() const { return seconds_; }  // the slices' time in all

private:
    void run_one();

    Renderer& renderer_;
    const LoadController& app_load_;
    bool graphics_ = false;
    State state_ = State::Off;
    std::size_t tapes_ = 0, bytes_ = 0;
    double seconds_ = 0;
};

[[nodiscard]] const char* warm_up_state_name(WarmUp::State s);

}  // namespace essi::viewer
