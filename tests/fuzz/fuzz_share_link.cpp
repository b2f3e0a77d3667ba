// Fuzz target: the share link decoder (essi/share_link.hpp), fed any bytes as a URL fragment. Built as
// essi_fuzz_share_link (libFuzzer, `make fuzz`) and essi_fuzz_replay_share_link (ctest `fuzz_replay_share_link`,
// every file of tests/fuzz/corpus/share_link), as the other targets.
//
// Checks besides "no crash": a view is finite with a zoom above 0; a store id is 64 lower-case hex digits; a name
// is at most a little over kMaxShareNameBytes; every problem has words; and the tape data of a link made from the
// decoded bytes reads back the same (base64url round trip).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "essi/share_link.hpp"

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_share_link: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view fragment(reinterpret_cast<const char*>(data), size);
    const essi::ShareLink link = essi::parse_share_fragment(fragment);
    if (link.view && !(std::isfinite(link.view->x) && std::isfinite(link.view->y) && link.view->zoom > 0 &&
                       std::isfinite(link.view->zoom)))
        fail("a view that is not finite or has no zoom");
    if (!link.store_id.empty() && link.store_id.size() != 64) fail("a store id that is not 64 hex digits");
    for (char c : link.store_id)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) fail("a store id with other characters");
    if (link.name.size() > essi::kMaxShareNameBytes + 3) fail("a name longer than the limit");
    for (const std::string& p : link.problems)
        if (p.size() < 4) fail("a problem without words");
    if (!link.packed.empty()) {
        const essi::ShareLink again = essi::parse_share_fragment("t=" + essi::base64url_encode(link.packed));
        if (again.packed != link.packed) fail("the tape data does not read back");
    }
    return 0;
}
