// Phase 6, plan: the cut plan checked, not only the syntax (docs/diagnostics.md, codes 6xx).
//
// A cut is a cut contour (essi/contour.hpp): from the pierce to the torch going off. It holds a closed loop when
// its path comes back to a point it passed; what comes before the loop is the lead-in, what comes after it the
// lead-out. A cut that comes back within closure_gap_mm but not within the arc tolerance is left open by a small
// gap (W601).
//
// Roles by nesting, plate by plate: a contour inside another is a hole of it (odd depth), a contour inside a hole is
// a part again (even depth); a contour that holds holes is a part. A lone contour (nothing inside it, inside
// nothing) is most likely a part, but may be a hole in the plate: where it has kerf compensation, the side says
// what the program treats it as (kerf outside: a part; inside: a hole in the plate); without compensation its role
// is unknown. Rules that need a role are errors only where the role is known, at most a note otherwise.
//
// Plates: a programmed stop (0, 102) with the torch back where the program started ends a plate (as a nesting
// program cuts several plates in one tape); parts of different plates never collide.
//
// Speed: the cuts are kept as their programmed motions (a small record each) until the plate ends; each cut's
// neighbours are found by a sweep along x over the cuts' boxes (on a crowded plate, a uniform grid over them), so
// containment and collisions test only contours whose boxes meet, never all pairs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "essi/contour.hpp"
#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"

namespace essi {

// Arcs are flattened within this for containment and collision tests (mm): far below a kerf.
constexpr double kPlanChordToleranceMm = 0.05;
// An arc is at most this many chords for those tests (a radius up to about 10 m keeps kPlanChordToleranceMm; a
// larger one is coarser: a tape's bounds, not a plate's, make such arcs). Never more than kMaxFlattenSegments (the
// fuzz-fast build's is smaller).
constexpr int kPlanMaxArcChords = kMaxFlattenSegments < 1024 ? kMaxFlattenSegments : 1024;
// A collision's overlap polygons (E605, N612) are at most this many points each: a longer contour's outline keeps
// this many of its points, evenly spread.
constexpr std::size_t kPlanMaxOverlapPoints = 256;
// The overlap polygons of a tape's collisions hold at most this many points together: the collisions after that
// (in the report's order) have none.
constexpr std::size_t kPlanMaxOverlapPointsPerTape = std::size_t{1} << 16;
// Two programmed contours closer than this touch even without compensation (mm).
constexpr double kPlanTouchToleranceMm = 0.01;
// Two paths whose points all lie this close are the same path (mm).
constexpr double kPlanSamePathToleranceMm = 0.01;
// A stop ends a plate when the torch is this close to where the program started (mm).
constexpr double kPlanHomeToleranceMm = 0.5;
// Closure is looked for among a cut's motions by comparing each end with every earlier point up to this many
// motions; longer cuts are compared with their first kPlanLeadMotions points only.
constexpr std::size_t kPlanFullClosureMotions = 512;
constexpr std::size_t kPlanLeadMotions = 4;
// A plate is analysed in parts of at most this many cutting motions (the first cut that ends past it closes the
// part; N614 says where): the memory a plate takes is bounded whatever the tape (about 160 bytes a motion while it
// is analysed), at the price of not comparing cuts of different parts. A real plate has far fewer.
constexpr std::size_t kPlanMaxPlateMotions = std::size_t{1} << 17;
// A plate is also analysed in parts of at most this many points of its contours flattened (a line is one point, an
// arc or a parabola up to kPlanMaxArcChords): big arcs make long polygons. A single cut of more points than this
// is left out of the cut plan's tests (N615): what a plate holds while it is analysed stays bounded.
constexpr std::size_t kPlanMaxPlatePoints = std::size_t{1} << 19;

enum class ContourRole : std::uint8_t {
    Part,      // holds holes, or lies inside a hole (even depth >= 2)
    Hole,      // inside another contour (odd depth)
    LonePart,  // lone, its kerf outside: a part by its program
    LoneHole,  // lone, its kerf inside: a hole in the plate by its program
    Lone,      // lone, no kerf compensation: unknown
};
[[nodiscard]] const char* contour_role_name(ContourRole r);  // "part", "hole", "lone-part", "lone-hole", "lone"

// A cut contour as the analysis found it (plan_contours, for tests and tools): the Contour (essi/contour.hpp) of
// the whole cut, pierce to torch off, with its loop and role.
struct PlanContour : Contour {
    // Its loop: the contour's motions [loop_begin, loop_end) (0: its first; contour_motions), from loop_start
    // round to loop_start again (within the arc tolerance). loop_start is the first one's start or a point on it
    // (where the path closes on a line, or at a parabola's chord); the loop ends at the last one's end or at a
    // point on it (a parabola's chord). Their lines:
    std::uint32_t loop_begin = 0, loop_end = 0;
    Point loop_start;
    std::uint32_t loop_first_line = 0, loop_last_line = 0;
    int plate = 1;
    int parent = -1;  // index (in plan_contours' list, or CutPlan::contours()) of the contour it lies in directly
    int depth = 0;
    ContourRole role = ContourRole::Lone;
    double area_mm2 = 0;  // signed: > 0 counter-clockwise (parabolas by their chords)
    KerfSide kerf = KerfSide::Off;
    bool lead_in = false;
};

// Where a plate's analysis runs. Without one, a plate is analysed when it ends, on the thread that feeds the plan;
// natively the pipelined check passes one whose plates its reading thread analyses while the interpreter goes on (the
// core starts no thread). The analysis of a plate depends on nothing but that plate.
class PlateRunner {
public:
    virtual ~PlateRunner() = default;
    // Runs `job` before wait() returns (it may wait for room first); `motions`: the plate's cutting motions, what
    // its memory is in proportion to.
    virtual void run(std::function<void()> job, std::size_t motions) = 0;
    // Returns once every job given has run.
    virtual void wait() = 0;
};

// A plate's contours with their cutting motions, as the cut plan hands them on (CutPlan::keep_plate_motions): what
// the parts list (essi/parts.hpp) is made from in the check's own pass.
struct MotionRange {
    std::uint32_t first = 0, end = 0;
};
struct PlateContours {
    std::span<const PlanContour> contours;  // as contours() lists them, a parent an index in this span
    std::span<const MotionRecord> motions;  // the plate's cutting motions
    std::span<const MotionRange> ranges;    // contour k's: motions[ranges[k].first, ranges[k].end)
    [[nodiscard]] std::span<const MotionRecord> of(std::size_t k) const {
        return motions.subspan(ranges[k].first, ranges[k].end - ranges[k].first);
    }
};
class PlateContoursSink {
public:
    virtual ~PlateContoursSink() = default;
    // One plate, after its analysis, in plate order on the thread that feeds the plan.
    virtual void on_plate(const PlateContours& plate) = 0;
};

// The cut plan of one tape, fed the motion stream (a MotionSink): diagnostics come out when a plate ends and at
// finish(). TapeChecker runs one on every tape it checks.
class CutPlan final : public MotionSink {
public:
    explicit CutPlan(const Profile& profile, bool keep_contours = false);
    ~CutPlan() override;
    CutPlan(const CutPlan&) = delete;
    CutPlan& operator=(const CutPlan&) = delete;

    void on_motion(const MotionRecord& m) override;
    void on_line(const UnitLine& l) override;
    void on_event(const MachineEvent& e) override;
    // Plates are analysed by `runner` from now on (null: at once). It must outlive finish().
    void set_runner(PlateRunner* runner);
    // Plates are not analysed when they end but kept as where their cuts are in the stream (a few bytes a cut, not
    // their motions), to be analysed later from `store`, the motions of the stream this plan was fed
    // (analyse_deferred_plate, or finish). Before the first motion; `store` must hold every motion given to this
    // plan by then and outlive it.
    void defer_plates(const MotionStore* store);
    // Each plate's contours and their cutting motions go to `sink` once the plate is analysed (the plate's cutting
    // motions are kept as records until then: a plate's parts are bounded by kPlanMaxPlateMotions and
    // kPlanMaxPlatePoints). Before the first motion; `sink` must outlive finish(). Not with defer_plates.
    void keep_plate_motions(PlateContoursSink* sink);
    // After the last motion: the last plate ended (analysed, handed to the runner, or kept when deferred).
    void end_input();
    // Analyses the next plate kept by defer_plates (after end_input, or between motions); false when none is left.
    bool analyse_deferred_plate();
    // Plates kept and not analysed yet, and all plates kept so far (for a progress bar).
    [[nodiscard]] std::size_t deferred_plates_left() const;
    [[nodiscard]] std::size_t deferred_plates() const;
    // After the last motion: every plate analysed (end_input first if it was not called); the diagnostics found
    // (unsorted). Call once.
    [[nodiscard]] std::vector<Diagnostic> finish();
    // The contours analysed, when keep_contours.
    [[nodiscard]] const std::vector<PlanContour>& contours() const;

private:
    struct State;
    std::unique_ptr<State> s_;
};

// The contours of a tape and their roles (reads and interprets it; for tests and tools).
[[nodiscard]] std::vector<PlanContour> plan_contours(std::string_view bytes, const Profile& profile,
                                                     InputFormat format = InputFormat::Essi);

}  // namespace essi
