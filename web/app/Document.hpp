// A loaded tape as the viewer holds it: the bytes, a compact copy of the motion stream (16 bytes a motion, 8 more
// an arc; full records only for parabolas), statistics and diagnostics exactly as the core gives them, and what
// it takes to read any line's blocks again. DocumentLoader (DocumentLoader.hpp) makes it in steps, DocumentSink
// (DocumentSink.hpp) writes its motions; Describe.hpp puts a motion or a block in words. Memory: the viewer must
// stay below 2 x the tape's bytes + what the core's Tape holds.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostic_marks.hpp"
#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/lines.hpp"
#include "essi/motion.hpp"
#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/stats.hpp"

namespace essi::viewer {

// A machine position in unit increments. The interpreter keeps every position as a whole number of units
// (machine mm = units x Profile::unit_mm + the setup offset, Document::point_mm), so 8 bytes hold it exactly.
struct UnitPoint {
    std::int32_t x = 0, y = 0;
    friend bool operator==(const UnitPoint&, const UnitPoint&) = default;
};

// One motion, compact: 16 bytes (the stream of a 10 M block tape must fit in the browser next to its bytes).
// The start is the end of the motion before (Document::start_of), except where `kFlagJump` says it is kept
// apart (head 2, the first motion). Arcs keep their centre in Document::arc_centres; radius, sweep and length
// are worked out again from the integers when the record is needed (Document::record, the same numbers as the
// interpreter's). Parabolas, and the rare motion with a point that is not a whole number of units within
// 32 bits, keep their full record (`kFlagKept`, Document::kept).
struct Motion {
    UnitPoint end_units;  // meaningless with kFlagKept (Document::end_of)
    std::uint32_t line = 0;
    MotionKind kind = MotionKind::Travel;
    CurveKind curve = CurveKind::Line;
    std::uint8_t tools = 0;
    std::uint8_t flags = 0;  // kFlag*
    static constexpr std::uint8_t kFlagHead2 = 1, kFlagKerfLeft = 2, kFlagKerfRight = 4, kFlagJump = 8,
                                  kFlagCcw = 16,  // arcs: counter-clockwise in machine coordinates
        kFlagKept = 32,                           // the full record is in Document::kept
        kFlagRapidFeed = 64;                      // the feed is the profile's rapid speed (else: `feeds`)
};
static_assert(sizeof(Motion) == 16, "Motion must stay compact");

// Which motions have an entry in a side table (an arc centre) and where: a bit a motion and a running count
// every 64 motions (1.5 bits a motion instead of a 4-byte index).
class RankIndex {
public:
    void reserve(std::size_t n);
    void push_back(bool has_entry);
    // Entries of the motions before i (the index of motion i's entry when it has one).
    [[nodiscard]] std::size_t rank(std::size_t i) const;
    [[nodiscard]] std::size_t memory_bytes() const;
    // As bytes, and read back (false when the bytes are not one): DocumentWire.hpp.
    void save(WireWriter& out) const;
    [[nodiscard]] bool restore(WireReader& in);

private:
    std::vector<std::uint64_t> bits_;
    std::vector<std::uint32_t> before_;  // entries before each 64 motions
    std::size_t size_ = 0, count_ = 0;
};

// The reader as it was before one chunk of blocks, kept so that the chunk can be read again: the document
// holds no Tape (35 bytes a motion); the block inspector re-reads the chunk of the line it shows.
struct ReadChunk {
    TapeReader reader;
    std::uint32_t first_block = 0;  // in the whole tape
    std::uint32_t first_line = 0;   // the line of that block
};

// The blocks that start on one source line, read again from the tape: [first, last) of `chunk`. Valid until
// the next Document::blocks_of_line of another chunk.
struct LineBlocks {
    const Tape* chunk = nullptr;
    std::size_t first = 0, last = 0;
    [[nodiscard]] bool empty() const { return first == last; }
    // Index in the whole tape of block k of the chunk.
    [[nodiscard]] std::size_t tape_index(std::size_t k) const { return chunk->first_block() + k; }
};

// A diagnostic drawn where it is: its index in Document::diagnostics and its place (program mm;
// essi::diagnostic_place).
struct DiagnosticMark {
    std::uint32_t diagnostic = 0;
    Point at;
};

// Never copied or moved by value (the ReadChunks refer to `bytes` and `profile`): held by a unique_ptr.
struct Document {
    std::string name;
    std::string bytes;
    Profile profile;
    TapeSetup setup;                      // how the tape is read: format, profile (given or auto), evidence, note
    std::vector<Diagnostic> diagnostics;  // sorted by line, column (as `essi check`)
    Stats stats;
    std::vector<Motion> motions;
    std::vector<UnitPoint> arc_centres;                        // of the arcs that are not kept, in motion order
    RankIndex arc_rank;                                        // motion -> its entry in arc_centres
    std::vector<std::pair<std::uint32_t, MotionRecord>> kept;  // (motion, full record) where kFlagKept is set
    std::vector<std::pair<std::uint32_t, Point>> jumps;        // (motion, start) where kFlagJump is set
    // (first motion, kerf mm) whenever the kerf changes, over the motions with kerf compensation on (off: 0)
    std::vector<std::pair<std::uint32_t, float>> kerfs;
    // (first motion, mm/min) whenever the feed changes, over the motions without kFlagRapidFeed
    std::vector<std::pair<std::uint32_t, float>> feeds;
    std::vector<std::uint32_t> pierces;  // the motions the statistics' pierces are at (essi::PierceTracker)
    LineIndex line_index;                // where each line starts (the core's rule, essi/lines.hpp)
    // Made after the check (DocumentLoader's last stage): a mark per diagnostic that has a place, and the motions
    // the diagnostics concern (their blocks, contours and related places: [first, last) ranges, sorted, merged).
    std::vector<DiagnosticMark> marks;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> concerned_motions;
    std::vector<ReadChunk> chunks;            // the reader before each chunk of kReadChunkBlocks blocks
    std::size_t blocks = 0, block_words = 0;  // what the reader read (all chunks)
    std::size_t curves = 0;                   // arcs and parabolas (the drawing depends on the zoom)
    Box bbox;                                 // all motion
    Point origin;                             // GPU coordinates are relative to this (float precision)

    // Blocks per TapeReader chunk: a few ms in the browser; the chunk, read again for the inspector, ~150 KB.
    static constexpr std::size_t kReadChunkBlocks = 8192;

    Document() = default;
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    [[nodiscard]] std::size_t line_count() const { return line_index.line_count(); }
    [[nodiscard]] std::string_view line(std::size_t line_1based) const;
    // Millimetres of a position in units, as the interpreter computes them (essi::units_to_mm).
    [[nodiscard]] Point point_mm(UnitPoint u) const { return units_to_mm(profile, u.x, u.y); }
    // The units of a position in mm, when it is a whole number of them within 32 bits (false otherwise).
    [[nodiscard]] bool to_units(Point mm, UnitPoint& out) const;
    [[nodiscard]] Point end_of(std::size_t i) const;
    [[nodiscard]] Point start_of(std::size_t i) const;
    [[nodiscard]] float feed_of(std::size_t i) const;
    [[nodiscard]] float kerf_of(std::size_t i) const;
    // The centre of arc i (an arc motion), without working out the rest of its record.
    [[nodiscard]] Point arc_centre(std::size_t i) const;
    // The full record of motion i (rebuilt from the compact form; `block` left 0: see block_of).
    [[nodiscard]] MotionRecord record(std::size_t i) const;
    // Motion i when several torches cut it (its record: torches, torch_step), else null.
    [[nodiscard]] const MotionRecord* torch_copies(std::size_t i) const;
    // The block of motion i (the motion block on its line).
    [[nodiscard]] std::size_t block_of(std::size_t i) const;
    // First motion whose line is >= line; motions.size() when none.
    [[nodiscard]] std::size_t first_motion_at_or_after(std::uint32_t line) const;
    // Motions [first, last) of one source line, of the lines of a range.
    [[nodiscard]] std::pair<std::size_t, std::size_t> motions_of_line(std::uint32_t line) const;
    [[nodiscard]] std::pair<std::size_t, std::size_t> motions_of_lines(LineRange lines) const;
    // What the motion stream says about a line: the end of its first motion, the end of the last one before it.
    [[nodiscard]] LineEnds line_ends(std::uint32_t line) const;
    // The marks and the concerned motions of the diagnostics (after the check).
    void place_diagnostics();
    // The torch's path of one source line's motions where kerf compensation is on or ends (docs/semantics.md §8):
    // the compensated pieces, worked out from where that compensation started (the inspector's second position).
    [[nodiscard]] std::vector<MotionRecord> torch_path_of_line(std::uint32_t line) const;
    // The blocks that start on one source line (the chunk that holds them is read again when needed).
    [[nodiscard]] LineBlocks blocks_of_line(std::uint32_t line) const;
    [[nodiscard]] bool has_errors() const;
    [[nodiscard]] std::size_t count(Severity s) const;
    // What the document holds (capacities), the bytes included: in parts, and the sum.
    [[nodiscard]] std::vector<std::pair<const char*, std::size_t>> memory_parts() const;
    [[nodiscard]] std::size_t memory_bytes() const;
    // What the core's Tape of the whole tape would hold (read_tape: a Block a block, 4 bytes a word and the
    // sparse word index): the "core's bytes per block" of the viewer's memory budget.
    [[nodiscard]] std::size_t core_tape_bytes() const;

private:
    [[nodiscard]] const MotionRecord& kept_record(std::size_t i) const;
    [[nodiscard]] const Tape& reread(std::size_t chunk) const;
    // The chunk last read again (blocks_of_line): the inspector asks for the same line every frame.
    mutable Tape reread_;
    mutable std::size_t reread_chunk_ = ~std::size_t(0);
};

}  // namespace essi::viewer
