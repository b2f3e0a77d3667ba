#include "app/TapeFacts.hpp"

#include "essi/interp.hpp"

namespace essi::viewer {

const PartsList* TapeFacts::parts() const {
    const Document* d = load_.document();
    if (!d) return nullptr;
    if (parts_.made_for != load_.documents_read()) {
        parts_.value = tape_parts(d->bytes, d->profile, d->setup.format);
        parts_.made_for = load_.documents_read();
    }
    return &parts_.value;
}

const PartsList* TapeFacts::parts_made() const {
    return load_.document() && parts_.made_for == load_.documents_read() ? &parts_.value : nullptr;
}

const std::vector<PlannedMotion>* TapeFacts::planned() const {
    const Document* d = load_.document();
    if (!d) return nullptr;
    if (planned_.made_for != load_.documents_read()) {
        planned_.value = planned_motions(d->bytes, d->profile, d->setup.format);
        planned_.made_for = load_.documents_read();
    }
    return &planned_.value;
}

}  // namespace essi::viewer
