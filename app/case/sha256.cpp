#include "app/case/sha256.hpp"

#include <nettle/sha2.h>

#include <cstdint>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace heavesim {

std::string sha256_hex(const std::string& message) {
  // Nettle's SHA-256 (FIPS 180-4): a plain function, no provider set-up. OpenSSL's EVP
  // digest, used before, loaded libcrypto (~21,000 relocations: a program linked against it
  // alone starts in 5.4 ms against 2.5 ms) and set up its providers at the first digest
  // (~2 ms; docs/performance.md, "Issue #18, seventeenth round").
  sha256_ctx context;
  sha256_init(&context);
  sha256_update(&context, message.size(), reinterpret_cast<const std::uint8_t*>(message.data()));
  std::uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&context, SHA256_DIGEST_SIZE, digest);
  return fmt::format("{:02x}", fmt::join(digest, ""));
}

}  // namespace heavesim
