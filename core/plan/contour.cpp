// A contour's motions read back from the stream (essi/contour.hpp).
#include "essi/contour.hpp"

namespace essi {

std::vector<MotionRecord> contour_motions(const Contour& c, const MotionStore& store) {
    std::vector<MotionRecord> out;
    for (std::size_t k = c.first_motion; k < c.end_motion; ++k) {
        MotionRecord m = store.motion(k);
        if (of_contour(c, m)) out.push_back(std::move(m));
    }
    return out;
}

}  // namespace essi
