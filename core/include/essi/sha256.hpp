// SHA-256 (FIPS 180-4): the content address of shared tapes, codeclimate's fingerprints and the job sheet's digest
// of a tape. One implementation per platform (core/base/digest/), chosen by core/CMakeLists.txt: OpenSSL's EVP
// natively (Debian libssl-dev), the digest written out under Emscripten (no OpenSSL in WebAssembly).
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace essi {

// The digest of `bytes`.
[[nodiscard]] std::array<unsigned char, 32> sha256(std::string_view bytes);
// The digest of `bytes` as 64 lower-case hex digits.
[[nodiscard]] std::string sha256_hex(std::string_view bytes);

}  // namespace essi
