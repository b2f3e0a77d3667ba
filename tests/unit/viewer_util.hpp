// The viewer's document of a tape, loaded to the end in one go (the tests of web/app and web/render).
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "app/Document.hpp"
#include "app/DocumentLoader.hpp"
#include "essi/profile.hpp"

namespace essi_test {

// An ESSI tape read with `profile` (default: iso6582), as the viewer's DocumentLoader loads it.
inline std::unique_ptr<essi::viewer::Document> load_document(
    const std::string& bytes, const essi::Profile& profile = *essi::builtin_profile("iso6582")) {
    essi::TapeSetup setup;
    setup.profile = profile;
    essi::viewer::DocumentLoader loader("tape", bytes, std::move(setup));
    while (!loader.step(1e9)) {
    }
    return loader.take();
}

}  // namespace essi_test
