// The cut plan's sink (essi/plan.hpp): cuts collected from the motion stream, plate by plate, and the rules that
// need no contour (feed, dwell, a cut larger than the table).
#include "essi/plan.hpp"

#include <algorithm>
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

struct CutPlan::State {
    const Profile& profile;
    bool keep_contours;
    double closure_mm;
    std::vector<plan::Cut> cuts;       // the plate's cuts, in cutting order
    plan::Cut open[2];                 // the cut of each head in progress
    bool cutting[2] = {false, false};
    KerfSide open_kerf[2] = {KerfSide::Off, KerfSide::Off};
    bool mixed_kerf[2] = {false, false};
    int plate = 1;
    bool moved = false;
    Point home, here;                  // where the program started, where head 1 is
    std::uint32_t feed_line = 0;       // the block that set the feed in force (39), 0: the profile's
    double reported_feed = -1;         // the out-of-range feed last reported (once per change)
    std::vector<Diagnostic> found;
    std::vector<PlanContour> contours;

    explicit State(const Profile& p, bool keep)
        : profile(p), keep_contours(keep), closure_mm(p.arc_tolerance_units * p.unit_mm) {}

    void add(const MotionRecord& m) {
        if (!moved) {
            home = m.start;
            moved = true;
        }
        if (m.head != 2) here = m.end;
        const int h = m.head == 2 ? 1 : 0;
        if (m.kind != MotionKind::Cut) {
            close(h);
            return;
        }
        check_feed(m.line, m.feed_mm_min);
        plan::Cut& c = open[h];
        if (!cutting[h]) {
            c = plan::Cut{};
            c.first_line = m.line;
            cutting[h] = true;
            open_kerf[h] = m.kerf;
            mixed_kerf[h] = false;
        }
        if (m.kerf != open_kerf[h]) mixed_kerf[h] = true;
        c.kerf_width_mm = std::max(c.kerf_width_mm, 2 * m.kerf_mm);
        c.last_line = m.line;
        c.length_mm += m.length_mm;
        c.box.add(bounding_box(m));
        if (m.curve == CurveKind::Parabola) {
            std::vector<Point> pts;
            flatten(m, kPlanChordToleranceMm, pts, /*include_start*/ true);
            for (std::size_t k = 1; k < pts.size(); ++k)
                c.pieces.push_back({pts[k - 1], pts[k], {}, 0, 0, std::hypot(pts[k].x - pts[k - 1].x, pts[k].y - pts[k - 1].y), m.line, false});
            return;
        }
        c.pieces.push_back({m.start, m.end, m.centre, m.sweep, m.radius, m.length_mm, m.line, m.curve == CurveKind::Arc});
    }

    void close(int h) {
        if (!cutting[h]) return;
        cutting[h] = false;
        plan::Cut& c = open[h];
        c.kerf = mixed_kerf[h] ? KerfSide::Off : open_kerf[h];
        if (c.kerf == KerfSide::Off) c.kerf_width_mm = 0;
        c.order = static_cast<int>(cuts.size());
        plan::close_loop(c, closure_mm, profile.closure_gap_mm);
        check_table(c);
        cuts.push_back(std::move(c));
    }

    void end_plate() {
        close(0);
        close(1);
        if (cuts.empty()) return;
        const plan::PlateSettings st{closure_mm, profile.closure_gap_mm, profile.lead_in_required, plate};
        plan::analyse_plate(cuts, st, found, keep_contours ? &contours : nullptr);
        cuts.clear();
        ++plate;
    }

    // W608: a cut at a feed outside feed_range_mm_min, once each time the feed changes.
    void check_feed(std::uint32_t line, double feed) {
        if (feed >= profile.feed_min_mm_min && feed <= profile.feed_max_mm_min) {
            reported_feed = -1;
            return;
        }
        if (feed == reported_feed) return;
        reported_feed = feed;
        Diagnostic d = make_diagnostic(Severity::Warning, DiagCode::W608_FeedOutOfRange, line, 0, Msg::PlanFeed,
                                       {number_text(feed), number_text(profile.feed_min_mm_min),
                                        number_text(profile.feed_max_mm_min)});
        if (feed_line > 0) d.related.push_back({feed_line, feed_line, Msg::RelatedFeedSet, {}});
        found.push_back(std::move(d));
    }

    // W611: a cut larger than the table's travel.
    void check_table(const plan::Cut& c) {
        if (!profile.table || c.box.empty) return;
        const double tw = profile.table->max_x_mm - profile.table->min_x_mm, th = profile.table->max_y_mm - profile.table->min_y_mm;
        const double w = c.box.max_x - c.box.min_x, h = c.box.max_y - c.box.min_y;
        if (w <= tw && h <= th) return;
        Diagnostic d = make_diagnostic(Severity::Warning, DiagCode::W611_CutLargerThanTable, c.first_line, 0,
                                       Msg::PlanLargerThanTable, {number_text(w), number_text(h), number_text(tw), number_text(th)});
        d.contour_first = c.first_line;
        d.contour_last = c.last_line;
        found.push_back(std::move(d));
    }

    void event(const MachineEvent& e) {
        if (e.kind == EventKind::Function && e.code == fn::kFeed) feed_line = e.line;
        if (e.kind == EventKind::Dwell && e.value > profile.max_dwell_s)
            found.push_back(make_diagnostic(Severity::Warning, DiagCode::W609_DwellTooLong, e.line, 0, Msg::PlanDwell,
                                            {number_text(e.value), number_text(profile.max_dwell_s)}));
        if (!(e.tools_after & kCuttingTools)) {
            close(0);
            close(1);
        }
        const bool at_home = moved && std::hypot(here.x - home.x, here.y - home.y) <= kPlanHomeToleranceMm;
        if (e.kind == EventKind::Stop && at_home && !(e.tools_after & kCuttingTools)) end_plate();
    }
};

CutPlan::CutPlan(const Profile& profile, bool keep_contours) : s_(std::make_unique<State>(profile, keep_contours)) {}
CutPlan::~CutPlan() = default;

void CutPlan::on_motion(const MotionRecord& m) { s_->add(m); }
void CutPlan::on_line(const UnitLine& l) { s_->add(record_of(l)); }
void CutPlan::on_event(const MachineEvent& e) { s_->event(e); }

std::vector<Diagnostic> CutPlan::finish() {
    s_->end_plate();
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
