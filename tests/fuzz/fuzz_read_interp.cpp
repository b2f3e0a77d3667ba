// Fuzz target: the whole pipeline (read -> interp -> check -> stats) through essi::check_tape, once with
// each built-in profile. Built two ways (tests/CMakeLists.txt):
//   essi_fuzz_read_interp         libFuzzer + ASan + UBSan (clang++-14, `make fuzz`, with read_interp.dict and
//                                 inputs up to 128 KB: the corpus holds whole generated tapes)
//   essi_fuzz_replay_read_interp  replay_main.cpp feeds it every file of tests/fuzz/corpus/read_interp (ctest
//                                 `fuzz_replay_read_interp`)
//
// Besides "does not crash, does not throw", it checks the contract of CheckResult (report.hpp) and aborts
// when it is broken, so both the fuzzer and the replay report it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "check_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    essi_fuzz::check_one(bytes, "iso6582");
    essi_fuzz::check_one(bytes, "woyda");
    return 0;
}
