// SHA-256 (FIPS 180-4) through OpenSSL's EVP interface (Debian libssl-dev): the content address of shared tapes and
// codeclimate's fingerprints. Under Emscripten (npm/: no OpenSSL) the same digest written out in sha256.cpp.
#pragma once

#include <string>
#include <string_view>

namespace essi::native {

// The digest of `bytes` as 64 lower-case hex digits.
[[nodiscard]] std::string sha256_hex(std::string_view bytes);

}  // namespace essi::native
