#include "app/panels/Panels.hpp"

namespace essi::viewer::panels {

void Panels::draw() {
    toolbar();
    tape_panel();
    source_panel();
    overlays();
    messages();
    if (p_.ui.help) help();
}

}  // namespace essi::viewer::panels
