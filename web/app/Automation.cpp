#include "app/Automation.hpp"

#include <algorithm>
#include <cmath>

namespace essi::viewer {

namespace {

// setLayer's numbers after the four MotionKinds.
constexpr int kLayerPierces = 4;
constexpr int kLayerStart = 5;
constexpr int kLayerKerf = 6;      // the compensated torch path
constexpr int kLayerKerfBand = 7;  // the band of the cut's width
constexpr int kLayerTable = 8;     // the table and the plate
constexpr int kLayerParts = 9;     // the parts' group numbers, the plates and their remnants

}  // namespace

void Automation::set_layer(int layer, bool visible) {
    Layers& layers = p_.layers;
    if (layer >= 0 && layer < static_cast<int>(kMotionKinds)) layers.kinds[static_cast<std::size_t>(layer)] = visible;
    if (layer == kLayerPierces) layers.pierces = visible;
    if (layer == kLayerStart) layers.start = visible;
    if (layer == kLayerKerf) layers.kerf = visible;
    if (layer == kLayerKerfBand) layers.kerf_band = visible;
    if (layer == kLayerTable) layers.table = visible;
    if (layer == kLayerParts) layers.parts = visible;
}

void Automation::set_playback(double factor, bool playing) {
    const Document* doc = p_.session.document();
    if (!doc) return;
    Playback& p = p_.playback;
    p.factor = static_cast<float>(std::clamp(factor, double{Playback::kMinFactor}, double{Playback::kMaxFactor}));
    if (playing != p.playing) p.toggle(doc->motions.size());
}

void Automation::pinch(double x0, double y0, double x1, double y1, double factor) {
    if (!(factor > 0) || !std::isfinite(factor)) return;
    View& view = p_.navigation.view();
    view.pan_by(x1 - x0, y1 - y0);
    view.zoom_at(x1, y1, factor);
}

void Automation::show_difference(int k) {
    const Compare* c = p_.compare.result();
    if (!c || k < 0) return;
    for (const ContourDiff& d : c->diff.contours) {
        if (d.change == ContourChange::Same || k-- > 0) continue;
        p_.compare.show_difference(d);
        return;
    }
}

void Automation::set_examples(std::vector<std::string> names) {
    for (const std::string& name : names) p_.fonts.require_glyphs(name);
    p_.ui.examples = std::move(names);
}

}  // namespace essi::viewer
