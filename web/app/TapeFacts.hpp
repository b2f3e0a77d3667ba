// What the viewer works out from the open tape beyond its check, when first asked: its parts and plates
// (essi/parts.hpp, what `essi parts` lists: the Job panel, the job sheet, the parts layer, colour by part group),
// the machine-time planner's motions (essi/machine_time.hpp: colour by speed) and the seconds of each motion
// (essi::motion_seconds: the playback). Each is made by the core reading the tape's bytes again, and kept until
// another tape is read.
#pragma once

#include <cstdint>
#include <vector>

#include "app/ColourBy.hpp"
#include "app/LoadController.hpp"
#include "app/Playback.hpp"
#include "essi/machine_time.hpp"
#include "essi/parts.hpp"

namespace essi::viewer {

class TapeFacts final : public ColourSources, public MotionTimesSource {
public:
    explicit TapeFacts(const LoadController& load) : load_(load) {}

    // The open tape's parts list; null while no tape is open.
    [[nodiscard]] const PartsList* parts() const override;
    // The same when it has been made for the open tape already, else null (makes nothing: the Job panel and
    // state() show the parts once something asked for them, and never read a big tape again by themselves).
    [[nodiscard]] const PartsList* parts_made() const;
    // The open tape's planned motions (empty without the profile's accel_mm_s2); null while no tape is open.
    [[nodiscard]] const std::vector<PlannedMotion>* planned() const override;
    // The open tape's motion times (the playback's clock); null while no tape is open.
    [[nodiscard]] const MotionTimes* motion_times() const override;

private:
    // A value kept for the tape it was made for.
    template <class T>
    struct Kept {
        std::uint64_t made_for = 0;  // LoadController::documents_read() when it was made (0: never)
        T value;
        // The value for the open tape (made by make(document) unless it was made for it); null without a tape.
        template <class Make>
        const T* get(const LoadController& load, Make make) {
            const Document* d = load.document();
            if (!d) return nullptr;
            if (made_for != load.documents_read()) {
                value = make(*d);
                made_for = load.documents_read();
            }
            return &value;
        }
        // The same when made for the open tape already, else null.
        [[nodiscard]] const T* made(const LoadController& load) const {
            return load.document() && made_for == load.documents_read() ? &value : nullptr;
        }
    };
    const LoadController& load_;
    mutable Kept<PartsList> parts_;
    mutable Kept<std::vector<PlannedMotion>> planned_;
    mutable Kept<MotionTimes> motion_times_;
};

}  // namespace essi::viewer
