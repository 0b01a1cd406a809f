// SHA-256 through OpenSSL's EVP digest interface (the library does the hashing).
#include "bipc/ir/detail/sha256.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace smcbip::bipc::ir::detail {

namespace {

void require(bool ok, const char* what) {
  if (!ok) throw std::runtime_error(std::string("SHA-256 through OpenSSL: ") + what + " failed");
}

}  // namespace

Sha256::Sha256() : context_(EVP_MD_CTX_new()) {
  require(context_ != nullptr, "EVP_MD_CTX_new");
  if (EVP_DigestInit_ex(context_, EVP_sha256(), nullptr) != 1) {
    EVP_MD_CTX_free(context_);
    require(false, "EVP_DigestInit_ex");
  }
}

Sha256::~Sha256() { EVP_MD_CTX_free(context_); }

void Sha256::update(std::span<const std::uint8_t> bytes) {
  require(!finished_, "an update after the digest");
  require(EVP_DigestUpdate(context_, bytes.data(), bytes.size()) == 1, "EVP_DigestUpdate");
}

void Sha256::update(std::string_view bytes) {
  update(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

std::string Sha256::hex_digest() {
  require(!finished_, "a second digest");
  finished_ = true;
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  require(EVP_DigestFinal_ex(context_, digest, &size) == 1 && size == 32, "EVP_DigestFinal_ex");
  static const char* const kHex = "0123456789abcdef";
  std::string hex;
  hex.reserve(2 * size);
  for (unsigned int i = 0; i < size; ++i) {
    hex += kHex[digest[i] >> 4];
    hex += kHex[digest[i] & 0xF];
  }
  return hex;
}

}  // namespace smcbip::bipc::ir::detail
