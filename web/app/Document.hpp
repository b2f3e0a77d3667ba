// A loaded tape as the viewer holds it: the bytes, the core's read result, a compact copy of the motion
// stream (full records only for arcs and parabolas), statistics and diagnostics exactly as the core gives them.
// Loading runs in steps so the UI can draw a progress bar between them (DocumentLoader).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/report.hpp"

namespace essi::viewer {

// One motion, compact (the stream of a 10 M block tape must fit in the browser).
struct Motion {
    Point start, end;
    std::uint32_t line = 0;
    std::uint32_t block = 0;
    std::uint32_t curve_index = kNoCurve;  // into Document::curves for arcs and parabolas
    float feed_mm_min = 0;
    float kerf_mm = 0;
    MotionKind kind = MotionKind::Travel;
    CurveKind curve = CurveKind::Line;
    std::uint8_t tools = 0;
    std::uint8_t flags = 0;  // kFlag*
    static constexpr std::uint32_t kNoCurve = 0xFFFFFFFFu;
    static constexpr std::uint8_t kFlagHead2 = 1, kFlagKerfLeft = 2, kFlagKerfRight = 4;
};

struct Document {
    std::string name;
    std::string bytes;
    Profile profile;
    Tape tape;
    std::vector<Diagnostic> diagnostics;  // sorted by line, column (as `essi check`)
    Stats stats;
    std::vector<Motion> motions;
    std::vector<MotionRecord> curves;
    std::vector<Point> pierces;           // where a cutting tool came on (display only)
    std::vector<std::uint32_t> line_starts;  // byte offset of line k+1 (CR, LF, CR LF, LF CR end a line)
    Box bbox;                             // all motion
    Point origin;                         // GPU coordinates are relative to this (float precision)

    [[nodiscard]] std::size_t line_count() const { return line_starts.size(); }
    [[nodiscard]] std::string_view line(std::size_t line_1based) const;
    // The full record of motion i (rebuilt from the compact form for lines).
    [[nodiscard]] MotionRecord record(std::size_t i) const;
    // First motion whose line is >= line; motions.size() when none.
    [[nodiscard]] std::size_t first_motion_at_or_after(std::uint32_t line) const;
    // Motions [first, last) of one source line.
    [[nodiscard]] std::pair<std::size_t, std::size_t> motions_of_line(std::uint32_t line) const;
    // Blocks [first, last) that start on one source line.
    [[nodiscard]] std::pair<std::size_t, std::size_t> blocks_of_line(std::uint32_t line) const;
    [[nodiscard]] bool has_errors() const;
    [[nodiscard]] std::size_t count(Severity s) const;
    [[nodiscard]] std::size_t memory_bytes() const;
};

// In words, for the block inspector: "cut arc CCW r=50.0 mm, centre (10.0, 20.0), sweep 90.0°, 78.5 mm".
[[nodiscard]] std::string describe_motion(const MotionRecord& m);
// The meaning of block i: describe_function for function blocks, the kind for the others.
[[nodiscard]] std::string describe_block(const Document& doc, std::size_t block_index);

// Loads a document in steps: index lines, read, interpret (+ statistics). Each step() does one stage.
class DocumentLoader {
public:
    DocumentLoader(std::string name, std::string bytes, Profile profile);
    // Runs the next stage; returns true when the document is complete.
    bool step();
    [[nodiscard]] float progress() const;      // 0..1
    [[nodiscard]] const char* stage() const;   // "indexing lines", "reading", "interpreting"
    [[nodiscard]] std::unique_ptr<Document> take() { return std::move(doc_); }
private:
    std::unique_ptr<Document> doc_;
    int stage_ = 0;
    std::size_t index_pos_ = 0;
};

}  // namespace essi::viewer
