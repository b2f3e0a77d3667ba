#include "app/Compare.hpp"

#include "app/Document.hpp"
#include "essi/geom.hpp"
#include "essi/text.hpp"

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

std::unique_ptr<Compare> make_compare(const Document& a, bool auto_profile, std::string name,
                                      const std::string& bytes) {
    auto c = std::make_unique<Compare>();
    c->name = std::move(name);
    c->a = tape_contours(a.bytes, a.setup, true);
    c->b = tape_contours(
        bytes, setup_tape(bytes, std::nullopt, auto_profile ? std::nullopt : std::optional<Profile>(a.profile)), true);
    c->diff = diff_contours(c->a.contours, c->b.contours);
    c->summary = diff_counts_text(c->diff);
    c->a_lines = flattened(c->a.contours);
    c->b_lines = flattened(c->b.contours);
    return c;
}

void CompareMode::begin(const Document* a) {
    if (!a) return notices_.notify(Msg::UiLoadFirstCompare);
    next_ = true;
    notices_.notify(Msg::UiDropOtherRevision, {display_text(a->name)});
}

void CompareMode::compare_with(const Document* a, bool auto_profile, std::string name, const std::string& bytes) {
    next_ = false;
    if (!a) return;
    fonts_.require_glyphs(name);
    compare_ = make_compare(*a, auto_profile, std::move(name), bytes);
    notices_.notify(Msg::UiComparedWith, {display_text(compare_->name), diff_counts_message(compare_->diff)});
}

void CompareMode::end() {
    compare_.reset();
    next_ = false;
}

void CompareMode::show_contour(std::size_t index, bool of_b) {
    if (!compare_) return;
    const auto& contours = of_b ? compare_->b.contours : compare_->a.contours;
    if (index >= contours.size()) return;
    const DiffContour& c = contours[index];
    if (!of_b) navigation_.select_line(c.first_line, false);
    navigation_.show_box(c.box);
}

}  // namespace essi::viewer
