// The mouse and the keyboard on the drawing: pan, zoom, pick a motion, measure between snapped points, and the
// shortcuts (the Help window lists them).
#pragma once

#include <cstddef>

#include "app/Document.hpp"
#include "app/Layers.hpp"
#include "app/Measure.hpp"
#include "app/Navigation.hpp"
#include "app/Playback.hpp"
#include "app/PlatformServices.hpp"
#include "app/Preferences.hpp"
#include "app/Session.hpp"
#include "app/ShareLinks.hpp"
#include "app/UiState.hpp"
#include "app/View.hpp"

namespace essi::viewer {

// The motion under screen point (sx, sy) among motions [0, limit) of the kinds in `kind_mask`, from the exact
// geometry (the segments live on the GPU only); Selection::npos when none is within the pick radius.
[[nodiscard]] std::size_t pick(const Document& d, const View& view, std::size_t limit, int kind_mask, double sx,
                               double sy);
// The machine point under (sx, sy), snapped to the nearest end point or arc centre within the snap radius.
[[nodiscard]] Point snap(const Document* d, const View& view, double sx, double sy, bool* snapped);

class Input {
public:
    // What the mouse and the keys read and change.
    struct Parts {
        const Session& session;
        Navigation& navigation;
        Layers& layers;
        Playback& playback;
        Measure& measure;
        ShareLinks& shares;
        Preferences& preferences;
        UiState& ui;
        PlatformServices& platform;
    };
    explicit Input(const Parts& parts) : p_(parts) {}

    void handle_shortcuts();
    void handle_canvas();

private:
    void handle_characters();
    void toggle_side_panel(bool left);
    void handle_keys();
    void click(double sx, double sy);

    Parts p_;
    bool dragging_ = false;
    bool press_in_canvas_ = false;
    float press_x_ = 0, press_y_ = 0;
};

}  // namespace essi::viewer
