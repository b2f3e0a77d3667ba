// What is drawn: the motion kinds (indexed by essi::MotionKind), the pierce and start markers, the grid.
#pragma once

#include <array>
#include <cstddef>

#include "app/ColourBy.hpp"
#include "essi/motion.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

struct Layers {
    std::array<bool, kMotionKinds> kinds = {true, true, true, true};  // by MotionKind
    bool pierces = true;
    bool start = true;
    bool grid = true;
    bool kerf = true;       // the compensated torch path (a tape with kerf compensation)
    bool kerf_band = true;  // the band of the cut's real width along it
    bool table = true;      // the machine's table (a profile with one) and the plate (the cut box)
    // The parts (TapeFacts::parts): each part's group number, each plate and its remnant. Off at first: the core
    // reads the tape again for them.
    bool parts = false;
    // The problems only: what no diagnostic concerns drawn faint (the marks, the blocks, contours and related places
    // of the diagnostics in full); kept across sessions (Preferences::set_problems_only).
    bool problems_only = false;
    // The cuts and marks in the colour of their feed or cut order (ColourBy.hpp) rather than their kind's.
    ColourBy colour_by = ColourBy::Kind;

    [[nodiscard]] bool& kind(MotionKind k) { return kinds[static_cast<std::size_t>(k)]; }
    [[nodiscard]] bool kind(MotionKind k) const { return kinds[static_cast<std::size_t>(k)]; }
    // A bit per visible MotionKind and kerf layer (DrawOptions::layer_mask).
    [[nodiscard]] int kind_mask() const {
        int m = 0;
        for (std::size_t k = 0; k < kMotionKinds; ++k)
            if (kinds[k]) m |= kind_bit(static_cast<MotionKind>(k));
        return m | (kerf ? kKerfPathBit : 0) | (kerf_band ? kKerfBandBit : 0);
    }
    // A bit per visible MarkerType drawn from the marker texture (DrawOptions::marker_mask).
    [[nodiscard]] int marker_mask() const {
        return (pierces ? marker_bit(MarkerType::Pierce) : 0) | (start ? marker_bit(MarkerType::Start) : 0) |
               kDiagnosticMarkersMask;  // (the diagnostics' marks are always drawn)
    }
};

}  // namespace essi::viewer
