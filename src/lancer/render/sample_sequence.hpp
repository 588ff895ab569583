// The random numbers of one sample of one pixel: the first two dimensions of Sobol' sequence, Owen
// scrambled and index shuffled per pixel and per pair of dimensions by a hash of both (Burley,
// "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020). Each pair of dimensions is a (0, 2)
// sequence over the pixel's samples, so any prefix of 2^k samples is stratified; the pairs are
// decorrelated by their seeds. Nothing is shared between pixels: the values depend only on the
// pixel, the sample index and the dimension, so the image has the same bytes for any thread count,
// MPI rank count or job-array split.
#pragma once

#include <cstdint>

#include "lancer/render/pixel_sampler.hpp"

namespace lancer {

namespace sobol {

inline std::uint32_t reverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// Laine & Karras' hash: a random permutation of the bit-reversed value that only mixes lower
// bits into higher ones, i.e. a nested uniform (Owen) scramble of the reversed bits.
inline std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

inline std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
  return reverseBits(laineKarras(reverseBits(x), seed));
}

// Sobol' dimension 1 of the index bits 8b..8b+7 (direction numbers v_i = v_{i-1} ^ v_{i-1} >> 1,
// v_0 = 2^31): the XOR of the v_i of the set bits, for every byte value. The index is Owen scrambled
// first, so all 32 of its bits are in play: four lookups rather than a loop over 32 bits.
struct SobolByteTables {
  std::uint32_t y[4][256];
  constexpr SobolByteTables() : y{} {
    std::uint32_t v[32] = {};
    v[0] = 0x80000000u;
    for (int i = 1; i < 32; ++i) v[i] = v[i - 1] ^ (v[i - 1] >> 1);
    for (int b = 0; b < 4; ++b)
      for (std::uint32_t value = 0; value < 256; ++value) {
        std::uint32_t sum = 0;
        for (int bit = 0; bit < 8; ++bit)
          if (value >> bit & 1u) sum ^= v[8 * b + bit];
        y[b][value] = sum;
      }
  }
};
inline constexpr SobolByteTables kSobolByteTables{};

// Sobol' dimension 0 (van der Corput) and dimension 1.
inline void sobol2d(std::uint32_t index, std::uint32_t& x, std::uint32_t& y) {
  x = reverseBits(index);
  const auto& t = kSobolByteTables.y;
  y = t[0][index & 0xFFu] ^ t[1][index >> 8 & 0xFFu] ^ t[2][index >> 16 & 0xFFu] ^ t[3][index >> 24];
}

inline float toUnitFloat(std::uint32_t bits) {
  return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);  // [0, 1), 24 bits
}

}  // namespace sobol

// The stream of one sample of one pixel; each call takes the next pair of dimensions.
class SampleStream {
 public:
  SampleStream(int x, int y, std::uint32_t sampleIndex)
      : pixelSeed_(hashBits(static_cast<std::uint32_t>(x) * 0x9E3779B1u ^
                            hashBits(static_cast<std::uint32_t>(y) + 0x632BE5ABu))),
        index_(sampleIndex) {}

  // Two values in [0, 1)^2.
  void next2D(float& u, float& v) {
    const std::uint32_t seed = hashBits(pixelSeed_ ^ hashBits(dimension_++ * 0x85EBCA77u + 1u));
    std::uint32_t x, y;
    sobol::sobol2d(sobol::owenScramble(index_, seed), x, y);
    u = sobol::toUnitFloat(sobol::owenScramble(x, hashBits(seed ^ 0x68E31DA4u)));
    v = sobol::toUnitFloat(sobol::owenScramble(y, hashBits(seed ^ 0xB5297A4Du)));
  }
  float next1D() {
    float u, v;
    next2D(u, v);
    return u;
  }

 private:
  std::uint32_t pixelSeed_;
  std::uint32_t index_;
  std::uint32_t dimension_ = 0;
};

}  // namespace lancer
