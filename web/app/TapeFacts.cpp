#include "app/TapeFacts.hpp"

#include "essi/interp.hpp"

namespace essi::viewer {

const PartsList* TapeFacts::parts() const {
    return parts_.get(load_, [](const Document& d) { return tape_parts(d.bytes, d.profile, d.setup.format); });
}

const PartsList* TapeFacts::parts_made() const { return parts_.made(load_); }

const std::vector<PlannedMotion>* TapeFacts::planned() const {
    return planned_.get(load_, [](const Document& d) { return planned_motions(d.bytes, d.profile, d.setup.format); });
}

const MotionTimes* TapeFacts::motion_times() const {
    return motion_times_.get(
        load_, [](const Document& d) { return MotionTimes(motion_seconds(d.bytes, d.profile, d.setup.format)); });
}

}  // namespace essi::viewer
