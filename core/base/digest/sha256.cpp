// What the SHA-256 implementations share (essi/sha256.hpp): the digest as hex digits.
#include "essi/sha256.hpp"

namespace essi {

std::string sha256_hex(std::string_view bytes) {
    static constexpr char kHex[] = "0123456789abcdef";
    const std::array<unsigned char, 32> digest = sha256(bytes);
    std::string out;
    out.reserve(2 * digest.size());
    for (const unsigned char b : digest) {
        out += kHex[b >> 4];
        out += kHex[b & 15];
    }
    return out;
}

}  // namespace essi
