// Where the test data lives, in both runtimes.
//
//   native: the source tree, given by compile definitions from tests/CMakeLists.txt
//           (ESSI_EXAMPLES_DIR = <repo>/examples, ESSI_TEST_DATA_DIR = <repo>/tests/data,
//           ESSI_CORPUS_DIR = <repo>/../shared/corpus/essiconv).
//   wasm:   the same folders preloaded into the Emscripten file system (--preload-file): examples/ at /examples,
//           tests/data/ at /test_data, ../shared/corpus/essiconv at /corpus (only when it existed at configure).
//
// This header is where tests/ chooses its data folders by runtime; elsewhere `__EMSCRIPTEN__` only selects what
// cannot run under node (threads, files written to disk, timers of the benchmarks).
#pragma once

#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>

#if !defined(__EMSCRIPTEN__) && \
    (!defined(ESSI_EXAMPLES_DIR) || !defined(ESSI_TEST_DATA_DIR) || !defined(ESSI_CORPUS_DIR))
#error "ESSI_EXAMPLES_DIR / ESSI_TEST_DATA_DIR / ESSI_CORPUS_DIR must be defined (tests/CMakeLists.txt does it)"
#endif

namespace essi_test_detail {
inline bool is_dir(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}
}  // namespace essi_test_detail

// The repository's examples/ folder (no trailing slash).
inline std::string examples_dir() {
#ifdef __EMSCRIPTEN__
    return "/examples";
#else
    return ESSI_EXAMPLES_DIR;
#endif
}

// The repository's tests/data/ folder: inputs with their results worked out by hand (no trailing slash).
inline std::string test_data_dir() {
#ifdef __EMSCRIPTEN__
    return "/test_data";
#else
    return ESSI_TEST_DATA_DIR;
#endif
}

// The real tapes of ../shared/corpus/essiconv, or nullopt when they are not there (tests then GTEST_SKIP()).
inline std::optional<std::string> corpus_dir() {
#ifdef __EMSCRIPTEN__
    const std::string dir = "/corpus";
#else
    const std::string dir = ESSI_CORPUS_DIR;
#endif
    if (!essi_test_detail::is_dir(dir)) return std::nullopt;
    return dir;
}

// The whole file as bytes (binary mode: CR, LF and NUL are kept). Throws std::runtime_error if unreadable.
inline std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
