// Contours of a tape and the comparison of two revisions (essi/diff.hpp).
#include "essi/diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include <nlohmann/json.hpp>

#include "essi/interp.hpp"
#include "essi/read.hpp"
#include "essi/report_json.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "essi/pipeline.hpp"

namespace essi {
namespace {

// Collects the contours (essi/contour.hpp) with their box, length and shape (and their motions, `keep_paths`).
class ContourSink final : public MotionSink {
public:
    ContourSink(std::vector<DiffContour>& out, bool keep_paths) : out_(out), keep_paths_(keep_paths) {}

    // Where a contour goes when it ends.
    auto kept() {
        return [this](DiffContour& c) { out_.push_back(std::move(c)); };
    }

    void on_motion(const MotionRecord& m) override {
        DiffContour* c = builder_.motion(
            m, [&](DiffContour& began) { began.start = m.start; }, kept());
        if (!c) return;
        add(*c, m);
        if (keep_paths_) c->path.push_back(m);
    }
    void on_event(const MachineEvent& e) override { builder_.event(e.tools_after, kept()); }
    void end() { builder_.end(kept()); }

private:
    static void add(DiffContour& c, const MotionRecord& m) {
        ++c.motions;
        c.length_mm += m.length_mm;
        c.box.add(bounding_box(m));
        const auto rel = [&](Point p) {
            c.shape.push_back(p.x - c.start.x);
            c.shape.push_back(p.y - c.start.y);
        };
        c.shape.push_back(static_cast<double>(m.curve));
        rel(m.end);
        if (m.curve == CurveKind::Arc) {
            rel(m.centre);
            c.shape.push_back(m.sweep * m.radius);  // (the arc's signed length: the sweep at the radius's scale)
        } else if (m.curve == CurveKind::Parabola) {
            c.shape.push_back(m.length_mm);
        }
    }

    std::vector<DiffContour>& out_;
    bool keep_paths_;
    ContourBuilder<DiffContour> builder_;
};

bool same_shape(const DiffContour& a, const DiffContour& b) {
    if (a.kind != b.kind || a.shape.size() != b.shape.size()) return false;
    for (std::size_t i = 0; i < a.shape.size(); ++i)
        if (std::fabs(a.shape[i] - b.shape[i]) > kDiffToleranceMm) return false;
    return true;
}

double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

bool overlap(const Box& a, const Box& b) {
    return !a.empty && !b.empty && a.min_x <= b.max_x + kDiffToleranceMm && b.min_x <= a.max_x + kDiffToleranceMm &&
           a.min_y <= b.max_y + kDiffToleranceMm && b.min_y <= a.max_y + kDiffToleranceMm;
}

// B's contours by their motion count and length (to 0.01 mm): the candidates of a shape are in its bucket or the
// two beside it (a length within the tolerance may round either way).
class ShapeIndex {
public:
    explicit ShapeIndex(const std::vector<DiffContour>& b) {
        for (std::size_t j = 0; j < b.size(); ++j) buckets_[key(b[j], 0)].push_back(static_cast<int>(j));
    }
    template <class F>
    void for_each_candidate(const DiffContour& a, F&& f) const {
        for (int d : {-1, 0, 1}) {
            const auto it = buckets_.find(key(a, d));
            if (it != buckets_.end())
                for (int j : it->second) f(j);
        }
    }

private:
    static std::pair<std::size_t, long long> key(const DiffContour& c, int shift) {
        return {c.motions, std::llround(c.length_mm * 100) + shift};
    }
    std::map<std::pair<std::size_t, long long>, std::vector<int>> buckets_;
};

// The unmatched contour of B nearest to `a`'s start among those `fits` accepts, or -1 (a scan of B: for the
// contours left after the shapes are matched).
template <class Fits>
int nearest(const DiffContour& a, const std::vector<DiffContour>& b, const std::vector<bool>& taken, Fits&& fits) {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < b.size(); ++j) {
        if (taken[j] || !fits(b[j])) continue;
        const double d = distance(a.start, b[j].start);
        if (d < best_d) {
            best_d = d;
            best = static_cast<int>(j);
        }
    }
    return best;
}

}  // namespace

TapeContours tape_contours(std::string_view bytes, const TapeSetup& setup, bool keep_paths) {
    TapeContours t;
    ContourSink sink(t.contours, keep_paths);
    TapeChecker checker(bytes, setup.profile, &sink);
    TapeReader reader(bytes, setup.profile, setup.format);
    Tape chunk;
    while (reader.read_chunk(chunk, kCheckChunkBlocks)) checker.check_chunk(chunk);
    sink.end();
    t.check = checker.finish();
    record_setup(t.check, setup);
    return t;
}

const char* contour_change_name(ContourChange c) {
    switch (c) {
        case ContourChange::Same: return "same";
        case ContourChange::Moved: return "moved";
        case ContourChange::Changed: return "changed";
        case ContourChange::Removed: return "removed";
        case ContourChange::Added: return "added";
    }
    return "?";
}

std::size_t TapeDiff::count(ContourChange c) const {
    return static_cast<std::size_t>(
        std::count_if(contours.begin(), contours.end(), [&](const ContourDiff& d) { return d.change == c; }));
}

TapeDiff diff_contours(const std::vector<DiffContour>& a, const std::vector<DiffContour>& b) {
    std::vector<ContourDiff> of_a(a.size());
    std::vector<bool> taken(b.size(), false);
    const ShapeIndex index(b);
    // 1. The same shape at the same place.
    for (std::size_t i = 0; i < a.size(); ++i) {
        of_a[i] = {ContourChange::Removed, static_cast<int>(i), -1, {}};
        index.for_each_candidate(a[i], [&](int j) {
            if (of_a[i].b >= 0 || taken[static_cast<std::size_t>(j)]) return;
            const DiffContour& c = b[static_cast<std::size_t>(j)];
            if (distance(a[i].start, c.start) <= kDiffToleranceMm && same_shape(a[i], c)) {
                of_a[i] = {ContourChange::Same, static_cast<int>(i), j, {}};
                taken[static_cast<std::size_t>(j)] = true;
            }
        });
    }
    // 2. The same shape elsewhere (the nearest), or another shape over the same place (the nearest): the shape
    // elsewhere when it is no farther than the contour's own size, else the edit in place (a part edited is
    // likelier than an identical one moved across the plate).
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (of_a[i].b >= 0) continue;
        int moved = -1;
        double moved_d = std::numeric_limits<double>::infinity();
        index.for_each_candidate(a[i], [&](int k) {
            const DiffContour& c = b[static_cast<std::size_t>(k)];
            if (taken[static_cast<std::size_t>(k)] || !same_shape(a[i], c) || distance(a[i].start, c.start) >= moved_d)
                return;
            moved_d = distance(a[i].start, c.start);
            moved = k;
        });
        const double size = std::hypot(a[i].box.max_x - a[i].box.min_x, a[i].box.max_y - a[i].box.min_y);
        const bool near_move = moved >= 0 && moved_d <= size;  // (then no scan for an edit in place)
        const int changed = near_move ? -1 : nearest(a[i], b, taken, [&](const DiffContour& c) {
            return c.kind == a[i].kind && overlap(a[i].box, c.box);
        });
        const bool take_moved = near_move || (moved >= 0 && changed < 0);
        if (!take_moved && changed < 0) continue;
        const int j = take_moved ? moved : changed;
        const DiffContour& c = b[static_cast<std::size_t>(j)];
        of_a[i] = {take_moved ? ContourChange::Moved : ContourChange::Changed, static_cast<int>(i), j, {}};
        if (take_moved) of_a[i].offset = {c.start.x - a[i].start.x, c.start.y - a[i].start.y};
        taken[static_cast<std::size_t>(j)] = true;
    }
    TapeDiff d;
    d.contours = std::move(of_a);
    for (std::size_t j = 0; j < b.size(); ++j)
        if (!taken[j]) d.contours.push_back({ContourChange::Added, -1, static_cast<int>(j), {}});
    return d;
}

namespace {

constexpr ContourChange kChanges[] = {ContourChange::Same, ContourChange::Moved, ContourChange::Changed,
                                      ContourChange::Removed, ContourChange::Added};

std::string signed_mm_text(double v) { return (v >= 0 ? "+" : "") + mm_text(v); }

std::string lines_text(const DiffContour& c, Lang lang) {
    return c.first_line == c.last_line ? format_message(Msg::DiffLine, lang, {c.first_line})
                                       : format_message(Msg::DiffLines, lang, {c.first_line, c.last_line});
}

std::string contour_text(const DiffContour& c, Lang lang) {
    return format_message(Msg::DiffContour, lang,
                          {c.kind == MotionKind::Mark ? Msg::DiffKindMark : Msg::DiffKindCut, mm_text(c.length_mm),
                           mm_text(c.start.x), mm_text(c.start.y)});
}

std::string side_text(const char* label, const DiffSide& s, Lang lang) {
    const CheckResult& r = s.tape->check;
    return format_message(
               Msg::DiffSide, lang,
               {label, display_text(s.name), r.profile, s.tape->contours.size(), mm_text(r.stats.cut_length_mm),
                r.stats.pierces, format_duration(r.stats.estimated_time_s)}) +
           "\n";
}

// The statistics a diff compares: (name, A's, B's, a count or a length).
struct StatChange {
    const char* name;  // its key in the JSON
    Msg word;          // its name in the text (in English: the key)
    double a, b;
    bool count = false;
};
// The machine time and the cost are compared when both sides have them (the profile's accel_mm_s2, costs).
std::vector<StatChange> stat_changes(const Stats& a, const Stats& b) {
    std::vector<StatChange> changes = {
        {"cut_length_mm", Msg::DiffStatCutLength, a.cut_length_mm, b.cut_length_mm},
        {"mark_length_mm", Msg::DiffStatMarkLength, a.mark_length_mm, b.mark_length_mm},
        {"travel_length_mm", Msg::DiffStatTravelLength, a.travel_length_mm, b.travel_length_mm},
        {"pierces", Msg::DiffStatPierces, static_cast<double>(a.pierces), static_cast<double>(b.pierces), true},
        {"motions", Msg::DiffStatMotions, static_cast<double>(a.motions), static_cast<double>(b.motions), true},
        {"estimated_time_s", Msg::DiffStatEstimatedTime, a.estimated_time_s, b.estimated_time_s}};
    if (a.machine_time && b.machine_time)
        changes.push_back(
            {"machine_time_s", Msg::DiffStatMachineTime, a.machine_time->total_s, b.machine_time->total_s});
    if (a.cost && b.cost) changes.push_back({"cost_total", Msg::DiffStatCostTotal, a.cost->total, b.cost->total});
    return changes;
}

nlohmann::json contour_json(const DiffContour& c) {
    return {{"kind", motion_kind_name(c.kind)},
            {"first_line", c.first_line},
            {"last_line", c.last_line},
            {"start_mm", {round_for_json(c.start.x), round_for_json(c.start.y)}},
            {"length_mm", round_for_json(c.length_mm)},
            {"motions", c.motions}};
}

nlohmann::json side_json(const DiffSide& s) {
    return {{"path", display_text(s.name)},
            {"profile", s.tape->check.profile},
            {"contours", s.tape->contours.size()},
            {"errors", s.tape->check.count(Severity::Error)},
            {"stats", stats_to_json(s.tape->check.stats)}};
}

}  // namespace

std::string difference_text(const TapeContours& a, const TapeContours& b, const ContourDiff& d, Lang lang) {
    const auto of_a = [&]() -> const DiffContour& { return a.contours[static_cast<std::size_t>(d.a)]; };
    const auto of_b = [&]() -> const DiffContour& { return b.contours[static_cast<std::size_t>(d.b)]; };
    switch (d.change) {
        case ContourChange::Same: break;
        case ContourChange::Moved:
            return format_message(Msg::DiffMoved, lang,
                                  {lines_text(of_a(), lang), lines_text(of_b(), lang), signed_mm_text(d.offset.x),
                                   signed_mm_text(d.offset.y), contour_text(of_a(), lang)});
        case ContourChange::Changed:
            return format_message(Msg::DiffChanged, lang,
                                  {lines_text(of_a(), lang), lines_text(of_b(), lang), contour_text(of_a(), lang),
                                   contour_text(of_b(), lang)});
        case ContourChange::Removed:
            return format_message(Msg::DiffRemoved, lang, {lines_text(of_a(), lang), contour_text(of_a(), lang)});
        case ContourChange::Added:
            return format_message(Msg::DiffAdded, lang, {lines_text(of_b(), lang), contour_text(of_b(), lang)});
    }
    return std::string(text(Msg::DiffSame, lang));
}

Message diff_counts_message(const TapeDiff& d) {
    return {Msg::DiffCounts,
            {d.count(ContourChange::Same), d.count(ContourChange::Moved), d.count(ContourChange::Changed),
             d.count(ContourChange::Removed), d.count(ContourChange::Added)}};
}

std::string diff_counts_text(const TapeDiff& d, Lang lang) { return diff_counts_message(d).text(lang); }

std::string diff_text(const DiffSide& a, const DiffSide& b, const TapeDiff& d, Lang lang) {
    std::string s = side_text("A", a, lang) + side_text("B", b, lang);
    for (const ContourDiff& c : d.contours)
        if (c.change != ContourChange::Same) s += difference_text(*a.tape, *b.tape, c, lang) + "\n";
    s += format_message(Msg::DiffContours, lang, {diff_counts_text(d, lang)}) + "\n";
    std::string stats;
    for (const StatChange& c : stat_changes(a.tape->check.stats, b.tape->check.stats)) {
        if (std::fabs(c.b - c.a) < 5e-4) continue;
        const auto value = [&](double v) { return c.count ? number_text(v) : mm_text(v); };
        if (!stats.empty()) stats += text(Msg::ListSeparator, lang);
        stats += std::string(text(c.word, lang)) + " " + value(c.a) + " -> " + value(c.b) + " (" +
                 (c.b >= c.a ? "+" : "") + value(c.b - c.a) + ")";
    }
    if (stats.empty()) stats = text(Msg::DiffStatisticsSame, lang);
    s += format_message(Msg::DiffStatistics, lang, {stats}) + "\n";
    return s;
}

std::string diff_json(const DiffSide& a, const DiffSide& b, const TapeDiff& d) {
    nlohmann::json summary = nlohmann::json::object();
    for (ContourChange c : kChanges) summary[contour_change_name(c)] = d.count(c);
    nlohmann::json contours = nlohmann::json::array();
    for (const ContourDiff& c : d.contours) {
        if (c.change == ContourChange::Same) continue;
        nlohmann::json j = {{"change", contour_change_name(c.change)}};
        j["a"] = c.a >= 0 ? contour_json(a.tape->contours[static_cast<std::size_t>(c.a)]) : nlohmann::json();
        j["b"] = c.b >= 0 ? contour_json(b.tape->contours[static_cast<std::size_t>(c.b)]) : nlohmann::json();
        if (c.change == ContourChange::Moved) j["offset_mm"] = {round_for_json(c.offset.x), round_for_json(c.offset.y)};
        contours.push_back(std::move(j));
    }
    nlohmann::json stats = nlohmann::json::object();
    for (const StatChange& c : stat_changes(a.tape->check.stats, b.tape->check.stats))
        stats[c.name] = {{"a", round_for_json(c.a)}, {"b", round_for_json(c.b)}, {"change", round_for_json(c.b - c.a)}};
    nlohmann::json out = {{"a", side_json(a)},  {"b", side_json(b)},    {"same", d.same()},
                          {"summary", summary}, {"contours", contours}, {"stats_change", stats}};
    return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace essi
