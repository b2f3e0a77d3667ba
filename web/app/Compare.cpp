#include "app/Compare.hpp"

#include "app/Document.hpp"
#include "essi/geom.hpp"
#include "essi/text.hpp"

namespace essi::viewer {
namespace {

std::vector<std::vector<Point>> flattened(const std::vector<DiffContour>& contours) {
    std::vector<std::vector<Point>> out(contours.size());
    for (std::size_t k = 0; k < contours.size(); ++k) flatten_contour(contours[k], kCompareChordMm, out[k]);
    return out;
}

}  // namespace

void flatten_contour(const DiffContour& c, double chord_mm, std::vector<Point>& out) {
    out.clear();
    for (std::size_t k = 0; k < c.path.size(); ++k) flatten(c.path[k], chord_mm, out, k == 0);
}

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

void CompareMode::show_difference(const ContourDiff& d) {
    if (!compare_) return;
    const auto of = [](const std::vector<DiffContour>& contours, int k) {
        return k >= 0 && static_cast<std::size_t>(k) < contours.size() ? &contours[static_cast<std::size_t>(k)]
                                                                       : nullptr;
    };
    const DiffContour* a = of(compare_->a.contours, d.a);
    const DiffContour* b = of(compare_->b.contours, d.b);
    Box box;
    for (const DiffContour* c : {a, b})
        if (c) box.add(c->box);
    if (a) navigation_.select_line(a->first_line, false);
    if (!box.empty) navigation_.show_box(box);
}

}  // namespace essi::viewer
