// The motion stream as GPU-ready segments (x0 y0 x1 y1 in float mm relative to the document origin, and a
// kind byte), built in steps from a Document at a chord tolerance that follows the zoom (essi::flatten).
// No copy of the whole segment stream is kept: the segments made by a step wait in a small staging area
// until the Renderer takes them (Renderer::append, a few texture rows at a time).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "app/ColourBy.hpp"
#include "app/Document.hpp"
#include "essi/kerf.hpp"
#include "render/Palette.hpp"

namespace essi::viewer {

struct MarkerInstance {
    float x, y;
    float type;  // MarkerType (render/Palette.hpp), as the marker texture holds it
};

class PathBuffers {
public:
    PathBuffers();
    ~PathBuffers();
    PathBuffers(const PathBuffers&) = delete;
    PathBuffers& operator=(const PathBuffers&) = delete;
    // (moved only when complete or new: a build in progress has its kerf path point at it)
    PathBuffers(PathBuffers&&) noexcept;
    PathBuffers& operator=(PathBuffers&&) noexcept;
    // `colour_by`: the cuts' and marks' segments of a colour bin get its kind (kColourByCutKind, render/Palette.hpp).
    // `sources`: what colour by part group and by speed take their values from (ColourSources).
    void begin(const Document& doc, double chord_tolerance_mm, ColourBy colour_by = ColourBy::Kind,
               const ColourSources* sources = nullptr);
    // Flattens up to `max_motions` more motions into the staging area; returns true when complete.
    bool step(std::size_t max_motions);
    [[nodiscard]] bool complete() const { return doc_ != nullptr && next_ >= doc_->motions.size(); }
    [[nodiscard]] float progress() const;
    [[nodiscard]] double tolerance() const { return tolerance_; }
    [[nodiscard]] ColourBy colour_by() const { return colour_by_; }
    // What the colours of colour_by() stand for (none by kind).
    [[nodiscard]] std::vector<ColourLegendEntry> colour_legend(Lang lang) const {
        return bins_ ? bins_->legend(lang) : std::vector<ColourLegendEntry>{};
    }
    // The final segment count once complete, a projection from the share built so far before.
    [[nodiscard]] std::size_t estimated_segments() const;

    std::size_t segment_count = 0;             // segments made so far (all of them once complete)
    std::vector<std::uint32_t> first_segment;  // per motion, plus one at the end
    std::vector<MarkerInstance> markers;       // pierces, the start point, the diagnostics' marks (until uploaded)
    // The kerf layers (a tape with compensation): the compensated torch path and the band of the cut's width,
    // made by a KerfPath that follows the motions. A motion's compensated piece is final when the next motion is
    // known, so it is among that one's segments.
    std::size_t kerf_segments = 0;
    std::array<float, kKerfBandWidths> kerf_widths{};  // the bands' widths (mm), in order of appearance
    std::size_t kerf_width_count = 0;

    // Segments made but not yet taken by the renderer: [staged_first, segment_count).
    std::vector<float> staged_ends;          // 4 floats a segment
    std::vector<std::uint8_t> staged_kinds;  // MotionKind
    std::size_t staged_first = 0;
    [[nodiscard]] std::size_t staged_count() const { return staged_kinds.size(); }
    void drop_staged(std::size_t n);  // the first n staged segments are on the GPU
    void release_staging();           // frees the staging area (the build is complete)

    [[nodiscard]] std::size_t memory_bytes() const;

private:
    void put(Point a, Point b, std::uint8_t kind);
    void put_kerf_piece(const MotionRecord& piece);
    [[nodiscard]] std::uint8_t band_kind(double width_mm);
    class KerfSegments;
    std::unique_ptr<KerfSegments> kerf_sink_;
    std::unique_ptr<KerfPath> kerf_;

    const Document* doc_ = nullptr;
    double tolerance_ = 0.01;
    ColourBy colour_by_ = ColourBy::Kind;
    std::unique_ptr<ColourBins> bins_;  // (colour by a value)
    std::size_t next_ = 0;
    std::vector<Point> scratch_;
    std::vector<Point> kerf_scratch_;  // (a piece is flattened while a motion's may be in scratch_)
};

}  // namespace essi::viewer
