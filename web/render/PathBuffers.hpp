// The motion stream as GPU-ready arrays: one instance (x0 y0 x1 y1 kind) per flattened segment, built in
// chunks from a Document at a chord tolerance that follows the zoom (essi::flatten).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "app/Document.hpp"

namespace essi::viewer {

struct SegmentInstance {
    float x0, y0, x1, y1;
    float kind;  // MotionKind as a number
};
static_assert(sizeof(SegmentInstance) == 20);

struct MarkerInstance {
    float x, y;
    float type;  // 0 pierce, 1 start, 2 tool
};

enum class MarkerType { Pierce = 0, Start = 1, Tool = 2 };

class PathBuffers {
public:
    void begin(const Document& doc, double chord_tolerance_mm);
    // Flattens up to `max_motions` more motions; returns true when complete.
    bool step(std::size_t max_motions);
    [[nodiscard]] bool complete() const { return doc_ != nullptr && next_ >= doc_->motions.size(); }
    [[nodiscard]] float progress() const;
    [[nodiscard]] double tolerance() const { return tolerance_; }

    std::vector<SegmentInstance> segments;     // freed once uploaded (release_segments): the GPU has them
    std::size_t segment_count = 0;
    std::vector<std::uint32_t> first_segment;  // per motion, plus one at the end
    std::vector<MarkerInstance> markers;       // pierces then the start point

    void release_segments();
    // Motion index of segment s.
    [[nodiscard]] std::size_t motion_of_segment(std::size_t s) const;

private:
    const Document* doc_ = nullptr;
    double tolerance_ = 0.01;
    std::size_t next_ = 0;
    std::vector<Point> scratch_;
};

}  // namespace essi::viewer
