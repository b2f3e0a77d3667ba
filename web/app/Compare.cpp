#include "app/Compare.hpp"

#include "app/Document.hpp"
#include "essi/geom.hpp"

namespace essi::viewer {
namespace {

constexpr double kCompareChordMm = 0.05;  // arcs drawn as chords within this (a hair at any useful zoom)

std::vector<std::vector<Point>> flattened(const std::vector<DiffContour>& contours) {
    std::vector<std::vector<Point>> out;
    out.reserve(contours.size());
    for (const DiffContour& c : contours) {
        std::vector<Point> pts;
        for (std::size_t k = 0; k < c.path.size(); ++k) flatten(c.path[k], kCompareChordMm, pts, k == 0);
        out.push_back(std::move(pts));
    }
    return out;
}

}  // namespace

std::unique_ptr<Compare> make_compare(const Document& a, bool auto_profile, std::string name, const std::string& bytes) {
    auto c = std::make_unique<Compare>();
    c->name = std::move(name);
    c->a = tape_contours(a.bytes, a.setup, true);
    c->b = tape_contours(bytes, setup_tape(bytes, std::nullopt, auto_profile ? std::nullopt : std::optional<Profile>(a.profile)), true);
    c->diff = diff_contours(c->a.contours, c->b.contours);
    c->summary = diff_counts_text(c->diff);
    c->a_lines = flattened(c->a.contours);
    c->b_lines = flattened(c->b.contours);
    return c;
}

}  // namespace essi::viewer
