// The case hash (app/case/sha256.cpp) against the published SHA-256 test vectors of FIPS
// 180-2, Appendix B (NIST, 2002), and the widely published digest of the empty message.
// The hash of a whole result's /case/yaml is checked against Python's hashlib by
// tests/scripts/test_report.py.
#include <gtest/gtest.h>

#include <string>

#include "app/case/sha256.hpp"

namespace heavesim {
namespace {

TEST(Sha256, PublishedTestVectors) {
  // B.1: one block.
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // B.2: two blocks (56 bytes: the padding needs a second block).
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // B.3: one million 'a'.
  EXPECT_EQ(sha256_hex(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, BytesAboveSevenBitsAndEmbeddedNulsAreHashedAsBytes) {
  // A case's text may hold UTF-8 (names, descriptions) and the hash covers every byte.
  // Reference: Python's hashlib.sha256(bytes([0, 0xc3, 0xa9, 0xff])).hexdigest().
  EXPECT_EQ(sha256_hex(std::string("\x00\xc3\xa9\xff", 4)),
            "8f0e7a2cd710cdc31d7cbb424a5ff3a126c4d3fcb64129a92ec70a21fb8dd817");
}

}  // namespace
}  // namespace heavesim
