// SPDX-License-Identifier: Apache-2.0
// SHA-256 known answers: the FIPS 180-4 examples (NIST CSRC "Examples with intermediate values" and the
// long-message vector) and the padding boundaries (55, 56, 63, 64, 65 bytes: one or two final blocks).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "ctab/io/sha256.hpp"

using ctab::gen::sha256_hex;

namespace {
std::string sha(const std::string& text) { return sha256_hex(text.data(), text.size()); }
}  // namespace

TEST(Sha256, Fips180Examples) {
  EXPECT_EQ(sha(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),  // 448 bits
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(
      sha("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrst"
          "nopqrstu"),  // 896 bits
      "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
}

TEST(Sha256, OneMillionA) {
  EXPECT_EQ(sha(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PaddingBoundaries) {
  EXPECT_EQ(sha(std::string(55, 'a')), "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  EXPECT_EQ(sha(std::string(56, 'a')), "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
  EXPECT_EQ(sha(std::string(63, 'a')), "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34");
  EXPECT_EQ(sha(std::string(64, 'a')), "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
  EXPECT_EQ(sha(std::string(65, 'a')), "635361c48bb9eab14198e76ea8ab7f1a41685d6ad62aa9146d301d4f17eb0ae0");
}

// The portable path against the same known answers, and the CPU's SHA-extension path (where this machine has it)
// against the portable one on every length 0..300 and on a table-sized buffer: every tail and block count.
TEST(Sha256, PortablePathKnownAnswers) {
  const std::string abc = "abc", million(1000000, 'a');
  EXPECT_EQ(ctab::gen::sha256_hex_portable(abc.data(), abc.size()),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(ctab::gen::sha256_hex_portable(million.data(), million.size()),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, CpuExtensionsGiveThePortableDigest) {
  if (!ctab::gen::sha256_has_cpu_extensions()) GTEST_SKIP() << "no SHA extensions on this CPU";
  std::string bytes(200000, '\0');
  std::uint32_t state = 12345;
  for (char& c : bytes) {
    state = state * 1664525u + 1013904223u;  // any fixed bytes will do
    c = static_cast<char>(state >> 24);
  }
  for (std::size_t size = 0; size <= 300; ++size)
    ASSERT_EQ(sha256_hex(bytes.data(), size), ctab::gen::sha256_hex_portable(bytes.data(), size)) << size << " bytes";
  EXPECT_EQ(sha256_hex(bytes.data(), bytes.size()), ctab::gen::sha256_hex_portable(bytes.data(), bytes.size()));
  EXPECT_EQ(sha256_hex(bytes.data() + 3, bytes.size() - 3),  // unaligned
            ctab::gen::sha256_hex_portable(bytes.data() + 3, bytes.size() - 3));
}
