// SHA-256 (FIPS 180-4) through OpenSSL's EVP interface, fed in pieces.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

struct evp_md_ctx_st;  // OpenSSL's EVP_MD_CTX, so that this header needs no OpenSSL header

namespace smcbip::bipc::ir::detail {

/// An incremental SHA-256 digest. OpenSSL failing (out of memory, a provider refusing the
/// algorithm) throws std::runtime_error: the digest cannot be had another way.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  /// Appends bytes to the message; not after hex_digest.
  void update(std::span<const std::uint8_t> bytes);
  void update(std::string_view bytes);
  /// The digest of everything appended, as 64 lowercase hex digits; call it once.
  std::string hex_digest();

 private:
  evp_md_ctx_st* context_ = nullptr;
  bool finished_ = false;
};

}  // namespace smcbip::bipc::ir::detail
