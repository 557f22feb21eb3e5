#pragma once
// SHA-256 (Nettle) of a text: what identifies the exact input of a result (the
// result file's case_sha256) and of a sweep's run (its hash, for resuming).
#include <string>

namespace heavesim {

/// The SHA-256 digest of `message` as 64 lower-case hexadecimal digits.
std::string sha256_hex(const std::string& message);

}  // namespace heavesim
