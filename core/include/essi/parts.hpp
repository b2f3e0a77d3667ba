// Parts and plates (docs/semantics.md §9, "Parts and plates"): what a tape makes, from the cut plan's contours
// (essi/plan.hpp). A part is a contour of the role part or lone-part with the holes that lie in it directly; parts of
// the same shape (equal under translation and rotation, within the same-shape tolerance) form a group, a mirrored
// copy another group that names its twin. Each plate of the plan gets its utilisation and its remnant.
//
// Bounds (docs/hostile-input.md): the parts come from the plan's contours, so a plate's parts are bounded by the
// plan's caps; a part is compared with at most kPartsMaxCompares earlier groups of its signature, each in at most
// kPartsMaxAlignments alignments; the shapes kept to compare with hold at most kPartsMaxKeptPieces pieces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "essi/geom.hpp"
#include "essi/motion.hpp"
#include "essi/plan.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"

namespace essi {

// Two parts are the same shape when every point of one, turned and moved onto the other, lies this close to the
// other's (mm), or within kPartsSameShapeUnits unit increments of the tape when that is coarser: a copy turned by an
// odd angle has its points rounded to the unit, each by up to 0.71 unit, so the points of two such copies differ by
// up to 1.42 units, and a little more once the turn between them is fitted.
constexpr double kPartsSameShapeMm = 0.01;
constexpr double kPartsSameShapeUnits = 2;
// A part is compared exactly with at most this many earlier groups whose signature it shares (area, perimeter,
// pieces, their lengths, its holes' places); past that it makes a group of its own.
constexpr std::size_t kPartsMaxCompares = 32;
// A part's search for its group visits at most this many earlier groups of its number of loops and pieces, its area
// and its perimeter (within the same-shape tolerance), similar or not; past that it makes a group of its own.
constexpr std::size_t kPartsMaxVisits = 4096;
// A comparison tries at most this many alignments (the features of the other part as far from its centroid as the
// farthest of this one's).
constexpr std::size_t kPartsMaxAlignments = 64;
// The groups' shapes, kept to compare later parts with, hold at most this many pieces together; a new shape past
// that is a group that no later part joins.
constexpr std::size_t kPartsMaxKeptPieces = std::size_t{1} << 20;
// The outline's smallest enclosing rectangle: its direction is sought by the edges of the hull of its arcs followed
// within kPartsOutlineCoarseMm, among the directions of its arcs' chords within kPartsOutlineToleranceMm; its size in
// the direction found is exact.
constexpr double kPartsOutlineCoarseMm = 0.2;
constexpr double kPartsOutlineToleranceMm = 0.001;
// The remnant is found over at most this many horizontal slabs of the plate's part outlines, and within this many
// steps (an outline's edge over a slab); past that over the parts' boxes.
constexpr std::size_t kPartsMaxRemnantSlabs = std::size_t{1} << 16;
constexpr std::size_t kPartsMaxRemnantSteps = std::size_t{1} << 24;

// One of a part's cuts: its source lines.
struct PartCut {
    std::uint32_t first_line = 0, last_line = 0;
};

struct Part {
    unsigned group = 0;  // its group's number (1, 2, ...)
    int plate = 1;
    std::vector<PartCut> cuts;  // its outline, then its holes (in the order they are cut)
    Box box;                    // its outline's exact box
    Point label_at;             // a point of the part's material, for its number on a drawing
    double cut_length_mm = 0;   // its cuts' programmed length, pierce to torch off (lead-ins and -outs included)
    double turned_deg = 0;      // how far it is turned from its group's first part, counter-clockwise (-180, 180]
};

struct PartGroup {
    unsigned number = 0;  // 1, 2, ...: in the order their first parts are cut
    unsigned count = 0;
    double net_area_mm2 = 0;             // the outline's area less its holes' (arcs and parabolas exact)
    double length_mm = 0, width_mm = 0;  // the outline's smallest enclosing rectangle, length >= width
    double cut_length_mm = 0;            // per part: the mean of its parts' cut lengths
    unsigned holes = 0;
    unsigned pierces = 0;              // per part: its cuts (the outline's and each hole's)
    std::optional<double> mass_kg;     // net area x the profile's material thickness and density
    unsigned mirror_of = 0;            // the group of its mirror image (0: none, or the part is its own mirror image)
    std::vector<std::uint32_t> parts;  // its parts (indices in PartsList::parts), in cutting order
};

struct PlateUse {
    int plate = 1;
    Box area;                   // the plate: profile plate_mm from the program's origin, else the parts' box
    bool from_profile = false;  // `area` is plate_mm's
    unsigned parts = 0;
    double net_area_mm2 = 0;         // its parts' net areas
    double utilisation = 0;          // net_area_mm2 / the plate's area
    std::optional<double> scrap_kg;  // (plate area - net area) x thickness x density, with the profile's material
    std::optional<Box> remnant;      // the largest rectangle at the plate's far end in x clear of every part and kerf
};

struct PartsList {
    std::vector<Part> parts;  // in cutting order (by their outlines)
    std::vector<PartGroup> groups;
    std::vector<PlateUse> plates;  // the plates that hold parts
};

// The parts of the plan's contours (CutPlan::contours(), plan_contours), their motions read back from `store`
// (contours listed plate by plate).
[[nodiscard]] PartsList find_parts(const std::vector<PlanContour>& contours, const MotionStore& store,
                                   const Profile& profile);

// The parts list made from the cut plan's plates as they are analysed (CutPlan::keep_plate_motions), in the pass
// that checks the tape (TapeChecker::find_parts): each plate's parts are made, grouped with the earlier plates',
// and its utilisation and remnant found when the plan hands it on; what is kept between plates is the list itself
// and the groups' shapes (kPartsMaxKeptPieces).
class PartsBuilder;
class PartsFinder final : public PlateContoursSink {
public:
    explicit PartsFinder(const Profile& profile);
    ~PartsFinder() override;
    PartsFinder(const PartsFinder&) = delete;
    PartsFinder& operator=(const PartsFinder&) = delete;
    void on_plate(const PlateContours& plate) override;
    // After the plan's finish(): the list. Call once.
    [[nodiscard]] PartsList finish();

private:
    std::unique_ptr<PartsBuilder> builder_;
};

// The parts of a tape: reads and interprets it once, through the cut plan (without the rest of the check).
[[nodiscard]] PartsList tape_parts(std::string_view bytes, const Profile& profile,
                                   InputFormat format = InputFormat::Essi);

}  // namespace essi
