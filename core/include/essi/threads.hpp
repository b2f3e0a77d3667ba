// Whether this build can start threads: natively yes; under Emscripten only when built with pthreads (the viewer's
// reading worker essi_reader_mt, web/CMakeLists.txt), not in the page's program, the npm package's CLI or the
// unit tests under node, where everything runs on the calling thread.
#pragma once

namespace essi {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kHaveThreads = false;
#else
inline constexpr bool kHaveThreads = true;
#endif

}  // namespace essi
