// essi/sha256.hpp through OpenSSL's EVP interface (Debian libssl-dev): the native builds.
#include <memory>
#include <stdexcept>

#include <openssl/evp.h>

#include "essi/sha256.hpp"

namespace essi {

std::array<unsigned char, 32> sha256(std::string_view bytes) {
    std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
    std::array<unsigned char, 32> digest{};
    unsigned int len = 0;
    if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1 ||
        EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size()) != 1 ||
        EVP_DigestFinal_ex(ctx.get(), digest.data(), &len) != 1 || len != digest.size())
        throw std::runtime_error("SHA-256 failed (OpenSSL EVP)");
    return digest;
}

}  // namespace essi
