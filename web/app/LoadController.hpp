// Loading and the rebuild policy: reads a tape in slices (DocumentLoader), then makes its drawing in slices too
// — a big tape's level of detail first (with the cells the view needs), then its segments, uploaded as they are
// made, then the cut plan's plates (kept while the tape was read: the drawing comes first), then the finer level
// of detail — and makes the segments again when the zoom moves far enough from the chord tolerance they were
// made at. Every slice takes about kStepBudgetMs; the document is not drawn until its
// segments are complete. A tape under kAtOnceBytes is loaded at once instead: read, checked and its drawing made
// and uploaded in one step, so the first frame after it was handed over shows it (no progress bar).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "app/Document.hpp"
#include "app/DocumentSource.hpp"
#include "app/ReadingWorker.hpp"
#include "render/LodRaster.hpp"
#include "render/PathBuffers.hpp"
#include "render/Renderer.hpp"

namespace essi::viewer {

class LoadController {
public:
    static constexpr double kStepBudgetMs = 30;  // work per frame while loading (the page keeps drawing)
    // Tapes under this many bytes are loaded at once (at_once()): most real tapes; about 70 000 motions of the
    // generated nest tape, whose whole load takes a few tens of ms in the browser.
    static constexpr std::size_t kAtOnceBytes = 1000000;

    // Where the work of a load is (what the progress bar says).
    enum class Phase {
        Idle,      // nothing to do, or only work after the load (a rebuild, the finer level of detail)
        Reading,   // the DocumentLoader: line index, reading and checking
        Overview,  // the first level of detail of a big tape
        Segments,  // the first build of the segments
        Plan,      // the cut plan's plates of a tape loaded in slices (its findings join the diagnostics)
    };

    explicit LoadController(Renderer& renderer) : renderer_(renderer) {}
    void set_graphics(bool ok) { graphics_ok_ = ok; }
    // The reading worker (none: every tape is read on the page). Tapes loaded in slices (kAtOnceBytes and more)
    // are read and checked there (WorkerLoader); smaller ones at once on the page, which shows them in the next
    // frame.
    void set_reading_worker(ReadingWorker* worker) { worker_ = worker; }
    // The reading worker, if there is one, started ahead of the first big tape (ReadingWorker::prepare).
    void prepare_reading_worker() {
        if (worker_ != nullptr) worker_->prepare();
    }

    // How the last load went, in the caller's frame numbers (begin_frame), for state().load: a tape handed over
    // between frames N and N + 1 and loaded at once is drawable before frame N + 1 begins and shown by it.
    struct LoadFrames {
        bool at_once = false;        // loaded at once (kAtOnceBytes), not in slices
        std::uint64_t handed = 0;    // frames begun when the tape was handed over (start())
        std::uint64_t drawable = 0;  // frames begun when its drawing was complete (read, checked, segments on the GPU)
        std::uint64_t shown = 0;     // the first frame that drew it (its segments or its level of detail); 0: none yet
        std::uint64_t complete = 0;  // the first frame that drew it complete: loaded, no segment left to draw
        std::uint64_t planned = 0;   // frames begun when its cut plan's findings joined the diagnostics (a tape
                                     // loaded in slices: after `drawable`); 0: checked with the reading
        std::uint64_t steps = 0;     // slices of work (in frames and between them) until its drawing was complete
        std::uint64_t progress_frames = 0;  // frames that showed its progress bar
    };

    // Frame `frame` (the caller's count of frames begun) begins: the numbers of LoadFrames.
    void begin_frame(std::uint64_t frame) { frame_ = frame; }
    // Starts reading a tape (the document before it stays drawn until this one is read). A tape under kAtOnceBytes
    // is loaded whole by the next step() (the caller's, outside a frame's panels: it replaces the document).
    void start(std::string name, std::string bytes, TapeSetup setup);
    // One slice of work (a load at once: all of it). True when a new document has just been read: the caller sets
    // the view, then calls begin_drawing() (which, for a load at once, makes and uploads the whole drawing).
    [[nodiscard]] bool step();
    // Makes the new document's drawing at `tolerance` mm; the view's zoom (px/mm, once fitted or as requested) and
    // the framebuffer scale size its first level of detail.
    void begin_drawing(double tolerance, double zoom, double framebuffer_scale);
    // The segments again at `tolerance` when the drawn ones are too coarse (zoomed in 2x) or too fine (out 16x).
    void maybe_rebuild(double tolerance);
    // The cuts' colours (Layers::colour_by): a new choice makes the segments again (maybe_rebuild) and the next
    // drawing with it. `sources`: the tape's parts and planned speeds (TapeFacts), asked only by those modes.
    void set_colour_by(ColourBy by, const ColourSources* sources) {
        colour_by_ = by;
        colour_sources_ = sources;
    }
    // This frame's scene (before it is drawn): whether it draws the tape (the first such frame after a load gives
    // shown_seconds()); a frame while loading shows the progress bar.
    void note_frame(bool drawn);
    // This frame was drawn: `drawn` the tape, `filling` its image still has segments to draw (Renderer::filling).
    void note_rendered(bool drawn, bool filling);
    [[nodiscard]] const LoadFrames& load_frames() const { return frames_; }
    // The load in progress is one at once: the caller's next step() finishes it.
    [[nodiscard]] bool at_once() const { return loader_ != nullptr && frames_.at_once; }
    // A load at once not yet drawn complete: its first frame draws the whole image (no fill over frames).
    [[nodiscard]] bool draw_whole() const { return frames_.at_once && frames_.complete == 0 && doc_ && !loading(); }

    // Gives the drawing's segments back to the GPU (a LoadController that goes away: the renderer outlives it).
    void release_drawing() {
        renderer_.release(gpu_);
        renderer_.release(gpu_building_);
    }

    [[nodiscard]] Phase phase() const;
    [[nodiscard]] bool loading() const { return phase() != Phase::Idle; }  // reading, or the first drawing
    [[nodiscard]] float progress() const;
    [[nodiscard]] Msg stage() const;  // what the progress bar says (a row of ui.def)
    // Loading or building work left to do on the page (the browser loop also runs slices of it between frames;
    // while the reading worker works, only the frames look for its messages).
    [[nodiscard]] bool has_work() const {
        return (loader_ != nullptr && loader_->works_on_page()) || lod_building_ || building_ != nullptr ||
               (plan_ != nullptr && plan_->works_on_page());
    }
    // Work left, on the page or in the reading worker.
    [[nodiscard]] bool busy() const {
        return loader_ != nullptr || plan_ != nullptr || lod_building_ || building_ != nullptr;
    }
    // The slice may run outside a frame (not before the first frame of a load has shown the progress bar).
    [[nodiscard]] bool may_step_outside_frame() const {
        return !(loader_ && !frames_.at_once && frames_since_start_ == 0);
    }
    // The segments are being made again at a new zoom's tolerance (not the load's first build), over the overview.
    [[nodiscard]] bool remaking() const { return building_ != nullptr && !first_build_ && renderer_.has_lod(); }
    [[nodiscard]] bool first_build() const { return first_build_; }
    [[nodiscard]] bool reading() const { return loader_ != nullptr; }
    // The last tape loaded in slices was read by the reading worker; why the page read it after all (empty: it
    // did not, or there is no worker).
    [[nodiscard]] bool read_by_worker() const { return read_by_worker_; }
    [[nodiscard]] const std::string& worker_failure() const { return worker_failure_; }

    [[nodiscard]] const Document* document() const { return doc_.get(); }
    // The documents read so far (the current one's number): what a cache of something worked out from the document
    // is keyed by (a new document may take the old one's address).
    [[nodiscard]] std::uint64_t documents_read() const { return documents_; }
    [[nodiscard]] const PathBuffers& buffers() const { return buffers_; }
    [[nodiscard]] const PathBuffers* building() const { return building_.get(); }
    // The segments to draw: none while the first build runs (nothing of a new tape is drawn until it is complete).
    [[nodiscard]] const GpuPath* drawn_path() const { return first_build_ ? nullptr : &gpu_; }
    [[nodiscard]] std::size_t gpu_bytes() const { return gpu_.gpu_bytes() + gpu_building_.gpu_bytes(); }
    [[nodiscard]] std::size_t segment_index_bytes() const {
        return buffers_.memory_bytes() + (building_ ? building_->memory_bytes() : 0);
    }
    [[nodiscard]] const std::string& loading_name() const { return loading_name_; }
    [[nodiscard]] std::size_t loading_bytes() const { return loading_bytes_; }
    [[nodiscard]] double load_seconds() const { return load_seconds_; }
    [[nodiscard]] double shown_seconds() const { return shown_seconds_; }

private:
    void step_overview(double until);
    void step_segments(double until);
    void segments_done();
    void begin_overview(double zoom, double framebuffer_scale);
    void build(double until);  // the drawing's work until `until` (glfwGetTime; infinity: all of it)
    void step_plan(double until);
    void note_worker(const DocumentSource& source);  // what the worker's failure was, if it failed

    Renderer& renderer_;
    bool graphics_ok_ = false;

    // Reading
    ReadingWorker* worker_ = nullptr;
    std::unique_ptr<DocumentSource> loader_;
    std::unique_ptr<DocumentSource> plan_;  // the loader of the drawn document while its cut plan is analysed
    bool read_by_worker_ = false;
    std::string worker_failure_;
    std::string loading_name_;
    std::size_t loading_bytes_ = 0;
    int frames_since_start_ = 0;
    double started_ = 0;
    double load_seconds_ = 0;
    double shown_seconds_ = 0;  // from the start of the load to the first frame that drew the tape
    LoadFrames frames_;
    std::uint64_t frame_ = 0;      // frames begun (begin_frame)
    bool awaiting_shown_ = false;  // begin_drawing ran and no frame has drawn the new document yet

    // The document and its drawing
    std::unique_ptr<Document> doc_;
    std::uint64_t documents_ = 0;
    ColourBy colour_by_ = ColourBy::Kind;
    const ColourSources* colour_sources_ = nullptr;
    PathBuffers buffers_;                    // the drawn set's motion -> segment map (its segments are on the GPU only)
    GpuPath gpu_;                            // the drawn segments
    std::unique_ptr<PathBuffers> building_;  // being built (first build or a rebuild at a new tolerance)
    GpuPath gpu_building_;                   // its segments, uploaded as they are made
    bool first_build_ = false;
    LodRaster lod_;              // zoomed-out drawing of big tapes, made before the first build
    bool lod_building_ = false;  // lod_ is being made (the first build waits for it; a finer one waits for builds)
    int lod_cells_ = 0;          // cells on the longer side of the level of detail being made or drawn
    int lod_full_cells_ = 0;     // the tape's own (LodRaster::cells_for)
};

}  // namespace essi::viewer
