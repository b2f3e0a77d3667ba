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

// One motion, compact: 32 bytes (the stream of a 10 M block tape must fit in the browser). The start is
// the end of the motion before (Document::start_of), except where `kFlagJump` says it is kept apart
// (head 2, the first motion). Arcs keep their geometry in Document::arcs, parabolas their full record.
struct Motion {
    Point end;
    std::uint32_t line = 0;
    std::uint32_t curve_index = kNoCurve;  // into Document::arcs or Document::parabolas
    float feed_mm_min = 0;
    MotionKind kind = MotionKind::Travel;
    CurveKind curve = CurveKind::Line;
    std::uint8_t tools = 0;
    std::uint8_t flags = 0;  // kFlag*
    static constexpr std::uint32_t kNoCurve = 0xFFFFFFFFu;
    static constexpr std::uint8_t kFlagHead2 = 1, kFlagKerfLeft = 2, kFlagKerfRight = 4, kFlagJump = 8;
};
static_assert(sizeof(Motion) == 32, "Motion must stay compact");

// An arc's geometry beyond its end points (ccw is the sign of the sweep).
struct ArcData {
    Point centre;
    double radius = 0, end_radius = 0, sweep = 0, length_mm = 0;
};

struct Document {
    std::string name;
    std::string bytes;
    Profile profile;
    Tape tape;                            // every block (the inspector's words), appended chunk by chunk
    std::vector<Diagnostic> diagnostics;  // sorted by line, column (as `essi check`)
    Stats stats;
    std::vector<Motion> motions;
    std::vector<ArcData> arcs;
    std::vector<MotionRecord> parabolas;
    std::vector<std::pair<std::uint32_t, Point>> jumps;  // (motion, start) where kFlagJump is set
    std::vector<std::pair<std::uint32_t, float>> kerfs;  // (first motion, kerf mm) whenever the kerf changes
    std::vector<Point> pierces;           // where a cutting tool came on (display only)
    std::vector<std::uint32_t> line_index;  // byte offset of line 1 + k * kLineIndexStride
    std::size_t lines = 0;
    Box bbox;                             // all motion
    Point origin;                         // GPU coordinates are relative to this (float precision)

    static constexpr std::size_t kLineIndexStride = 64;

    [[nodiscard]] std::size_t line_count() const { return lines; }
    [[nodiscard]] std::string_view line(std::size_t line_1based) const;
    [[nodiscard]] Point start_of(std::size_t i) const;
    // The full record of motion i (rebuilt from the compact form; `block` left 0: see block_of).
    [[nodiscard]] MotionRecord record(std::size_t i) const;
    // The block of motion i (the motion block on its line).
    [[nodiscard]] std::size_t block_of(std::size_t i) const;
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

// Loads a document in steps that each take about `budget_ms` (so the page keeps drawing): the line index,
// then TapeReader chunks through essi::TapeChecker (the statistics and diagnostics of `essi check`), the
// viewer's compact stream taken on the way (TapeChecker's `also` sink), the blocks appended to the Tape.
class DocumentLoader {
public:
    DocumentLoader(std::string name, std::string bytes, Profile profile);
    ~DocumentLoader();
    // Runs for about budget_ms; returns true when the document is complete.
    bool step(double budget_ms = 12);
    [[nodiscard]] float progress() const;      // 0..1
    [[nodiscard]] const char* stage() const;   // "indexing lines", "reading and checking", ...
    [[nodiscard]] std::unique_ptr<Document> take() { return std::move(doc_); }
private:
    class Sink;
    std::unique_ptr<Document> doc_;
    std::unique_ptr<Sink> sink_;
    std::unique_ptr<TapeReader> reader_;
    std::unique_ptr<TapeChecker> checker_;
    Tape chunk_;
    int stage_ = 0;
    std::size_t index_pos_ = 0;
    std::size_t motion_lines_ = 0;  // lines starting with + or -: the motion stream's size, near enough
    static constexpr std::size_t kMotionReserveSlack = 64;  // 1/64 more for addressed motions ("1+100+0")
    std::size_t read_pos_ = 0;  // byte offset reached by the reader
};

}  // namespace essi::viewer
