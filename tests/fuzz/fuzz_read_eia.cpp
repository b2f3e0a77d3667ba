// Fuzz target: EIA (RS-274) tapes through the whole pipeline (core/read/eia_reader.cpp -> interp -> check ->
// stats), with the three EIA tables of the built-in profiles (woyda's, din66025's, hypertherm's). Built as
// essi_fuzz_read_eia (libFuzzer, `make fuzz`, dictionary read_eia.dict) and essi_fuzz_replay_read_eia (ctest
// `fuzz_replay_read_eia`, every file of tests/fuzz/corpus/read_eia), as the other targets. The contract checked
// is the one of every reader (check_contract.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "check_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    for (const char* profile : {"woyda", "din66025", "hypertherm"})
        essi_fuzz::check_one(bytes, profile, essi::InputFormat::Eia);
    return 0;
}
