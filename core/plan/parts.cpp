// The parts list (essi/parts.hpp): the plan's contours made parts, plate by plate; their shapes grouped; each
// plate's utilisation and remnant.
#include "essi/parts.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "essi/interp.hpp"
#include "essi/read.hpp"
#include "part_shape.hpp"
#include "remnant.hpp"

namespace essi {
namespace {

bool is_part(ContourRole r) { return r == ContourRole::Part || r == ContourRole::LonePart; }

constexpr double kMm3PerM3 = 1e9;

// The loop of a contour: its motions [loop_begin, loop_end), the first from loop_start, the last to where the loop
// closes (a parabola's chord may close it inside the motion).
void loop_motions(const PlanContour& c, std::span<const MotionRecord> all, double closure_mm,
                  std::vector<MotionRecord>& loop) {
    loop.assign(all.begin() + c.loop_begin, all.begin() + c.loop_end);
    if (loop.empty()) return;
    const auto near = [&](Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y) <= closure_mm; };
    if (!(loop.front().start == c.loop_start)) {
        const double f = nearest_fraction(loop.front(), c.loop_start);
        if (f > 0 && f < 1) loop.front() = sub_motion(loop.front(), f, 1);
        loop.front().start = c.loop_start;
    }
    if (!near(loop.back().end, c.loop_start) && loop.back().curve != CurveKind::Line) {
        const double f = nearest_fraction(loop.back(), c.loop_start);
        if (f > 0 && f < 1) loop.back() = sub_motion(loop.back(), 0, f);
    }
}

double contour_length(std::span<const MotionRecord> motions) {
    double length = 0;
    for (const MotionRecord& m : motions) length += m.length_mm;
    return length;
}

// The groups and the shapes they are compared by.
class Grouper {
public:
    explicit Grouper(double tolerance) : tolerance_(tolerance) {}

    struct Found {
        std::size_t group;  // index in the groups
        double turned = 0;  // radians, counter-clockwise, from the group's first part
        bool is_new = false;
        std::optional<std::size_t> mirror_of;
    };
    // The group of a part of this shape (a new one when no kept shape is the same; keep() it then).
    Found place(const parts::Shape& shape) {
        bool any_similar = false;
        if (const auto found = find(shape, any_similar)) return {found->first, -found->second, false, std::nullopt};
        Found out{groups_++, 0, true, std::nullopt};
        // (a mirror image has the same signature: only a shape with similar ones kept can have its twin among them)
        if (any_similar)
            if (const auto twin = find(parts::mirrored(shape), any_similar)) out.mirror_of = twin->first;
        return out;
    }
    // The shape of a new group kept to compare later parts with, while the kept shapes' pieces allow it.
    void keep(parts::Shape&& shape, const Found& found) {
        if (!found.is_new || kept_pieces_ + shape.pieces > kPartsMaxKeptPieces) return;
        kept_pieces_ += shape.pieces;
        buckets_[key_of(shape, 0)].emplace(shape.area, Entry{longest(shape), static_cast<std::uint32_t>(kept_.size())});
        kept_.push_back({std::move(shape), found.group});
    }

private:
    struct Kept {
        parts::Shape shape;
        std::size_t group;
    };
    // A kept shape in its bucket: its longest piece (two similar shapes' longest pieces are as long within twice
    // the tolerance: most are told apart without reading the shape) and where it is in kept_.
    struct Entry {
        double longest;
        std::uint32_t kept;
    };
    using Bucket = std::multimap<double, Entry>;  // by net area
    static double longest(const parts::Shape& shape) { return shape.lengths.empty() ? 0 : shape.lengths.back(); }
    // Shapes of one number of loops and of pieces, their perimeters in one cell of the width within which similar()
    // takes two perimeters as the same: a shape's similar ones are in its cell or a neighbour.
    using Key = std::tuple<std::size_t, std::size_t, long long>;
    [[nodiscard]] Key key_of(const parts::Shape& shape, int neighbour) const {
        const double cell = 2 * tolerance_ * static_cast<double>(std::max<std::size_t>(shape.pieces, 1));
        const double c = std::floor(shape.perimeter / cell);
        const long long index = std::isfinite(c) && std::fabs(c) < 1e15 ? static_cast<long long>(c) : 0;
        return {shape.loops.size(), shape.pieces, index + neighbour};
    }

    // The first kept shape that `shape` turns onto (its group and the turn), in the order of their areas, among the
    // first kPartsMaxCompares of similar signature and the first kPartsMaxVisits of about its area and perimeter;
    // `any_similar`: whether one was similar.
    std::optional<std::pair<std::size_t, double>> find(const parts::Shape& shape, bool& any_similar) const {
        const double slack = 2 * tolerance_ * shape.perimeter + 4 * tolerance_ * tolerance_;
        // the three cells' shapes within the slack, merged by area
        std::array<Bucket::const_iterator, 3> at, end;
        std::size_t cells = 0;
        for (int n = -1; n <= 1; ++n) {
            const auto b = buckets_.find(key_of(shape, n));
            if (b == buckets_.end()) continue;
            at[cells] = b->second.lower_bound(shape.area - slack);
            end[cells++] = b->second.end();
        }
        const double its_longest = longest(shape);
        std::size_t compared = 0, visited = 0;
        while (compared < kPartsMaxCompares && visited < kPartsMaxVisits) {
            std::size_t next = cells;
            for (std::size_t c = 0; c < cells; ++c)
                if (at[c] != end[c] && at[c]->first <= shape.area + slack &&
                    (next == cells || at[c]->first < at[next]->first))
                    next = c;
            if (next == cells) break;
            const Entry entry = (at[next]++)->second;
            ++visited;
            if (std::fabs(entry.longest - its_longest) > 2 * tolerance_) continue;  // (not similar)
            const Kept& kept = kept_[entry.kept];
            if (!parts::similar(shape, kept.shape, tolerance_)) continue;
            any_similar = true;
            ++compared;
            if (const auto turn = parts::turn_onto(shape, kept.shape, tolerance_)) return std::pair{kept.group, *turn};
        }
        return std::nullopt;
    }

    double tolerance_;
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            // (FNV-1a over the three, 64 bits on every platform)
            const auto mix = [](std::uint64_t h, std::uint64_t v) { return (h ^ v) * 0x100000001b3ULL; };
            return static_cast<std::size_t>(mix(mix(mix(0xcbf29ce484222325ULL, std::get<0>(k)), std::get<1>(k)),
                                                static_cast<std::uint64_t>(std::get<2>(k))));
        }
    };
    std::unordered_map<Key, Bucket, KeyHash> buckets_;  // (a hash: a part looks up three of them)
    std::vector<Kept> kept_;
    std::size_t groups_ = 0;
    std::size_t kept_pieces_ = 0;
};

}  // namespace

// The parts list made a plate at a time.
class PartsBuilder {
public:
    explicit PartsBuilder(const Profile& profile)
        : profile_(profile), tolerance_(std::max(kPartsSameShapeMm, kPartsSameShapeUnits * profile.unit_mm)),
          closure_mm_(profile.arc_tolerance_units * profile.unit_mm), grouper_(tolerance_) {}

    // One plate's contours (a parent: `parent_base` + its index in `all`); motions_of(k): contour k's motions
    // (std::span<const MotionRecord>).
    template <class MotionsOf>
    void add_plate(std::span<const PlanContour> all, int parent_base, MotionsOf&& motions_of) {
        if (all.empty()) return;
        std::map<int, std::vector<std::size_t>> holes;  // by the part they lie in
        for (std::size_t k = 0; k < all.size(); ++k) {
            const int parent = all[k].parent - parent_base;
            if (all[k].role == ContourRole::Hole && all[k].parent >= 0 && is_part(all[parent].role))
                holes[parent].push_back(k);
        }
        PlateUse plate;
        plate.plate = all[0].plate;
        std::vector<std::vector<Point>> outlines;
        double kerf_mm = 0;
        for (std::size_t k = 0; k < all.size(); ++k) {
            if (!is_part(all[k].role)) continue;
            std::vector<std::size_t> cuts{k};
            const auto h = holes.find(static_cast<int>(k));
            if (h != holes.end()) cuts.insert(cuts.end(), h->second.begin(), h->second.end());
            add_part(all, cuts, motions_of, plate, kerf_mm);
            outlines.push_back(polygons_[0]);
        }
        if (plate.parts == 0) return;
        finish_plate(plate, outlines, kerf_mm);
        list_.plates.push_back(plate);
    }

    PartsList finish() {
        for (PartGroup& g : list_.groups) g.cut_length_mm /= g.count;
        return std::move(list_);
    }

private:
    template <class MotionsOf>
    void add_part(std::span<const PlanContour> all, const std::vector<std::size_t>& cuts, MotionsOf& motions_of,
                  PlateUse& plate, double& kerf_mm) {
        Part part;
        part.plate = all[cuts[0]].plate;
        std::vector<parts::Loop> loops;
        for (const std::size_t k : cuts) {
            const PlanContour& c = all[k];
            const std::span<const MotionRecord> motions = motions_of(k);
            for (const MotionRecord& m : motions) kerf_mm = std::max(kerf_mm, m.kerf_mm);
            part.cuts.push_back({c.first_line, c.last_line});
            part.cut_length_mm += contour_length(motions);
            loop_motions(c, motions, closure_mm_, loop_);
            loops.push_back(parts::make_loop(loop_, tolerance_));
        }
        for (const parts::Seg& s : loops[0].segs) part.box.add(parts::seg_box(s));
        polygons_.resize(loops.size());
        for (std::size_t k = 0; k < loops.size(); ++k) {
            polygons_[k].clear();
            parts::flatten_loop(loops[k], kPlanChordToleranceMm, kPlanMaxArcChords, polygons_[k]);
        }
        parts::Shape shape = parts::make_shape(std::move(loops));
        part.label_at = parts::label_point(shape, part.box, std::span(polygons_.data(), shape.loops.size()));
        const Grouper::Found found = grouper_.place(shape);
        if (found.is_new) new_group(shape, found);
        grouper_.keep(std::move(shape), found);
        PartGroup& g = list_.groups[found.group];
        part.group = g.number;
        part.turned_deg = degrees(found.turned);
        ++g.count;
        g.cut_length_mm += part.cut_length_mm;
        g.parts.push_back(static_cast<std::uint32_t>(list_.parts.size()));
        ++plate.parts;
        plate.net_area_mm2 += g.net_area_mm2;
        plate.area.add(part.box);
        list_.parts.push_back(std::move(part));
    }

    void new_group(const parts::Shape& shape, const Grouper::Found& found) {
        PartGroup g;
        g.number = static_cast<unsigned>(list_.groups.size() + 1);
        g.net_area_mm2 = shape.area;
        const parts::OutlineRect rect = parts::smallest_rectangle(shape.loops[0]);
        g.length_mm = rect.length;
        g.width_mm = rect.width;
        g.holes = static_cast<unsigned>(shape.loops.size() - 1);
        g.pierces = g.holes + 1;
        if (profile_.material)
            g.mass_kg = shape.area * profile_.material->thickness_mm * profile_.material->density_kg_m3 / kMm3PerM3;
        if (found.mirror_of) {
            g.mirror_of = list_.groups[*found.mirror_of].number;
            if (list_.groups[*found.mirror_of].mirror_of == 0) list_.groups[*found.mirror_of].mirror_of = g.number;
        }
        list_.groups.push_back(std::move(g));
    }

    // The plate's area (plate_mm from the program's origin, or from the parts' lowest corner when they do not lie
    // in that; else the parts' box), utilisation, scrap and remnant.
    void finish_plate(PlateUse& plate, const std::vector<std::vector<Point>>& outlines, double kerf_mm) const {
        const Box parts_box = plate.area;
        if (profile_.plate) {
            plate.from_profile = true;
            const double x = profile_.plate->x_mm, y = profile_.plate->y_mm;
            plate.area = Box{0, 0, x, y, false};
            if (!plate.area.contains(parts_box))
                plate.area = Box{parts_box.min_x, parts_box.min_y, parts_box.min_x + x, parts_box.min_y + y, false};
        }
        const double area = (plate.area.max_x - plate.area.min_x) * (plate.area.max_y - plate.area.min_y);
        plate.utilisation = area > 0 ? plate.net_area_mm2 / area : 0;
        if (profile_.material)
            plate.scrap_kg = std::max(0.0, area - plate.net_area_mm2) * profile_.material->thickness_mm *
                             profile_.material->density_kg_m3 / kMm3PerM3;
        // (the full kerf width from every outline: the compensation's, else the profile's width)
        const double width = kerf_mm > 0 ? 2 * kerf_mm
                             : profile_.kerf_value == KerfValueMeaning::Width
                                 ? profile_.kerf_units * profile_.unit_mm
                                 : 2 * profile_.kerf_units * profile_.unit_mm;
        plate.remnant = parts::remnant(plate.area, outlines, width);
    }

    static double degrees(double radians) {
        double d = radians * 180 / kPi;
        while (d <= -180) d += 360;
        while (d > 180) d -= 360;
        return std::fabs(d) < 1e-9 ? 0 : d;
    }

    const Profile& profile_;
    double tolerance_;
    double closure_mm_;
    Grouper grouper_;
    PartsList list_;
    std::vector<MotionRecord> loop_;            // the loop of a contour (loop_motions)
    std::vector<std::vector<Point>> polygons_;  // the part's loops flattened, the outline first
};

PartsList find_parts(const std::vector<PlanContour>& contours, const MotionStore& store, const Profile& profile) {
    PartsBuilder builder(profile);
    std::vector<MotionRecord> motions;
    for (std::size_t begin = 0, end = 0; begin < contours.size(); begin = end) {
        for (end = begin + 1; end < contours.size() && contours[end].plate == contours[begin].plate;) ++end;
        const std::span<const PlanContour> plate(contours.data() + begin, end - begin);
        builder.add_plate(plate, static_cast<int>(begin), [&](std::size_t k) {
            motions = contour_motions(plate[k], store);
            return std::span<const MotionRecord>(motions);
        });
    }
    return builder.finish();
}

PartsFinder::PartsFinder(const Profile& profile) : builder_(std::make_unique<PartsBuilder>(profile)) {}
PartsFinder::~PartsFinder() = default;

void PartsFinder::on_plate(const PlateContours& plate) {
    builder_->add_plate(plate.contours, 0, [&](std::size_t k) { return plate.of(k); });
}

PartsList PartsFinder::finish() { return builder_->finish(); }

PartsList tape_parts(std::string_view bytes, const Profile& profile, InputFormat format) {
    PartsFinder finder(profile);
    CutPlan plan(profile);
    plan.keep_plate_motions(&finder);
    replay_tape(bytes, profile, format, plan);
    (void)plan.finish();
    return finder.finish();
}

}  // namespace essi
