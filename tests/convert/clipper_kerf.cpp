// The kerf-compensated path against Clipper (Debian libpolyclipping-dev, Angus Johnson's Clipper 6): for every
// closed contour cut with compensation, the area of the compensated loop (core/geom/kerf.cpp) must be within 0.1 %
// of the area of Clipper's offset of the programmed contour with round joins (docs/semantics.md §8).
//
//   essi_clipper_kerf TAPE...      (ctest `clipper_kerf`: every example and real tape, and a generated nest)
//
// A closed contour: a run of cut motions with the same compensation whose last motion ends where one of them
// starts (lead-ins and lead-outs are outside it). Its compensated loop is what KerfPath makes of the contour on
// its own, closed (the motions fed once round and the first once more, so that the closing corner is turned like
// the others). Prints one line per contour and a summary; exit 1 when an area differs or nothing was compared.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <polyclipping/clipper.hpp>

#include "essi/dialect.hpp"
#include "essi/geom.hpp"
#include "essi/interp.hpp"
#include "essi/kerf.hpp"
#include "essi/read.hpp"

namespace {

constexpr double kScale = 1e5;               // Clipper's integers: 10 nm
constexpr double kChordMm = 1e-4;            // flattening of both loops (mm)
constexpr double kRelativeTolerance = 1e-3;  // 0.1 %
constexpr double kCloseMm = 1e-6;            // a contour is closed when its end is this near its start

struct Collect : essi::MotionSink {
    std::vector<essi::MotionRecord> motions;
    void on_motion(const essi::MotionRecord& m) override { motions.push_back(m); }
};

double polygon_area(const std::vector<essi::Point>& p) {
    double a = 0;
    for (std::size_t i = 0, n = p.size(); i < n; ++i) a += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    return a / 2;
}

std::vector<essi::Point> flatten_all(const std::vector<essi::MotionRecord>& motions) {
    std::vector<essi::Point> pts;
    for (const auto& m : motions) essi::flatten(m, kChordMm, pts, pts.empty());
    if (pts.size() > 1 && std::hypot(pts.front().x - pts.back().x, pts.front().y - pts.back().y) < kCloseMm)
        pts.pop_back();
    return pts;
}

// Clipper's offset of a closed polygon by `delta` mm (round joins), as an area (holes subtracted).
double clipper_offset_area(const std::vector<essi::Point>& pts, double delta) {
    ClipperLib::Path path;
    for (const auto& p : pts)
        path.push_back({static_cast<ClipperLib::cInt>(std::llround(p.x * kScale)),
                        static_cast<ClipperLib::cInt>(std::llround(p.y * kScale))});
    if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
    ClipperLib::ClipperOffset offset(2.0, kChordMm * kScale / 10);
    offset.AddPath(path, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    ClipperLib::Paths out;
    offset.Execute(out, delta * kScale);
    double area = 0;
    for (const auto& p : out) area += ClipperLib::Area(p);
    return area / (kScale * kScale);
}

// The compensated loop of a closed contour: KerfPath on the contour alone, once round and the first motion again.
std::vector<essi::MotionRecord> compensated_loop(const std::vector<essi::MotionRecord>& contour, bool& gouged) {
    Collect out;
    essi::KerfPath path(out, kChordMm);
    path.motion(contour.back());  // the entry: from there the first corner is the closing one
    for (const auto& m : contour) path.motion(m);
    const std::size_t before_last = out.motions.size();
    path.motion(contour.front());
    gouged = !path.take_gouges().empty();
    // After the entry, up to the last motion of the contour (the first piece the last call passed on).
    return {out.motions.begin() + 1, out.motions.begin() + static_cast<std::ptrdiff_t>(before_last) + 1};
}

bool same_compensation(const essi::MotionRecord& a, const essi::MotionRecord& b) {
    return a.kerf == b.kerf && a.kerf_mm == b.kerf_mm && a.head == b.head;
}

// The closed contours of a programmed stream: in each run of compensated cuts, the longest stretch that ends
// where it starts.
std::vector<std::vector<essi::MotionRecord>> closed_contours(const std::vector<essi::MotionRecord>& motions) {
    std::vector<std::vector<essi::MotionRecord>> found;
    std::size_t i = 0;
    while (i < motions.size()) {
        const auto& first = motions[i];
        if (first.kind != essi::MotionKind::Cut || first.kerf == essi::KerfSide::Off || !(first.kerf_mm > 0)) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < motions.size() && motions[end].kind == essi::MotionKind::Cut &&
               same_compensation(motions[end], first))
            ++end;
        bool done = false;
        for (std::size_t a = i; a < end && !done; ++a)
            for (std::size_t b = end; b-- > a && !done;) {
                const bool closes =
                    std::hypot(motions[a].start.x - motions[b].end.x, motions[a].start.y - motions[b].end.y) < kCloseMm;
                if (closes && (b > a || motions[a].curve == essi::CurveKind::Arc)) {
                    found.emplace_back(motions.begin() + static_cast<std::ptrdiff_t>(a),
                                       motions.begin() + static_cast<std::ptrdiff_t>(b) + 1);
                    done = true;
                }
            }
        i = end;
    }
    return found;
}

}  // namespace

int main(int argc, char** argv) {
    int compared = 0, failures = 0;
    for (int t = 1; t < argc; ++t) {
        std::ifstream in(argv[t], std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const essi::TapeSetup setup = essi::setup_tape(bytes, std::nullopt, std::nullopt);
        const essi::Tape tape = essi::read_tape(bytes, setup.profile, setup.format);
        std::vector<essi::Diagnostic> diagnostics;
        Collect programmed;
        essi::interpret(tape, bytes, setup.profile, programmed, diagnostics);
        int n = 0;
        for (const auto& contour : closed_contours(programmed.motions)) {
            ++n;
            const auto loop_pts = flatten_all(contour);
            const double signed_area = polygon_area(loop_pts);
            if (std::abs(signed_area) < 1e-9) continue;
            // Left of the direction of travel is inside a counter-clockwise contour: it shrinks.
            const bool left = contour.front().kerf == essi::KerfSide::Left;
            const bool ccw = signed_area > 0;
            const double delta = contour.front().kerf_mm * (left == ccw ? -1 : 1);
            bool gouged = false;
            const auto loop = compensated_loop(contour, gouged);
            if (gouged) {
                std::printf(
                    "skip %s contour %d (line %u): the compensated path gouges (E307), Clipper's offset does not\n",
                    argv[t], n, contour.front().line);
                continue;
            }
            const double ours = std::abs(polygon_area(flatten_all(loop)));
            const double theirs = std::abs(clipper_offset_area(loop_pts, delta));
            const double rel = theirs > 0 ? std::abs(ours - theirs) / theirs : std::abs(ours);
            ++compared;
            const bool ok = rel <= kRelativeTolerance;
            if (!ok) ++failures;
            std::printf(
                "%s %s contour %d (line %u, %zu motions, offset %+.3f mm): %.4f mm2, Clipper %.4f mm2 (%.4f %%)\n",
                ok ? "ok  " : "FAIL", argv[t], n, contour.front().line, contour.size(), delta, ours, theirs, rel * 100);
        }
    }
    std::printf("%d of %d compensated contours within %.1f %% of Clipper's offset area\n", compared - failures,
                compared, kRelativeTolerance * 100);
    if (compared == 0) {
        std::printf("FAIL no closed contour with kerf compensation was compared\n");
        return 1;
    }
    return failures ? 1 : 0;
}
