// The viewer's load of a big tape, natively and under WASM (where it is the page's or the reading worker's work):
//
//   viewer_load/one_thread    DocumentLoader to the document, the cut plan kept for later (as the page and the
//                             worker read a tape loaded in slices), on one thread (the page's; the worker without
//                             threads)
//   viewer_load/two_threads   the same on two threads (essi::PipelinedCheck: natively, and the worker built with
//                             threads); not registered where the build has no threads
//   viewer_wire               the document encoded for the page and decoded there (the worker's hand-over)
//   viewer_overview           the level of detail of the fitted view (LodRaster at kOverviewCells on the longer
//                             side, all its levels): the stage "drawing the overview" before a big tape's first frame
//
// On a generated nest of kViewerTapeMb (about 1 M motions: the 1 M motion tape of tests/e2e/bench.mjs), whatever
// --essi_tape_mb says. Counters: `motions`, and MB/s of the tape's bytes.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <limits>
#include <memory>
#include <string>

#include "app/DocumentLoader.hpp"
#include "app/DocumentWire.hpp"
#include "essi/dialect.hpp"
#include "essi/threads.hpp"
#include "nest_generator.hpp"
#include "render/LodRaster.hpp"

namespace {

constexpr double kViewerTapeMb = 14;
constexpr unsigned kViewerSeed = 1;
// The overview's cells on the tape's longer side for the e2e benchmark's window (1 600 x 900, a cell a pixel).
constexpr int kOverviewCells = 1200;

const std::string& viewer_tape() {
    static const std::string bytes = essi::bench::generate_nest_tape(static_cast<std::size_t>(kViewerTapeMb * 1e6),
                                                                     kViewerSeed, essi::bench::LineEnding::CrLf);
    return bytes;
}

std::unique_ptr<essi::viewer::Document> load(std::size_t two_threads_min_bytes) {
    const std::string& bytes = viewer_tape();
    essi::viewer::DocumentLoader loader("nest.esi", bytes, essi::setup_tape(bytes, std::nullopt, std::nullopt),
                                        /*plan_later=*/true, two_threads_min_bytes);
    while (!loader.step(std::numeric_limits<double>::infinity())) {
    }
    return loader.take();
}

const essi::viewer::Document& loaded_once() {
    static const std::unique_ptr<essi::viewer::Document> doc = load(std::numeric_limits<std::size_t>::max());
    return *doc;
}

void counters(benchmark::State& state) {
    const auto total = static_cast<double>(viewer_tape().size()) * static_cast<double>(state.iterations());
    state.counters["MB/s"] = benchmark::Counter(total / 1e6, benchmark::Counter::kIsRate);
    state.counters["motions"] = static_cast<double>(loaded_once().motions.size());
}

void bm_viewer_load(benchmark::State& state, std::size_t two_threads_min_bytes) {
    (void)loaded_once();  // (the tape generated, and the code run once, before the timing)
    for (auto _ : state) {
        std::unique_ptr<essi::viewer::Document> doc = load(two_threads_min_bytes);
        benchmark::DoNotOptimize(doc->motions.data());
    }
    counters(state);
}

void bm_viewer_wire(benchmark::State& state) {
    const essi::viewer::Document& doc = loaded_once();
    for (auto _ : state) {
        const std::string wire = essi::viewer::encode_document(doc);
        std::string bytes = doc.bytes;
        essi::viewer::WireError error;
        std::unique_ptr<essi::viewer::Document> back = essi::viewer::decode_document(wire, bytes, error);
        if (!back) state.SkipWithError(error.message().c_str());
        benchmark::DoNotOptimize(back.get());
    }
    counters(state);
}

void bm_viewer_overview(benchmark::State& state) {
    const essi::viewer::Document& doc = loaded_once();
    for (auto _ : state) {
        essi::viewer::LodRaster lod;
        lod.begin(doc, kOverviewCells);
        while (!lod.step(doc.motions.size())) {
        }
        lod.finish();
        benchmark::DoNotOptimize(lod.width());
    }
    counters(state);
}

const bool registered = [] {
    benchmark::RegisterBenchmark("viewer_load/one_thread", bm_viewer_load, std::numeric_limits<std::size_t>::max())
        ->Unit(benchmark::kMillisecond);
    if (essi::kHaveThreads)
        benchmark::RegisterBenchmark("viewer_load/two_threads", bm_viewer_load, std::size_t{0})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    benchmark::RegisterBenchmark("viewer_wire", bm_viewer_wire)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("viewer_overview", bm_viewer_overview)->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
