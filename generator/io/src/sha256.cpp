// SPDX-License-Identifier: Apache-2.0
#include "ctab/io/sha256.hpp"

#include <array>
#include <cstdint>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__)
#include <cpuid.h>
#include <immintrin.h>
#define CTAB_SHA256_X86 1
#endif

namespace ctab::gen {

namespace {

using State = std::array<std::uint32_t, 8>;

// FIPS 180-4, 4.2.2 and 5.3.3.
alignas(16) constexpr std::array<std::uint32_t, 64> kRoundConstants = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};
constexpr State kInitialState = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};

constexpr std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

std::uint32_t big_endian_word(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

// The compression function (6.2.2) over `blocks` consecutive 64-byte blocks.
void compress_portable(State& h, const unsigned char* data, std::size_t blocks) {
  for (std::size_t block = 0; block < blocks; ++block, data += 64) {
    std::array<std::uint32_t, 64> w;
    for (std::size_t t = 0; t < 16; ++t) w[t] = big_endian_word(data + 4 * t);
    for (std::size_t t = 16; t < 64; ++t) {
      const std::uint32_t s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
      const std::uint32_t s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
      w[t] = w[t - 16] + s0 + w[t - 7] + s1;
    }
    auto [a, b, c, d, e, f, g, hh] = h;
    for (std::size_t t = 0; t < 64; ++t) {
      const std::uint32_t s1 = rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25);
      const std::uint32_t choice = (e & f) ^ (~e & g);
      const std::uint32_t t1 = hh + s1 + choice + kRoundConstants[t] + w[t];
      const std::uint32_t s0 = rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22);
      const std::uint32_t majority = (a & b) ^ (a & c) ^ (b & c);
      const std::uint32_t t2 = s0 + majority;
      hh = g;
      g = f;
      f = e;
      e = d + t1;
      d = c;
      c = b;
      b = a;
      a = t1 + t2;
    }
    const State add = {a, b, c, d, e, f, g, hh};
    for (std::size_t i = 0; i < 8; ++i) h[i] += add[i];
  }
}

#ifdef CTAB_SHA256_X86
// The same compression with the x86 SHA extensions (SHA256RNDS2: two rounds on the state held as ABEF and CDGH;
// SHA256MSG1/MSG2: the message schedule's sigma0 and sigma1 terms, four words at a time).
__attribute__((target("sha,sse4.1"))) void compress_sha_extensions(State& h, const unsigned char* data,
                                                                   std::size_t blocks) {
  const __m128i byte_swap = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);  // big-endian words
  // h[0..3] = a b c d, h[4..7] = e f g h (dword 0 first) -> abef = (f e b a), cdgh = (h g d c) from dword 0 up.
  const __m128i abcd = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(h.data())), 0xB1);
  const __m128i efgh = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(h.data() + 4)), 0x1B);
  __m128i abef = _mm_alignr_epi8(abcd, efgh, 8);
  __m128i cdgh = _mm_blend_epi16(efgh, abcd, 0xF0);
  for (std::size_t block = 0; block < blocks; ++block, data += 64) {
    const __m128i abef_before = abef, cdgh_before = cdgh;
    __m128i w[4];
    for (int i = 0; i < 4; ++i)
      w[i] = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(data + 16 * i)), byte_swap);
    for (int group = 0; group < 16; ++group) {  // rounds 4 group ... 4 group + 3
      __m128i& words = w[group % 4];            // W[4 group - 16 ...] before, W[4 group ...] after
      if (group >= 4) {
        const __m128i& next = w[(group + 1) % 4];   // W[4 group - 12 ...]
        const __m128i& older = w[(group + 2) % 4];  // W[4 group - 8 ...]
        const __m128i& last = w[(group + 3) % 4];   // W[4 group - 4 ...]
        const __m128i partial = _mm_add_epi32(_mm_sha256msg1_epu32(words, next), _mm_alignr_epi8(last, older, 4));
        words = _mm_sha256msg2_epu32(partial, last);
      }
      __m128i message =
          _mm_add_epi32(words, _mm_load_si128(reinterpret_cast<const __m128i*>(kRoundConstants.data() + 4 * group)));
      cdgh = _mm_sha256rnds2_epu32(cdgh, abef, message);  // two rounds: cdgh now holds the new abef
      message = _mm_shuffle_epi32(message, 0x0E);
      abef = _mm_sha256rnds2_epu32(abef, cdgh, message);  // two more: abef and cdgh as they were named
    }
    abef = _mm_add_epi32(abef, abef_before);
    cdgh = _mm_add_epi32(cdgh, cdgh_before);
  }
  const __m128i feba = _mm_shuffle_epi32(abef, 0x1B);  // (a b e f)
  const __m128i dchg = _mm_shuffle_epi32(cdgh, 0xB1);  // (g h c d)
  _mm_storeu_si128(reinterpret_cast<__m128i*>(h.data()), _mm_blend_epi16(feba, dchg, 0xF0));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(h.data() + 4), _mm_alignr_epi8(dchg, feba, 8));
}
#endif

using Compress = void (*)(State&, const unsigned char*, std::size_t);

std::string digest(const void* data, std::size_t size, Compress compress) {
  State h = kInitialState;
  const auto* bytes = static_cast<const unsigned char*>(data);
  const std::size_t full_blocks = size / 64;
  compress(h, bytes, full_blocks);
  // The tail, 0x80, zeros and the bit length (5.1.1): one or two final blocks.
  std::array<unsigned char, 128> tail{};
  const std::size_t rest = size - 64 * full_blocks;
  if (rest > 0) std::memcpy(tail.data(), bytes + 64 * full_blocks, rest);
  tail[rest] = 0x80;
  const std::size_t tail_blocks = rest < 56 ? 1 : 2;
  const std::uint64_t bit_length = static_cast<std::uint64_t>(size) * 8;
  for (std::size_t i = 0; i < 8; ++i)
    tail[64 * tail_blocks - 1 - i] = static_cast<unsigned char>(bit_length >> (8 * i));
  compress(h, tail.data(), tail_blocks);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(64);
  for (const std::uint32_t word : h)
    for (int shift = 28; shift >= 0; shift -= 4) out += kHex[(word >> shift) & 0xf];
  return out;
}

}  // namespace

bool sha256_has_cpu_extensions() noexcept {
#ifdef CTAB_SHA256_X86
  // CPUID directly: clang 14's __builtin_cpu_supports knows no "sha" (leaf 7 EBX bit 29; SSE4.1: leaf 1 ECX bit 19).
  static const bool available = [] {
    unsigned a = 0, b = 0, c = 0, d = 0;
    const bool sse41 = __get_cpuid(1, &a, &b, &c, &d) != 0 && (c & bit_SSE4_1) != 0;
    return sse41 && __get_cpuid_count(7, 0, &a, &b, &c, &d) != 0 && (b & bit_SHA) != 0;
  }();
  return available;
#else
  return false;
#endif
}

std::string sha256_hex(const void* data, std::size_t size) {
#ifdef CTAB_SHA256_X86
  if (sha256_has_cpu_extensions()) return digest(data, size, compress_sha_extensions);
#endif
  return digest(data, size, compress_portable);
}

std::string sha256_hex_portable(const void* data, std::size_t size) { return digest(data, size, compress_portable); }

}  // namespace ctab::gen
