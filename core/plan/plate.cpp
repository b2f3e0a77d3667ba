// One plate's cuts analysed (essi/plan.hpp): the same path twice, roles by nesting, the kerf side, the cutting
// order, collisions and cuts across parts already cut free.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "essi/text.hpp"
#include "grid.hpp"
#include "plan_internal.hpp"

namespace essi::plan {
namespace {

// The sweep that finds a plate's neighbours gives up for the grid past this many comparisons a cut on average.
constexpr std::size_t kSweepComparisonsPerCut = 48;
// The grid's search for neighbours stops (N613) once it has found this many pairs, or looked at this many
// candidates, a cut on average (plus a base for small plates): a real nest has a few neighbours a cut; contours
// piled over each other would have every pair. So the pairs a plate compares are at most
// kPairsPerCut * cuts + kPairsBase, whatever the plate.
constexpr std::size_t kPairsPerCut = 64, kPairsBase = 65536;
constexpr std::size_t kVisitsPerCut = 1024, kVisitsBase = 1 << 20;
// A pair's tests cost about the two contours' points flattened (arcs of up to kPlanMaxArcChords chords): the pairs
// found weigh that much, and the search stops (N613) once they weigh kPairPointsPerPoint times the plate's points
// plus kPairPointsBase. So the tests' work is linear in the plate's points (contours piled over each other, big
// arcs), and an ordinary plate never reaches it.
constexpr std::size_t kPairPointsPerPoint = 32, kPairPointsBase = std::size_t{1} << 24;

struct Node {
    int parent = -1;
    int depth = 0;
    int children = 0;
    bool duplicate = false;  // the same path as an earlier cut: left out of the nesting
    ContourRole role = ContourRole::Lone;
};

// v in whole steps of `step` (the same-path test's keys and points).
long long quantized(double v, double step) { return static_cast<long long>(std::floor(v / step + 0.5)); }

bool is_part(ContourRole r) { return r == ContourRole::Part || r == ContourRole::LonePart; }
// Contours that can collide: parts, lone contours of unknown role, and holes in the plate (with a part: a hole in the
// plate overlapping a part cuts into it; two of them make a slot).
bool collides(ContourRole r) { return is_part(r) || r == ContourRole::Lone || r == ContourRole::LoneHole; }
bool collides_as_pair(ContourRole a, ContourRole b) {
    return collides(a) && collides(b) && !(a == ContourRole::LoneHole && b == ContourRole::LoneHole);
}

class Plate {
public:
    Plate(std::vector<Cut>& cuts, std::span<const Piece> pieces, const PlateSettings& st, std::vector<Diagnostic>& out,
          DiagnosticCap& cap)
        : cuts_(cuts), pieces_(pieces), st_(st), out_(out), cap_(cap), nodes_(cuts.size()) {
        std::size_t total = 0;
        for (const Cut& c : cuts_) {
            max_width_ = std::max(max_width_, c.kerf_width_mm);
            total += c.points;
        }
        pair_points_budget_ = kPairPointsPerPoint * total + kPairPointsBase;
        pair_points_left_ = pair_points_budget_;
    }

    void run() {
        table();
        gaps();
        same_paths();
        find_neighbours();
        nest();
        kerf_sides();
        order();
        collisions();
        lead_ins();
    }
    // The plate's contours with a loop (not the same path again), in cutting order, appended to `contours`: a
    // parent is an index in that list.
    void record(std::vector<PlanContour>& contours) const {
        std::vector<int> index_of(cuts_.size(), -1);  // (a parent is a usable cut, cut before or after its child)
        int next = static_cast<int>(contours.size());
        for (std::size_t i = 0; i < cuts_.size(); ++i)
            if (usable(i)) index_of[i] = next++;
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            const Cut& c = cuts_[i];
            if (!usable(i)) continue;
            PlanContour pc;
            static_cast<Contour&>(pc) = c;
            pc.loop_begin = motion_of_piece(c, pieces_, c.loop_begin);
            pc.loop_end = motion_of_piece(c, pieces_, c.loop_end - 1) + 1;
            pc.loop_start = c.loop_start;
            pc.loop_first_line = pieces_[c.loop_begin].line;
            pc.loop_last_line = pieces_[c.loop_end - 1].line;
            pc.plate = st_.plate;
            pc.parent = nodes_[i].parent < 0 ? -1 : index_of[static_cast<std::size_t>(nodes_[i].parent)];
            pc.depth = nodes_[i].depth;
            pc.role = nodes_[i].role;
            pc.area_mm2 = c.area_mm2;
            pc.kerf = c.kerf;
            pc.lead_in = c.loop_begin > c.first_piece;
            contours.push_back(pc);
        }
    }

private:
    // --- helpers ---
    Diagnostic about(DiagCode code, const Cut& c, Point at, Msg msg, MessageArgs args) const {
        Diagnostic d = make_diagnostic(default_severity(code), code, c.first_line, 0, msg, std::move(args));
        d.contour_first = c.first_line;
        d.contour_last = c.last_line;
        d.has_at = true;
        d.at = at;
        return d;
    }
    static RelatedLocation related(const Cut& c, Msg what) { return {c.first_line, c.last_line, what, {}}; }
    bool usable(std::size_t i) const { return cuts_[i].closed && !nodes_[i].duplicate; }
    const Piece& first_piece(const Cut& c) const { return pieces_[c.first_piece]; }
    const Piece& last_piece(const Cut& c) const { return pieces_[c.end_piece - 1]; }
    // The loop of cut i flattened (made once, when a test needs it).
    const std::vector<Point>& polygon(std::size_t i) {
        if (polygons_.empty()) polygons_.resize(cuts_.size());
        if (polygons_[i].empty()) polygons_[i] = loop_polygon(cuts_[i], pieces_);
        return polygons_[i];
    }

    // --- W611: a cut larger than the table's travel ---
    void table() {
        if (!st_.table) return;
        const double tw = st_.table->max_x_mm - st_.table->min_x_mm, th = st_.table->max_y_mm - st_.table->min_y_mm;
        for (const Cut& c : cuts_) {
            const double w = c.box.max_x - c.box.min_x, h = c.box.max_y - c.box.min_y;
            if (c.box.empty || (w <= tw && h <= th)) continue;
            Diagnostic d =
                make_diagnostic(Severity::Warning, DiagCode::W611_CutLargerThanTable, c.first_line, 0,
                                Msg::PlanLargerThanTable, {mm_text(w), mm_text(h), mm_text(tw), mm_text(th)});
            d.contour_first = c.first_line;
            d.contour_last = c.last_line;
            emit(std::move(d));
        }
    }

    // --- W601: a contour left open by a small gap ---
    void gaps() {
        for (const Cut& c : cuts_) {
            if (c.closed || c.end_piece == c.first_piece ||
                !(c.gap_mm > st_.closure_mm && c.gap_mm <= st_.gap_limit_mm))
                continue;
            const Point e = last_piece(c).end;
            Diagnostic d = about(DiagCode::W601_ContourGap, c, {(e.x + c.gap_from.x) / 2, (e.y + c.gap_from.y) / 2},
                                 Msg::PlanGap, {mm_text(c.gap_mm), c.gap_line, mm_text(st_.closure_mm)});
            d.line = last_piece(c).line;
            d.add_related({c.gap_line, c.gap_line, Msg::RelatedContourStart, {}});
            emit(std::move(d));
        }
    }

    // --- W607: the same path twice ---
    // Two cuts are the same path when their pieces end at the same points and their arcs turn about the same centres
    // (whatever the start and the direction): their sorted points, to kPlanSamePathToleranceMm, are equal. Cuts are
    // sorted by their box and a hash of those points, and each is compared with the first of its run only, so that
    // many cuts in one place cost a sort, not all pairs.
    using Signature = std::vector<std::pair<long long, long long>>;
    Signature signature(const Cut& c) const {
        const auto q = [](double v) { return quantized(v, kPlanSamePathToleranceMm); };
        const std::uint32_t first = c.closed ? c.loop_begin : c.first_piece, end = c.closed ? c.loop_end : c.end_piece;
        Signature sig;
        sig.reserve(2 * (end - first) + 1);
        if (!c.closed) sig.push_back({q(pieces_[first].start.x), q(pieces_[first].start.y)});
        for (std::uint32_t k = first; k < end; ++k) {
            const Piece& p = pieces_[k];
            sig.push_back({q(k + 1 == end && c.closed ? c.loop_start.x : p.end.x),
                           q(k + 1 == end && c.closed ? c.loop_start.y : p.end.y)});
            if (p.arc)
                sig.push_back({q(p.centre.x) ^ 0x5bd1e995LL, q(p.centre.y)});  // (a centre is not a point passed)
        }
        std::sort(sig.begin(), sig.end());
        return sig;
    }
    static std::uint64_t hash_of(std::span<const std::pair<long long, long long>> values) {
        std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the values
        for (const auto& [x, y] : values)
            for (const long long v : {x, y}) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
        return h;
    }
    void same_paths() {
        const auto q = [](double v) { return quantized(v, 4 * kPlanSamePathToleranceMm); };
        // Keyed by a hash of the head and the quantized box: a run of equal keys holds every cut with that box
        // (and, rarely, another whose key is the same by chance: the signatures tell them apart).
        std::vector<std::pair<std::uint64_t, int>> keyed;
        keyed.reserve(cuts_.size());
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            const Box& b = cuts_[i].box;
            if (b.empty) continue;
            const std::array<std::pair<long long, long long>, 3> key{
                {{cuts_[i].head, q(b.min_x)}, {q(b.min_y), q(b.max_x)}, {q(b.max_y), 0}}};
            keyed.push_back({hash_of(key), static_cast<int>(i)});
        }
        std::sort(keyed.begin(), keyed.end());
        // Only cuts that share their box (rare) are signed and compared: a run of the sorted boxes at a time.
        std::vector<std::pair<std::uint64_t, int>> run;
        std::vector<Signature> sigs;
        for (std::size_t k = 0, end = 0; k < keyed.size(); k = end) {
            for (end = k + 1; end < keyed.size() && keyed[end].first == keyed[k].first;) ++end;
            if (end - k < 2) continue;
            run.clear();
            sigs.assign(end - k, {});
            for (std::size_t m = k; m < end; ++m) {
                sigs[m - k] = signature(cuts_[static_cast<std::size_t>(keyed[m].second)]);
                run.push_back({hash_of(sigs[m - k]), static_cast<int>(m - k)});
            }
            std::sort(run.begin(), run.end());  // (equal hashes together, in cutting order)
            for (std::size_t r = 1, first = 0; r < run.size(); ++r) {
                if (run[r].first != run[first].first) {
                    first = r;
                    continue;
                }
                const std::size_t a =
                    static_cast<std::size_t>(keyed[k + static_cast<std::size_t>(run[first].second)].second);
                const std::size_t b =
                    static_cast<std::size_t>(keyed[k + static_cast<std::size_t>(run[r].second)].second);
                if (cuts_[a].closed == cuts_[b].closed && cuts_[a].head == cuts_[b].head &&
                    sigs[static_cast<std::size_t>(run[first].second)] == sigs[static_cast<std::size_t>(run[r].second)])
                    report_same_path(std::min(a, b), std::max(a, b));
            }
        }
    }
    void report_same_path(std::size_t first, std::size_t later) {
        if (nodes_[later].duplicate) return;
        nodes_[later].duplicate = true;
        const Cut& a = cuts_[first];
        const Cut& c = cuts_[later];
        Diagnostic d =
            about(DiagCode::W607_SamePathTwice, c, first_piece(c).end, Msg::PlanSamePath, {a.first_line, a.last_line});
        d.add_related(related(a, Msg::RelatedFirstCut));
        emit(std::move(d));
    }

    // Each cut's neighbours: the loops whose boxes meet its whole box (grown by the widest kerf), in cutting order,
    // found once and used by the nesting, the collisions and the crossings. A sweep along x over the cuts' boxes
    // finds them on an ordinary plate (a cut is compared with the few whose x ranges meet its own); a crowded plate
    // (many cuts over the same x, where the sweep would compare nearly all pairs) uses the uniform grid instead.
    // (Out of line: inlined into run(), its sweep's hot loop comes out slower.)
    [[gnu::noinline]] void find_neighbours() {
        boxes_.assign(cuts_.size(), Box{});
        for (std::size_t i = 0; i < cuts_.size(); ++i)
            if (usable(i)) boxes_[i] = cuts_[i].loop_box;
        const double margin = max_width_ + kPlanTouchToleranceMm;
        pairs_.clear();
        if (!sweep_pairs(margin)) grid_pairs(margin);
        std::sort(pairs_.begin(), pairs_.end());
        first_neighbour_.assign(cuts_.size() + 1, 0);
        neighbours_.resize(pairs_.size());
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            ++first_neighbour_[static_cast<std::size_t>(pairs_[k].first) + 1];
            neighbours_[k] = pairs_[k].second;
        }
        for (std::size_t i = 1; i < first_neighbour_.size(); ++i) first_neighbour_[i] += first_neighbour_[i - 1];
    }
    // Whether loop j is a neighbour of cut i (the test of both ways of finding them).
    bool meets(std::size_t i, std::size_t j, double margin) const {
        return i != j && cuts_[j].head == cuts_[i].head && boxes_meet(cuts_[i].box, boxes_[j], margin);
    }
    // The pairs (cut, neighbour) by a sweep along x; false (and no pairs) when the plate is too crowded for it.
    bool sweep_pairs(double margin) {
        order_.clear();
        for (std::size_t i = 0; i < cuts_.size(); ++i)
            if (!cuts_[i].box.empty && !std::isnan(cuts_[i].box.min_x)) order_.push_back(static_cast<int>(i));
        std::sort(order_.begin(), order_.end(), [&](int a, int b) {
            return cuts_[static_cast<std::size_t>(a)].box.min_x < cuts_[static_cast<std::size_t>(b)].box.min_x;
        });
        // (a loop lies in its cut's box: two cuts are neighbours only when their boxes' x ranges come this close)
        const std::size_t budget = kSweepComparisonsPerCut * (order_.size() + 1);
        std::size_t compared = 0;
        for (std::size_t a = 0; a < order_.size(); ++a) {
            const auto i = static_cast<std::size_t>(order_[a]);
            const double reach = cuts_[i].box.max_x + margin;
            for (std::size_t b = a + 1; b < order_.size(); ++b) {
                const auto k = static_cast<std::size_t>(order_[b]);
                if (!(cuts_[k].box.min_x <= reach)) break;
                if (++compared > budget) {
                    pairs_.clear();
                    return false;
                }
                const Box& bi = cuts_[i].box;
                const Box& bk = cuts_[k].box;
                if (bk.min_y > bi.max_y + margin || bi.min_y > bk.max_y + margin) continue;  // (apart in y: both ways)
                if (meets(i, k, margin) || meets(k, i, margin)) {
                    if (!charge(i, k)) {
                        pairs_.clear();
                        return false;
                    }
                    if (meets(i, k, margin)) pairs_.push_back({static_cast<int>(i), static_cast<int>(k)});
                    if (meets(k, i, margin)) pairs_.push_back({static_cast<int>(k), static_cast<int>(i)});
                }
            }
        }
        return true;
    }
    // The pair (i, j) found: its weight taken from what is left; false when there is not enough left.
    bool charge(std::size_t i, std::size_t j) {
        const std::size_t weight = cuts_[i].points + cuts_[j].points;
        if (weight > pair_points_left_) return false;
        pair_points_left_ -= weight;
        return true;
    }
    // The pairs through the grid over the loops' boxes (any plate), within the budget of pairs and candidates
    // (N613 past it: the cuts from there on get no more neighbours).
    void grid_pairs(double margin) {
        thread_local BoxGrid grid;  // (its arrays kept from plate to plate)
        grid.build(boxes_);
        pair_points_left_ = pair_points_budget_;
        const std::size_t max_pairs = kPairsPerCut * cuts_.size() + kPairsBase;
        const std::size_t max_visits = kVisitsPerCut * cuts_.size() + kVisitsBase;
        std::size_t visits = 0;
        for (std::size_t i = 0; i < cuts_.size() && !crowded_; ++i) {
            const Box& b = cuts_[i].box;
            if (b.empty) continue;
            grid.query({b.min_x - margin, b.min_y - margin, b.max_x + margin, b.max_y + margin, false}, [&](int j) {
                if (meets(i, static_cast<std::size_t>(j), margin)) {
                    if (!charge(i, static_cast<std::size_t>(j))) crowded_ = true;
                    else pairs_.push_back({static_cast<int>(i), j});
                }
                crowded_ = crowded_ || pairs_.size() >= max_pairs || ++visits >= max_visits;
                return !crowded_;
            });
        }
        if (crowded_) {
            const Cut& first = cuts_.front();
            emit(make_diagnostic(Severity::Note, DiagCode::N613_PlateTooCrowded, first.first_line, 0,
                                 Msg::PlanPlateCrowded,
                                 {first.first_line, cuts_.back().last_line, pairs_.size(), kPairsPerCut}));
        }
    }
    std::span<const int> neighbours(std::size_t i) const {
        return {neighbours_.data() + first_neighbour_[i], neighbours_.data() + first_neighbour_[i + 1]};
    }

    // --- roles by nesting ---
    void nest() {
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            if (!usable(i)) continue;
            const Cut& a = cuts_[i];
            double best = std::numeric_limits<double>::infinity();
            for (int j : neighbours(i)) {
                const Cut& b = cuts_[static_cast<std::size_t>(j)];
                if (!b.loop_box.contains(a.loop_box)) continue;
                const double area = std::fabs(b.area_mm2);
                if (area <= std::fabs(a.area_mm2) || area >= best || !inside_loop(b, pieces_, a.loop_start)) continue;
                best = area;
                nodes_[i].parent = j;
            }
        }
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            if (!usable(i)) continue;
            int depth = 0;
            for (int p = nodes_[i].parent; p >= 0; p = nodes_[static_cast<std::size_t>(p)].parent) ++depth;
            nodes_[i].depth = depth;
            if (nodes_[i].parent >= 0) ++nodes_[static_cast<std::size_t>(nodes_[i].parent)].children;
        }
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            if (!usable(i)) continue;
            Node& n = nodes_[i];
            if (n.depth % 2 == 1) n.role = ContourRole::Hole;
            else if (n.depth > 0 || n.children > 0) n.role = ContourRole::Part;
            else if (cuts_[i].kerf == KerfSide::Off) n.role = ContourRole::Lone;
            else n.role = kerf_inside(cuts_[i]) ? ContourRole::LoneHole : ContourRole::LonePart;
        }
    }
    static bool kerf_inside(const Cut& c) { return (c.area_mm2 > 0) == (c.kerf == KerfSide::Left); }
    bool ancestor(int a, int d) const {
        for (int p = nodes_[static_cast<std::size_t>(d)].parent; p >= 0; p = nodes_[static_cast<std::size_t>(p)].parent)
            if (p == a) return true;
        return false;
    }

    // --- E602 / N603: the kerf side ---
    void kerf_sides() {
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            const Cut& c = cuts_[i];
            if (!usable(i) || c.kerf == KerfSide::Off) continue;
            const bool inside = kerf_inside(c);
            const ContourRole role = nodes_[i].role;
            const bool ccw = c.area_mm2 > 0;
            const Msg side = c.kerf == KerfSide::Left ? Msg::PlanSideLeft : Msg::PlanSideRight;
            const Msg other = c.kerf == KerfSide::Left ? Msg::PlanSideRight : Msg::PlanSideLeft;
            const Msg travel = ccw ? Msg::PlanCounterClockwise : Msg::PlanClockwise;
            Msg msg = Msg::None;
            DiagCode code = DiagCode::E602_KerfIntoPart;
            if (role == ContourRole::Part && inside) msg = Msg::PlanKerfInsidePart;
            else if (role == ContourRole::Hole && !inside) msg = Msg::PlanKerfOutsideHole;
            else if (role == ContourRole::LoneHole) {
                msg = Msg::PlanKerfInsideLone;
                code = DiagCode::N603_KerfInsideLoneContour;
            }
            if (msg == Msg::None) continue;
            const std::uint32_t line = pieces_[c.loop_begin].line;
            if (!cap_.admit(code, line, default_severity(code))) continue;  // (on every part of a tape: counted only)
            Diagnostic d = about(code, c, c.loop_start, msg, {side, travel, other});
            d.line = line;
            out_.push_back(std::move(d));
        }
    }

    // --- W604: a contour cut before one inside it ---
    void order() {
        std::map<int, std::vector<int>> late;  // parent -> its children cut after it, in cutting order
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            const int p = nodes_[i].parent;
            if (usable(i) && p >= 0 && cuts_[static_cast<std::size_t>(p)].order < cuts_[i].order)
                late[p].push_back(static_cast<int>(i));
        }
        for (const auto& [p, children] : late) {
            const Cut& parent = cuts_[static_cast<std::size_t>(p)];
            const Cut& first = cuts_[static_cast<std::size_t>(children.front())];
            const bool part = nodes_[static_cast<std::size_t>(p)].role != ContourRole::Hole;
            Diagnostic d = about(DiagCode::W604_CutBeforeInside, parent, parent.loop_start,
                                 part ? Msg::PlanPartBeforeHoles : Msg::PlanHoleBeforeParts,
                                 {children.size(), first.first_line, first.last_line});
            for (int ch : children)
                d.add_related(
                    related(cuts_[static_cast<std::size_t>(ch)], part ? Msg::RelatedHoleAfter : Msg::RelatedPartAfter));
            emit(std::move(d));
        }
    }

    // --- E605 / N612 / E606: collisions and cuts across parts cut free ---
    static double width_between(const Cut& a, const Cut& b) {
        return std::max({a.kerf_width_mm, b.kerf_width_mm, kPlanTouchToleranceMm});
    }
    // The nearest approach of two closed polygons, stopping at the first below `limit`; `where` on `a`.
    // The nearest approach of a path `a` to the closed polygon `b` among the segment pairs closer than `limit`,
    // stopping at the first crossing; `where` on `a`; infinity when no pair is that close. b's segments near a are
    // put in a grid of their own, so that two long contours (arcs of thousands of chords) cost about their length.
    static double approach(const std::vector<Point>& a, bool a_closed, const std::vector<Point>& b, const Box& b_box,
                           double limit, Point& where) {
        Box a_box;
        for (Point p : a) a_box.add(p);
        std::vector<Box> near;
        std::vector<std::uint32_t> index;
        for (std::size_t k = 0; k < b.size(); ++k) {
            Box seg = Box::of(b[k], b[(k + 1) % b.size()]);
            if (!boxes_meet(seg, a_box, limit)) continue;
            seg.min_x -= limit;
            seg.min_y -= limit;
            seg.max_x += limit;
            seg.max_y += limit;
            near.push_back(seg);
            index.push_back(static_cast<std::uint32_t>(k));
        }
        double best = std::numeric_limits<double>::infinity();
        if (near.empty()) return best;
        BoxGrid grid;
        grid.build(near);
        const std::size_t na = a.size();
        for (std::size_t i = 0; i + (a_closed ? 0 : 1) < na && best > 0; ++i) {
            const Point p = a[i], q = a[(i + 1) % na];
            const Box s = Box::of(p, q);
            if (!boxes_meet(s, b_box, limit)) continue;
            grid.query(s, [&](int j) {
                if (best == 0 || !boxes_meet(s, near[static_cast<std::size_t>(j)], 0)) return;
                const std::size_t k = index[static_cast<std::size_t>(j)];
                Point w;
                const double d = segment_distance(p, q, b[k], b[(k + 1) % b.size()], w);
                if (d < best) {
                    best = d;
                    where = w;
                }
            });
        }
        return best;
    }
    void collisions() {
        std::set<std::pair<int, int>> reported;
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            if (!usable(i) || !collides(nodes_[i].role)) continue;
            const Cut& a = cuts_[i];
            for (int j : neighbours(i)) {
                if (static_cast<std::size_t>(j) <= i ||
                    !collides_as_pair(nodes_[i].role, nodes_[static_cast<std::size_t>(j)].role))
                    continue;
                if (ancestor(j, static_cast<int>(i)) || ancestor(static_cast<int>(i), j)) continue;
                const Cut& b = cuts_[static_cast<std::size_t>(j)];
                const double limit = width_between(a, b);
                if (!boxes_meet(a.loop_box, b.loop_box, limit)) continue;
                Point where;
                const double d =
                    approach(polygon(static_cast<std::size_t>(j)), true, polygon(i), a.loop_box, limit, where);
                if (!(d < limit)) continue;
                reported.insert({static_cast<int>(i), j});
                report_collision(i, static_cast<std::size_t>(j), d, limit, where);
            }
        }
        crossings(reported);
    }
    void report_collision(std::size_t i, std::size_t j, double d, double width, Point where) {
        const Cut& a = cuts_[i];
        const Cut& b = cuts_[j];
        const ContourRole ra = nodes_[i].role, rb = nodes_[j].role;
        const bool lone = ra == ContourRole::Lone || rb == ContourRole::Lone;
        if (lone && d > kPlanTouchToleranceMm) return;  // (without compensation only a real overlap counts)
        // (counted before it is made: N parts in one place make N² / 2 collisions, each with its overlap polygons)
        const DiagCode code = lone ? DiagCode::N612_ContoursOverlap : DiagCode::E605_PartsCollide;
        if (!cap_.admit(code, b.first_line, default_severity(code))) return;
        Diagnostic diag;
        if (lone) {
            diag =
                about(DiagCode::N612_ContoursOverlap, b, where, Msg::PlanContoursOverlap, {a.first_line, a.last_line});
            diag.add_related(related(a, Msg::RelatedOtherContour));
        } else if (ra == ContourRole::LoneHole || rb == ContourRole::LoneHole) {
            const bool b_is_hole = rb == ContourRole::LoneHole;
            diag = about(DiagCode::E605_PartsCollide, b, where,
                         b_is_hole ? Msg::PlanPlateHoleOverlapsPart : Msg::PlanPartOverlapsPlateHole,
                         {a.first_line, a.last_line, mm_text(width)});
            diag.add_related(related(a, b_is_hole ? Msg::RelatedOtherPart : Msg::RelatedPlateHole));
        } else if (width <= kPlanTouchToleranceMm) {  // (no compensation on either: no kerf width to name)
            diag = about(DiagCode::E605_PartsCollide, b, where, Msg::PlanPartsTouch, {a.first_line, a.last_line});
            diag.add_related(related(a, Msg::RelatedOtherPart));
        } else if (d == 0) {
            diag = about(DiagCode::E605_PartsCollide, b, where, Msg::PlanPartsOverlap,
                         {a.first_line, a.last_line, mm_text(width)});
            diag.add_related(related(a, Msg::RelatedOtherPart));
        } else {
            diag = about(DiagCode::E605_PartsCollide, b, where, Msg::PlanPartsTooClose,
                         {mm_text(d), a.first_line, a.last_line, mm_text(width)});
            diag.add_related(related(a, Msg::RelatedOtherPart));
        }
        if (d == 0) diag.set_overlap({outline(polygon(i)), outline(polygon(j))});
        out_.push_back(std::move(diag));
    }
    // A polygon of a collision's overlap: itself, or kPlanMaxOverlapPoints of its points evenly spread (a report's
    // size stays bounded: max_per_code collisions of two outlines each).
    static std::vector<Point> outline(const std::vector<Point>& polygon) {
        const std::size_t n = polygon.size();
        if (n <= kPlanMaxOverlapPoints) return polygon;
        std::vector<Point> thinned(kPlanMaxOverlapPoints);
        for (std::size_t k = 0; k < kPlanMaxOverlapPoints; ++k) thinned[k] = polygon[k * n / kPlanMaxOverlapPoints];
        return thinned;
    }
    // E606: a cut (its whole path) crossing a part cut free before it.
    void crossings(const std::set<std::pair<int, int>>& reported) {
        std::vector<std::vector<Point>> paths;
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            if (cuts_[i].end_piece == cuts_[i].first_piece || nodes_[i].duplicate) continue;
            const auto ranges = crossing_ranges(i);
            const Cut& c = cuts_[i];
            Box reach;
            if (ranges[1].second == 0) {
                reach = c.box;  // (the whole path)
            } else {
                for (const auto& [first, end] : ranges)
                    for (std::uint32_t k = first; k < end; ++k) reach.add(piece_box(pieces_[k]));
            }
            if (reach.empty) continue;
            paths.clear();
            bool done = false;
            for (int j : neighbours(i)) {
                const Cut& p = cuts_[static_cast<std::size_t>(j)];
                if (done || p.order >= cuts_[i].order || !is_part(nodes_[static_cast<std::size_t>(j)].role) ||
                    !boxes_meet(reach, p.loop_box, kPlanTouchToleranceMm))
                    continue;
                if (reported.count({std::min<int>(j, static_cast<int>(i)), std::max<int>(j, static_cast<int>(i))}))
                    continue;
                if (paths.empty())
                    for (const auto& [first, end] : ranges) paths.push_back(pieces_points(pieces_, first, end));
                for (const std::vector<Point>& path : paths) {
                    Point where;
                    if (path.size() < 2 || approach(path, false, polygon(static_cast<std::size_t>(j)), p.loop_box,
                                                    kPlanTouchToleranceMm, where) > 0)
                        continue;
                    Diagnostic d = about(DiagCode::E606_CutCrossesCutPart, cuts_[i], where, Msg::PlanCutCrossesPart,
                                         {p.first_line, p.last_line});
                    d.add_related(related(p, Msg::RelatedPartCutFree));
                    emit(std::move(d));
                    done = true;
                    break;
                }
            }
        }
    }
    // The pieces of cut i that may cross a part cut free: the whole path of an open cut or a hole; the lead-in and
    // lead-out of a contour that counts as a part (its loop is a collision's business).
    std::array<std::pair<std::uint32_t, std::uint32_t>, 2> crossing_ranges(std::size_t i) const {
        const Cut& c = cuts_[i];
        if (c.closed && collides(nodes_[i].role)) return {{{c.first_piece, c.loop_begin}, {c.loop_end, c.end_piece}}};
        return {{{c.first_piece, c.end_piece}, {0, 0}}};
    }

    // --- W610: a contour pierced on its own line ---
    void lead_ins() {
        if (!st_.lead_in_required) return;
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            const Cut& c = cuts_[i];
            if (!usable(i) || c.loop_begin > c.first_piece || !pierced_on_loop(i)) continue;
            emit(about(DiagCode::W610_PierceWithoutLeadIn, c, first_piece(c).start, Msg::PlanNoLeadIn, {}));
        }
    }

    // Whether cut i's pierce lies on its loop: where the loop starts, or on the loop's way back to its start (an
    // overcut that runs past the pierce before it closes).
    bool pierced_on_loop(std::size_t i) {
        const Cut& c = cuts_[i];
        const Point pierce = first_piece(c).start;
        if (c.loop_start == pierce) return true;
        const std::vector<Point>& loop = polygon(i);
        for (std::size_t k = 0; k < loop.size(); ++k) {
            Point where;
            if (segment_distance(loop[k], loop[(k + 1) % loop.size()], pierce, pierce, where) <= st_.closure_mm)
                return true;
        }
        return false;
    }

    void emit(Diagnostic d) {
        if (cap_.admit(d)) out_.push_back(std::move(d));
    }

    std::vector<Cut>& cuts_;
    std::span<const Piece> pieces_;
    const PlateSettings& st_;
    std::vector<Diagnostic>& out_;
    DiagnosticCap& cap_;  // max_per_code within the plate: the rest are counted, not made
    std::vector<Node> nodes_;
    std::vector<Box> boxes_;                    // the loops' boxes (empty: no loop), the grid's
    std::vector<std::vector<Point>> polygons_;  // the loops flattened, as made
    std::vector<std::uint32_t> first_neighbour_;
    std::vector<int> neighbours_;             // each cut's, ascending, from first_neighbour_[i]
    std::vector<std::pair<int, int>> pairs_;  // (cut, neighbour) as found
    std::vector<int> order_;                  // the cuts by their boxes' min_x (the sweep)
    bool crowded_ = false;                    // the search for neighbours stopped at its budget (N613)
    std::size_t pair_points_budget_ = 0;      // what the pairs found may weigh (kPairPointsPerPoint)
    std::size_t pair_points_left_ = 0;
    double max_width_ = 0;  // the widest kerf of the plate's cuts
};

}  // namespace

void analyse_plate(std::vector<Cut>& cuts, std::span<const Piece> pieces, const PlateSettings& settings,
                   std::vector<Diagnostic>& out, DiagnosticCap& cap, std::vector<PlanContour>* contours) {
    Plate plate(cuts, pieces, settings, out, cap);
    plate.run();
    if (contours) plate.record(*contours);
}

}  // namespace essi::plan
