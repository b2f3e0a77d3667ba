#include "app/LoadController.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "app/DocumentLoader.hpp"
#include "app/WorkerLoader.hpp"

namespace essi::viewer {

namespace {

constexpr std::size_t kBuildMotionsPerFrame = 200000;  // tapes up to this size are drawn in the loading frame
constexpr std::size_t kBuildMotionsPerStep = 4096;     // between two looks at the clock (and texture uploads)
// Tapes with at least this many motions get a level-of-detail raster for zoomed-out views (below, drawing every
// segment costs a CPU renderer less than a frame or two).
constexpr std::size_t kLodMinMotions = 100000;
// The first level of detail has the cells the view needs when the tape's own (LodRaster::cells_for) are more than
// this many times those; the finer one follows once the segments are made.
constexpr double kLodRefineRatio = 1.5;
// The drawn segments are made again when their chord tolerance is coarser than this many times the one wanted
// (zoomed in past 2x), or finer than the wanted one divided by kRebuildFiner (zoomed out 16x: fewer segments).
constexpr double kRebuildCoarser = 2;
constexpr double kRebuildFiner = 16;
constexpr double kNoLimit = std::numeric_limits<double>::infinity();  // a load at once: no slice budget
constexpr float kPlanFrom = 0.9f;  // the progress bar's share before the cut plan (tapes loaded in slices)

}  // namespace

void LoadController::start(std::string name, std::string bytes, TapeSetup setup) {
    loading_name_ = name;
    loading_bytes_ = bytes.size();
    frames_ = LoadFrames{};
    frames_.at_once = bytes.size() < kAtOnceBytes;
    frames_.handed = frame_;
    awaiting_shown_ = false;
    plan_.reset();  // (the plan of the tape before is not finished: it is dropped with it)
    // A tape loaded in slices keeps its cut plan's plates for after its drawing; one loaded at once is complete.
    read_by_worker_ = worker_ != nullptr && !frames_.at_once;
    worker_failure_.clear();
    if (read_by_worker_)
        loader_ = std::make_unique<WorkerLoader>(*worker_, std::move(name), std::move(bytes), std::move(setup));
    else
        loader_ =
            std::make_unique<DocumentLoader>(std::move(name), std::move(bytes), std::move(setup), !frames_.at_once);
    frames_since_start_ = 0;
    started_ = glfwGetTime();
}

bool LoadController::step() {
    const bool at_once = frames_.at_once;
    if (loader_) {
        // Sliced: the first frame only shows the progress bar; then about kStepBudgetMs of work per slice. At once:
        // all of it now (begin_drawing makes the whole drawing too).
        if (!at_once && frames_since_start_++ == 0) return false;
        ++frames_.steps;
        if (!loader_->step(at_once ? kNoLimit : kStepBudgetMs)) return false;
        note_worker(*loader_);
        doc_ = loader_->take();
        ++documents_;
        if (loader_->plan_pending()) plan_ = std::move(loader_);
        loader_.reset();
        return true;
    }
    if (loading()) ++frames_.steps;
    build(glfwGetTime() + kStepBudgetMs / 1000.0);
    return false;
}

// A big tape's level of detail goes first (one pass over the motions, arcs at a chord of a quarter cell), with the
// cells the view needs: the fitted view shows the tape from it while the exact segments are made. The finer one
// (LodRaster::cells_for, for zooms between the fit and the segments) is made after them; a rebuild at another
// tolerance goes before it.
void LoadController::build(double until) {
    if (plan_ && !first_build_) {  // the verdict before the finer level of detail
        step_plan(until);
        // (the reading worker's verdict: the finer level of detail meanwhile, not slices that only wait for it)
        if (plan_ == nullptr || plan_->works_on_page()) return;
    }
    if (lod_building_ && (first_build_ || !building_)) {
        step_overview(until);
        if (lod_building_) return;
    }
    if (building_) step_segments(until);
}

void LoadController::step_plan(double until) {
    if (!plan_->step_plan(*doc_, (until - glfwGetTime()) * 1000.0)) return;
    note_worker(*plan_);
    plan_.reset();
    frames_.planned = frame_;
}

void LoadController::note_worker(const DocumentSource& source) {
    if (!source.failure().empty()) worker_failure_ = source.failure();
}

void LoadController::step_overview(double until) {
    bool done = false;
    while (!done && glfwGetTime() < until) done = lod_.step(kBuildMotionsPerStep);
    if (!done) return;
    lod_building_ = false;
    lod_.finish();
    if (graphics_ok_) renderer_.upload_lod(lod_);
    lod_.release();  // the GPU has it
}

void LoadController::step_segments(double until) {
    // Flatten and upload in the same slice: the segments go to the GPU a few texture rows at a time, so no frame
    // builds or uploads the whole stream (and no CPU copy of it is kept).
    bool done = false;
    while (!done && glfwGetTime() < until) {
        done = building_->step(kBuildMotionsPerStep);
        if (graphics_ok_) renderer_.append(gpu_building_, *building_);
        else building_->drop_staged(building_->staged_count());
    }
    if (done) segments_done();
}

// The built segments replace the drawn ones; after a load's first build, the finer level of detail follows.
void LoadController::segments_done() {
    buffers_ = std::move(*building_);
    building_.reset();
    buffers_.release_staging();
    renderer_.release(gpu_);
    gpu_ = std::move(gpu_building_);
    gpu_building_ = GpuPath{};
    if (!first_build_) return;
    first_build_ = false;
    load_seconds_ = glfwGetTime() - started_;
    frames_.drawable = frame_;
    if (lod_cells_ > 0 && lod_cells_ < lod_full_cells_) {
        lod_.begin(*doc_, lod_full_cells_);
        lod_cells_ = lod_full_cells_;
        lod_building_ = lod_.active();
    }
}

void LoadController::begin_drawing(double tolerance, double zoom, double framebuffer_scale) {
    const Document& d = *doc_;
    renderer_.release(gpu_);
    renderer_.release(gpu_building_);
    buffers_ = PathBuffers{};
    building_ = std::make_unique<PathBuffers>();
    building_->begin(d, tolerance, colour_by_, colour_sources_);
    if (graphics_ok_) renderer_.upload_markers(building_->markers);
    building_->markers = std::vector<MarkerInstance>();  // (the GPU has them)
    renderer_.clear_lod();
    lod_ = LodRaster{};
    lod_building_ = false;
    lod_cells_ = lod_full_cells_ = 0;
    if (d.motions.size() >= kLodMinMotions && !d.bbox.empty) begin_overview(zoom, framebuffer_scale);
    first_build_ = true;
    shown_seconds_ = 0;
    awaiting_shown_ = true;
    // A load at once: the whole drawing now (the level of detail, every segment made and uploaded). Other tapes
    // up to kBuildMotionsPerFrame motions: a slice of it now, so the next frame often shows the drawing.
    if (frames_.at_once) build(kNoLimit);
    else if (d.motions.size() <= kBuildMotionsPerFrame) build(glfwGetTime() + kStepBudgetMs / 1000.0);
}

// First the cells the view needs (a cell at most a pixel, as the renderer draws it), when that is well below what
// the tape's motions allow (samples scale with the cells: 0.4 of them for a big tape fitted here).
void LoadController::begin_overview(double zoom, double framebuffer_scale) {
    const Document& d = *doc_;
    const double w = d.bbox.max_x - d.bbox.min_x, h = d.bbox.max_y - d.bbox.min_y;
    lod_full_cells_ = LodRaster::cells_for(w, h, d.motions.size());
    const double view_cells = std::max(w, h) * zoom * framebuffer_scale / Renderer::kLodMaxCellPx + 2;
    lod_cells_ = view_cells * kLodRefineRatio < lod_full_cells_
                     ? std::max(LodRaster::kMinCells, static_cast<int>(std::ceil(view_cells)))
                     : lod_full_cells_;
    lod_.begin(d, lod_cells_);
    lod_building_ = lod_.active();
}

void LoadController::maybe_rebuild(double tolerance) {
    if (!doc_ || loader_ || building_) return;
    const double have = buffers_.tolerance();
    const bool recolour = buffers_.colour_by() != colour_by_;
    if (recolour || (doc_->curves > 0 && (have > tolerance * kRebuildCoarser || have < tolerance / kRebuildFiner))) {
        renderer_.release(gpu_building_);
        building_ = std::make_unique<PathBuffers>();
        building_->begin(*doc_, tolerance, colour_by_, colour_sources_);
        if (doc_->motions.size() <= kBuildMotionsPerFrame) build(glfwGetTime() + kStepBudgetMs / 1000.0);
    }
}

void LoadController::note_frame(bool drawn) {
    if (loading() && !at_once()) ++frames_.progress_frames;  // (the panels show no progress bar for a load at once)
    if (!drawn || !awaiting_shown_) return;
    awaiting_shown_ = false;
    frames_.shown = frame_;
    shown_seconds_ = glfwGetTime() - started_;
}

void LoadController::note_rendered(bool drawn, bool filling) {
    if (drawn && !filling && frames_.shown != 0 && frames_.complete == 0 && !loading()) frames_.complete = frame_;
}

LoadController::Phase LoadController::phase() const {
    if (loader_) return Phase::Reading;
    if (lod_building_ && first_build_) return Phase::Overview;
    if (building_ && first_build_) return Phase::Segments;
    if (plan_) return Phase::Plan;
    return Phase::Idle;
}

// Reading and checking up to 0.7, then the level of detail (big tapes) and the segments.
float LoadController::progress() const {
    switch (phase()) {
        case Phase::Reading: return loader_->progress();
        case Phase::Overview: return 0.7f + 0.1f * lod_.progress();
        case Phase::Plan: return kPlanFrom + (1.f - kPlanFrom) * plan_->plan_progress();
        default: break;
    }
    const float from = renderer_.has_lod() ? 0.8f : 0.7f, to = plan_ ? kPlanFrom : 1.f;
    return building_ ? from + (to - from) * building_->progress() : 1.f;
}

Msg LoadController::stage() const {
    switch (phase()) {
        case Phase::Reading: return loader_->stage();
        case Phase::Overview: return Msg::UiStageOverview;
        case Phase::Plan: return Msg::UiStagePlan;
        default: return Msg::UiStageBuilding;
    }
}

}  // namespace essi::viewer
