// Contours (docs/semantics.md §9): the motion stream cut into what one kind of tool of one head makes between
// coming on and going off. The rule is ContourBuilder's; the cut plan (essi/plan.hpp) takes its cuts from it and
// `essi diff` (essi/diff.hpp) its contours.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "essi/motion.hpp"

namespace essi {

// A contour: a run of cut motions (or of mark motions) of one head. It ends at a motion of that head of another
// kind, at an event after which no tool of its kind is on (a cutting tool for a cut, a marking tool for a mark),
// or at the end of the stream. The other head's motions may come between its motions, and neither end it nor
// belong to it.
struct Contour {
    MotionKind kind = MotionKind::Cut;            // Cut or Mark
    std::uint8_t head = 1;                        // 1, or 2 for head 2 of a 3-axis tape
    std::uint32_t first_line = 0, last_line = 0;  // the source lines of its first and last motion
    // Where it is in the motion stream (0: the stream's first motion): its motions are those of its head with
    // an index in [first_motion, end_motion) (of_contour; contour_motions reads them back).
    std::uint32_t first_motion = 0, end_motion = 0;
};

// Whether `m`, a motion of the stream with an index in [c.first_motion, c.end_motion), is one of the contour's.
[[nodiscard]] inline bool of_contour(const Contour& c, const MotionRecord& m) { return (m.head == 2) == (c.head == 2); }

// The motions of a stream by their index (0: the first one a sink was given), for a caller that keeps them
// anyway (the viewer's document): a contour's motions are read back from it.
class MotionStore {
public:
    virtual ~MotionStore() = default;
    [[nodiscard]] virtual MotionRecord motion(std::size_t index) const = 0;
};

// The contour's motions, in order, read back from the store of the stream it was found in: its geometry exactly
// (arcs and parabolas as the interpreter made them).
[[nodiscard]] std::vector<MotionRecord> contour_motions(const Contour& c, const MotionStore& store);

// The rule of Contour, applied to a motion stream: it is given every motion, in stream order (it counts their
// indices), and every event, then end(). A contour that a motion opens goes to `began` (a callable taking a T&,
// its first motion not yet in it), one that ends to `ended` (a callable taking a T& that it may move from). T is
// Contour, or a type derived from it that carries what its caller gathers along a contour (kept small: the cut
// plan makes one a cut). `kTools`: the kinds of contour made, by their tools (kCuttingTools: the cuts only; a mark
// motion is then one of another kind, which ends a cut).
template <class T, std::uint8_t kTools = kCuttingTools | kMarkingTools>
class ContourBuilder {
public:
    // The contour the motion belongs to (opened by it, its head's contour of another kind ended first), or null
    // for a motion that makes none (it ends its head's contour).
    template <class Began, class Ended>
    T* motion(std::uint8_t head, MotionKind kind, std::uint32_t line, Began&& began, Ended&& ended) {
        const std::uint32_t index = next_motion_++;
        Slot& s = head == 2 ? second_ : first_;
        T& c = s.contour;
        if (kind != s.kind) [[unlikely]] {  // (else the motion goes on with the contour)
            if (s.tools) close(s, ended);
            const std::uint8_t tools = tools_of(kind);
            if (!tools) return nullptr;
            c = T{};
            c.kind = kind;
            c.head = head == 2 ? 2 : 1;
            c.first_line = line;
            c.first_motion = index;
            s.kind = kind;
            s.tools = tools;
            began(c);
        }
        c.last_line = line;
        c.end_motion = index + 1;
        return &c;
    }
    template <class Began, class Ended>
    T* motion(const MotionRecord& m, Began&& began, Ended&& ended) {
        return motion(m.head, m.kind, m.line, began, ended);
    }
    template <class Began, class Ended>
    T* motion(const UnitLine& l, Began&& began, Ended&& ended) {  // (head 1's)
        return motion(1, l.kind, l.line, began, ended);
    }

    // An event: the contours whose kind of tool it leaves off end (head 1's first).
    template <class Ended>
    void event(std::uint8_t tools_after, Ended&& ended) {
        if (each_kind_on(tools_after)) return;  // (most events: nothing ends)
        if (first_.tools && (kOneKind || !(first_.tools & tools_after))) close(first_, ended);
        if (second_.tools && (kOneKind || !(second_.tools & tools_after))) close(second_, ended);
    }
    // The end of the stream: the contours still open end (head 1's first).
    template <class Ended>
    void end(Ended&& ended) {
        if (first_.tools) close(first_, ended);
        if (second_.tools) close(second_, ended);
    }

    // The contour of head `head` (1 or 2) in progress, or null.
    [[nodiscard]] const T* open(std::uint8_t head) const {
        const Slot& s = head == 2 ? second_ : first_;
        return s.tools ? &s.contour : nullptr;
    }

private:
    // A head's contour in progress, its kind and the tools that make it (none: kNone and 0).
    static constexpr MotionKind kNone = static_cast<MotionKind>(0xff);
    struct Slot {
        T contour;
        MotionKind kind = kNone;
        std::uint8_t tools = 0;
    };
    // The tools that make a contour of this kind (0: it makes none).
    static constexpr std::uint8_t tools_of(MotionKind kind) {
        return kTools & (kind == MotionKind::Cut ? kCuttingTools : kind == MotionKind::Mark ? kMarkingTools : 0);
    }
    // Contours of one kind only: when its tools are off, each contour in progress ends.
    static constexpr bool kOneKind = kTools == kCuttingTools || kTools == kMarkingTools;
    // Whether a tool of each kind made is on: then no contour ends.
    static constexpr bool each_kind_on(std::uint8_t tools) {
        return (!(kTools & kCuttingTools) || (tools & kCuttingTools)) &&
               (!(kTools & kMarkingTools) || (tools & kMarkingTools));
    }
    // (marked closed before `ended` is called: it sees the builder as it is after the contour)
    template <class Ended>
    void close(Slot& s, Ended& ended) {
        s.kind = kNone;
        s.tools = 0;
        ended(s.contour);
    }

    Slot first_, second_;  // heads 1 and 2 (by name rather than an array: no index to scale on every motion)
    std::uint32_t next_motion_ = 0;
};

}  // namespace essi
