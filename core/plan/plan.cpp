// The cut plan's sink (essi/plan.hpp): cuts collected from the motion stream, plate by plate, and the rules that
// need no contour (feed, dwell, a cut larger than the table).
#include "essi/plan.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "essi/interp.hpp"
#include "essi/read.hpp"
#include "essi/text.hpp"
#include "plan_internal.hpp"

namespace essi {

const char* contour_role_name(ContourRole r) {
    switch (r) {
        case ContourRole::Part: return "part";
        case ContourRole::Hole: return "hole";
        case ContourRole::LonePart: return "lone-part";
        case ContourRole::LoneHole: return "lone-hole";
        case ContourRole::Lone: return "lone";
    }
    return "?";
}

namespace {

// A plate handed over: its cuts and pieces, and what its analysis finds.
struct PlateJob {
    std::vector<plan::Cut> cuts;
    std::vector<plan::Piece> pieces;
    plan::PlateSettings settings;
    bool keep_contours = false;
    bool keep_motions = false;  // the cuts' records, for a PlateContoursSink
    std::vector<MotionRecord> records;
    std::vector<MotionRange> ranges;  // of each contour's records (keep_motions)
    std::vector<Diagnostic> found;
    DiagnosticCap cap;  // max_per_code within the plate (what it left out is counted for the tape)
    std::vector<PlanContour> contours;
    std::atomic<bool> done{false};  // run() has returned (on whichever thread ran it)
    void run() {
        cap = DiagnosticCap(settings.max_per_code);
        for (plan::Cut& c : cuts) plan::close_loop(c, pieces, settings.closure_mm, settings.gap_limit_mm);
        plan::analyse_plate(cuts, pieces, settings, found, cap, keep_contours ? &contours : nullptr);
        if (keep_motions) record_ranges();
        std::vector<plan::Cut>().swap(cuts);  // (only the findings are kept until they are folded in)
        std::vector<plan::Piece>().swap(pieces);
        done.store(true, std::memory_order_release);
    }
    // Each contour's records: its cut's (the contours are cuts, in cutting order, some left out).
    void record_ranges() {
        ranges.reserve(contours.size());
        for (const plan::Cut& c : cuts)
            if (ranges.size() < contours.size() && contours[ranges.size()].first_motion == c.first_motion)
                ranges.push_back({c.first_record, c.end_record});
    }
};

// A plate kept by defer_plates: where each cut is in the stream (its motions are read back to analyse it).
struct DeferredCut {
    Contour contour;
    double kerf_width_mm;
    KerfSide kerf;
};
struct DeferredPlate {
    std::vector<DeferredCut> cuts;
    plan::PlateSettings settings;
};

}  // namespace

namespace plan {

void append_parabola(const MotionRecord& m, std::vector<Piece>& out) {
    std::vector<Point> pts;
    flatten(m, kPlanChordToleranceMm, pts, /*include_start*/ true, kPlanMaxArcChords);
    for (std::size_t k = 1; k < pts.size(); ++k) out.push_back({pts[k - 1], pts[k], {}, 0, 0, m.line, false, k > 1});
}

}  // namespace plan

struct CutPlan::State {
    const Profile& profile;
    bool keep_contours;
    double closure_mm;
    std::vector<plan::Cut> cuts;      // the plate's cuts, in cutting order
    std::vector<plan::Piece> pieces;  // their pieces, cut after cut
    // The cut of each head in progress (the cut contours: marks are no part of the plan). Head 1's pieces go
    // straight to the plate's; head 2's are gathered apart (the heads' motions interleave) and join the plate's
    // when it ends, or after head 1's cut if that is still going.
    ContourBuilder<plan::Cut, kCuttingTools> cuts_found;
    std::vector<plan::Piece> head2_pieces;
    std::vector<plan::Cut> deferred;  // head 2's cuts that ended while head 1 was cutting, with their pieces
    std::vector<std::vector<plan::Piece>> deferred_pieces;
    // keep_plate_motions: the plate's cutting motions as records, beside the pieces (head 2's apart as its pieces)
    PlateContoursSink* plate_sink = nullptr;
    std::vector<MotionRecord> records, head2_records;
    std::vector<std::vector<MotionRecord>> deferred_records;
    int plate = 1;
    bool moved = false;
    Point home, here;               // where the program started, where head 1 is
    std::uint32_t feed_line = 0;    // the block that set the feed in force (39), 0: the profile's
    double checked_feed = -1;       // the feed of the last cut motion (checked, and reported, once per change)
    std::vector<Diagnostic> found;  // as far as `cap` admits them: the stream's, then each plate's in plate order
    DiagnosticCap cap;              // max_per_code for the tape
    std::vector<PlanContour> contours;
    PlateRunner* runner = nullptr;
    std::vector<std::unique_ptr<PlateJob>> jobs;  // the plates handed over, in order
    std::size_t folded = 0;                       // jobs[0, folded) are folded into `found` (and freed)
    std::size_t plate_motions = 0;       // cutting motions of the plate so far (its part: kPlanMaxPlateMotions)
    std::size_t plate_points = 0;        // their points flattened, as held (its part: kPlanMaxPlatePoints)
    std::size_t cut_points[2] = {0, 0};  // the open cut's points flattened
    bool too_long[2] = {false, false};   // the open cut has more than kPlanMaxPlatePoints: left out (N615)
    std::size_t overlap_points_left = kPlanMaxOverlapPointsPerTape;  // for the collisions' overlap polygons
    bool ended = false;                                              // end_input() was called
    // defer_plates: the store the plates' motions are read back from, and the plates kept (the first
    // `next_deferred` of them analysed).
    const MotionStore* store = nullptr;
    std::vector<DeferredPlate> deferred_plates;
    std::size_t next_deferred = 0;

    explicit State(const Profile& p, bool keep)
        : profile(p), keep_contours(keep), closure_mm(p.arc_tolerance_units * p.unit_mm), cap(p.max_per_code) {}

    // Where the program started and where head 1 is.
    void passed(int head, Point start, Point end) {
        if (!moved) {
            home = start;
            moved = true;
        }
        if (head == 0) here = end;
    }
    // Whether head `h` (0, 1) is cutting.
    bool cutting(int h) const { return cuts_found.open(static_cast<std::uint8_t>(h + 1)) != nullptr; }
    // Where a cut goes when it ends.
    auto cut_ended() {
        return [this](plan::Cut& c) { end_cut(c); };
    }
    // A cut begins, its first motion cut with this kerf.
    void begin_cut(plan::Cut& c, KerfSide kerf) {
        c.kerf = kerf;
        if (c.head == 2) head2_pieces.clear();
        if (c.head == 2) head2_records.clear();
        c.first_piece = static_cast<std::uint32_t>(pieces.size());
        c.first_record = static_cast<std::uint32_t>(records.size());
        const int h = c.head == 2 ? 1 : 0;
        cut_points[h] = 0;
        too_long[h] = false;
    }
    // The cut `c` of head `h` gets a motion of line `line` and `points` points, cut with this kerf.
    void cut_of(plan::Cut& c, int h, std::uint32_t line, KerfSide kerf, double kerf_mm, double feed,
                std::size_t points) {
        if (feed != checked_feed) [[unlikely]]
            check_feed(line, feed);
        ++plate_motions;
        count_points(c, h, points);
        if (kerf != c.kerf) [[unlikely]]
            c.kerf_changed = true;
        if (2 * kerf_mm > c.kerf_width_mm) [[unlikely]]
            c.kerf_width_mm = 2 * kerf_mm;
    }
    // Head 1's pieces go straight to the plate's; head 2's wait apart (the heads' motions interleave).
    std::vector<plan::Piece>& pieces_of(int h) { return h == 0 ? pieces : head2_pieces; }
    // The open cut of head `h` grows by `points`; past kPlanMaxPlatePoints it is left out and its pieces dropped.
    void count_points(const plan::Cut& c, int h, std::size_t points) {
        cut_points[h] += points;
        if (cut_points[h] > kPlanMaxPlatePoints) [[unlikely]] {
            drop_long_cut(c, h, points);
            return;
        }
        plate_points += points;
    }
    [[gnu::noinline]] void drop_long_cut(const plan::Cut& c, int h, std::size_t points) {
        if (too_long[h]) return;
        too_long[h] = true;
        plate_points -= cut_points[h] - points;  // (what the cut added before this motion)
        if (h == 0) pieces.resize(c.first_piece);
        else head2_pieces.clear();
        if (h == 0) records.resize(c.first_record);
        else head2_records.clear();
    }
    // Whether the pieces of head `h`'s motion are kept (not when the plate's motions are read back from a store, nor
    // for a cut left out).
    bool keeps_pieces(int h) const { return !store && !too_long[h]; }

    void add(const MotionRecord& m) {
        const int h = m.head == 2 ? 1 : 0;
        passed(h, m.start, m.end);
        const auto began = [&](plan::Cut& cut) { begin_cut(cut, m.kerf); };
        plan::Cut* c = cuts_found.motion(m, began, cut_ended());
        if (!c) return;
        cut_of(*c, h, m.line, m.kerf, m.kerf_mm, m.feed_mm_min, plan::plan_points(m));
        if (!keeps_pieces(h)) return;
        plan::append_pieces(m, pieces_of(h));
        if (plate_sink) [[unlikely]]
            (h == 0 ? records : head2_records).push_back(m);
    }
    // A straight motion of head 1 (most of a tape): no record made.
    [[gnu::flatten]] void add(const UnitLine& l) {
        passed(0, l.start, l.end);
        const auto began = [&](plan::Cut& cut) { begin_cut(cut, l.kerf); };
        plan::Cut* c = cuts_found.motion(l, began, cut_ended());
        if (!c) return;
        cut_of(*c, 0, l.line, l.kerf, l.kerf_mm, l.feed_mm_min, 1);
        if (!keeps_pieces(0)) return;
        pieces.push_back({l.start, l.end, {}, 0, 0, l.line, false});
        if (plate_sink) [[unlikely]]
            records.push_back(record_of(l));
    }

    void end_cut(plan::Cut& c) {
        const int h = c.head == 2 ? 1 : 0;
        c.points = too_long[h] ? 0 : cut_points[h];
        if (too_long[h]) [[unlikely]]
            leave_out(c);
        if (c.kerf_changed) c.kerf = KerfSide::Off;
        if (c.kerf == KerfSide::Off) c.kerf_width_mm = 0;
        const bool head2 = c.head == 2;
        if (head2) {
            if (cutting(0)) {  // (head 1's cut is filling the plate's pieces: head 2's joins after it)
                deferred.push_back(std::move(c));
                deferred_pieces.push_back(std::move(head2_pieces));
                deferred_records.push_back(std::move(head2_records));
                return;
            }
            join(c, head2_pieces, head2_records);
        }
        finish_cut(c);
        if (!head2 && !deferred.empty()) {
            for (std::size_t k = 0; k < deferred.size(); ++k) {
                join(deferred[k], deferred_pieces[k], deferred_records[k]);
                finish_cut(deferred[k]);
            }
            deferred.clear();
            deferred_pieces.clear();
            deferred_records.clear();
        }
    }
    // A cut of head 2, its pieces and records gathered apart, joins the plate's.
    void join(plan::Cut& c, const std::vector<plan::Piece>& its_pieces, const std::vector<MotionRecord>& its_records) {
        c.first_piece = static_cast<std::uint32_t>(pieces.size());
        pieces.insert(pieces.end(), its_pieces.begin(), its_pieces.end());
        c.first_record = static_cast<std::uint32_t>(records.size());
        records.insert(records.end(), its_records.begin(), its_records.end());
    }
    // A cut of more points than a plate's part holds: no pieces and no motions (a store gives none back), so the
    // plate's tests pass over it; N615 says so.
    void leave_out(plan::Cut& c) {
        c.end_motion = c.first_motion;
        if (!cap.admit(DiagCode::N615_CutTooLong, c.first_line, Severity::Note)) return;
        Diagnostic d = make_diagnostic(Severity::Note, DiagCode::N615_CutTooLong, c.first_line, 0, Msg::PlanCutTooLong,
                                       {c.first_line, c.last_line, kPlanMaxPlatePoints});
        d.contour_first = c.first_line;
        d.contour_last = c.last_line;
        found.push_back(std::move(d));
    }
    void finish_cut(plan::Cut& c) {
        c.end_piece = static_cast<std::uint32_t>(pieces.size());
        c.end_record = static_cast<std::uint32_t>(records.size());
        c.order = static_cast<int>(cuts.size());
        cuts.push_back(std::move(c));
        if ((plate_motions >= kPlanMaxPlateMotions || plate_points >= kPlanMaxPlatePoints) && !cutting(0) &&
            !cutting(1)) [[unlikely]]
            split_plate();
    }
    // The plate so far is analysed as a part of its own (N614 after its last cut): a plate's memory is bounded.
    void split_plate() {
        const std::uint32_t last = cuts.back().last_line;
        if (cap.admit(DiagCode::N614_PlateSplit, last, Severity::Note)) {
            const bool by_motions = plate_motions >= kPlanMaxPlateMotions;
            found.push_back(make_diagnostic(Severity::Note, DiagCode::N614_PlateSplit, last, 0,
                                            by_motions ? Msg::PlanPlateSplit : Msg::PlanPlateSplitPoints,
                                            {last, by_motions ? kPlanMaxPlateMotions : kPlanMaxPlatePoints}));
        }
        end_plate();
    }

    plan::PlateSettings settings() const {
        return {closure_mm, profile.closure_gap_mm, profile.lead_in_required,
                plate,      profile.table,          profile.max_per_code};
    }
    // The plate ends (no cut is going on).
    void end_plate() {
        // (the runner's queue weighs a plate by its motions, or by its points at the scale of the motions' limit)
        const std::size_t weight = std::max(plate_motions, plate_points / (kPlanMaxPlatePoints / kPlanMaxPlateMotions));
        plate_motions = 0;
        plate_points = 0;
        if (cuts.empty()) return;
        if (store) {
            keep_plate();
            return;
        }
        auto job = std::make_unique<PlateJob>();
        job->cuts.swap(cuts);
        job->pieces.swap(pieces);
        job->settings = settings();
        cuts.reserve(job->cuts.size());  // (the next plate is likely as large)
        pieces.reserve(job->pieces.size());
        job->keep_contours = keep_contours || plate_sink;
        job->keep_motions = plate_sink != nullptr;
        job->records.swap(records);
        records.reserve(job->records.size());
        PlateJob* j = job.get();
        jobs.push_back(std::move(job));
        if (runner) runner->run([j] { j->run(); }, weight);
        else j->run();
        ++plate;
        fold_done();
    }
    // The findings of the plates analysed so far, in plate order, through the tape's cap; their jobs freed. So at
    // most the runner's waiting plates hold findings beside the tape's `found`, however many plates a tape has.
    void fold_done() {
        while (folded < jobs.size() && jobs[folded]->done.load(std::memory_order_acquire)) {
            PlateJob& j = *jobs[folded];
            const std::size_t first_new = found.size();
            cap.move_admitted(j.found, found);
            for (std::size_t k = first_new; k < found.size(); ++k) keep_overlap_within_budget(found[k]);
            cap.add_omitted(j.cap);
            if (j.keep_motions) plate_sink->on_plate({j.contours, j.records, j.ranges});
            if (keep_contours) {
                const int before = static_cast<int>(contours.size());  // (the plate's parents: in the plate's list)
                for (PlanContour& c : j.contours) {
                    if (c.parent >= 0) c.parent += before;
                    contours.push_back(std::move(c));
                }
            }
            jobs[folded++].reset();
        }
    }
    // A collision keeps its overlap polygons while the tape's so far hold at most kPlanMaxOverlapPointsPerTape
    // points; later ones go without (the report's size stays bounded whatever the collisions).
    void keep_overlap_within_budget(Diagnostic& d) {
        std::size_t points = 0;
        for (const std::vector<Point>& polygon : d.overlap()) points += polygon.size();
        if (points == 0) return;
        if (points > overlap_points_left) {
            d.set_overlap({});
            overlap_points_left = 0;
            return;
        }
        overlap_points_left -= points;
    }
    // defer_plates: the plate's cuts kept as where they are in the stream.
    void keep_plate() {
        DeferredPlate kept{{}, settings()};
        kept.cuts.reserve(cuts.size());
        for (const plan::Cut& c : cuts) kept.cuts.push_back({c, c.kerf_width_mm, c.kerf});
        deferred_plates.push_back(std::move(kept));
        cuts.clear();
        pieces.clear();
        ++plate;
    }
    // The next kept plate: its cuts and pieces made again from the store's motions, analysed at once.
    bool analyse_deferred() {
        if (next_deferred == deferred_plates.size()) return false;
        DeferredPlate& kept = deferred_plates[next_deferred++];
        auto job = std::make_unique<PlateJob>();
        job->settings = kept.settings;
        job->keep_contours = keep_contours;
        for (const DeferredCut& d : kept.cuts) {
            plan::Cut c;
            static_cast<Contour&>(c) = d.contour;
            c.kerf = d.kerf;
            c.kerf_width_mm = d.kerf_width_mm;
            c.order = static_cast<int>(job->cuts.size());
            c.first_piece = static_cast<std::uint32_t>(job->pieces.size());
            for (std::uint32_t k = c.first_motion; k < c.end_motion; ++k) {
                const MotionRecord m = store->motion(k);
                if (!of_contour(c, m)) continue;
                plan::append_pieces(m, job->pieces);
                c.points += plan::plan_points(m);
            }
            c.end_piece = static_cast<std::uint32_t>(job->pieces.size());
            job->cuts.push_back(c);
        }
        std::vector<DeferredCut>().swap(kept.cuts);
        job->run();
        jobs.push_back(std::move(job));
        fold_done();
        return true;
    }

    // After the last plate: every plate's findings, in plate order.
    void collect() {
        if (runner) runner->wait();
        fold_done();
        jobs.clear();
        folded = 0;
        cap.append_summaries(found);
    }

    // W608: a cut at a feed outside feed_range_mm_min, once each time the feed changes.
    void check_feed(std::uint32_t line, double feed) {
        checked_feed = feed;
        if (feed >= profile.feed_min_mm_min && feed <= profile.feed_max_mm_min) return;
        Diagnostic d = make_diagnostic(
            Severity::Warning, DiagCode::W608_FeedOutOfRange, line, 0, Msg::PlanFeed,
            {number_text(feed), number_text(profile.feed_min_mm_min), number_text(profile.feed_max_mm_min)});
        if (feed_line > 0) d.add_related({feed_line, feed_line, Msg::RelatedFeedSet, {}});
        if (cap.admit(d)) found.push_back(std::move(d));
    }

    void event(const MachineEvent& e) {
        if (e.kind == EventKind::Function && e.code == fn::kFeed) feed_line = e.line;
        if (e.kind == EventKind::Dwell && e.value > profile.max_dwell_s &&
            cap.admit(DiagCode::W609_DwellTooLong, e.line, Severity::Warning))
            found.push_back(make_diagnostic(Severity::Warning, DiagCode::W609_DwellTooLong, e.line, 0, Msg::PlanDwell,
                                            {number_text(e.value), number_text(profile.max_dwell_s)}));
        cuts_found.event(e.tools_after, cut_ended());
        if (e.kind == EventKind::Stop && !(e.tools_after & kCuttingTools) && moved &&
            std::hypot(here.x - home.x, here.y - home.y) <= kPlanHomeToleranceMm)
            end_plate();
    }
};

CutPlan::CutPlan(const Profile& profile, bool keep_contours) : s_(std::make_unique<State>(profile, keep_contours)) {}
CutPlan::~CutPlan() = default;

void CutPlan::on_motion(const MotionRecord& m) { s_->add(m); }
void CutPlan::on_line(const UnitLine& l) { s_->add(l); }
void CutPlan::on_event(const MachineEvent& e) { s_->event(e); }

void CutPlan::set_runner(PlateRunner* runner) { s_->runner = runner; }
void CutPlan::defer_plates(const MotionStore* store) { s_->store = store; }
void CutPlan::keep_plate_motions(PlateContoursSink* sink) { s_->plate_sink = sink; }

void CutPlan::end_input() {
    if (s_->ended) return;
    s_->ended = true;
    s_->cuts_found.end(s_->cut_ended());
    s_->end_plate();
}

bool CutPlan::analyse_deferred_plate() { return s_->analyse_deferred(); }
std::size_t CutPlan::deferred_plates_left() const { return s_->deferred_plates.size() - s_->next_deferred; }
std::size_t CutPlan::deferred_plates() const { return s_->deferred_plates.size(); }

std::vector<Diagnostic> CutPlan::finish() {
    end_input();
    while (s_->analyse_deferred()) {
    }
    s_->collect();
    return std::move(s_->found);
}

const std::vector<PlanContour>& CutPlan::contours() const { return s_->contours; }

std::vector<PlanContour> plan_contours(std::string_view bytes, const Profile& profile, InputFormat format) {
    CutPlan plan(profile, /*keep_contours*/ true);
    const Tape tape = read_tape(bytes, profile, format);
    std::vector<Diagnostic> ignored;
    interpret(tape, bytes, profile, plan, ignored);
    (void)plan.finish();
    return plan.contours();
}

}  // namespace essi
