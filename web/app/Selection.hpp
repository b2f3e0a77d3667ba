// The selected source line and motion (a click on a segment, a source line or a diagnostic).
#pragma once

#include <cstddef>
#include <cstdint>

namespace essi::viewer {

struct Selection {
    static constexpr std::size_t npos = ~std::size_t(0);
    std::uint32_t line = 0;      // 0: none
    std::size_t motion = npos;   // npos: none
    bool scroll_source = false;  // the source panel brings the line into view (once)

    void clear() {
        motion = npos;
        line = 0;
    }
};

}  // namespace essi::viewer
