// Where the samples of a pixel fall: the regular n x n sub-pixel grid, or a jittered
// (stratified) grid seeded per pixel so that images are identical for any thread count.
#pragma once

#include <cstdint>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// A small, high-quality integer hash (Jarkko Lempinen's / Chris Wellons' "lowbias32").
inline std::uint32_t hashBits(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// Uniform float in [0, 1) from a hash of (pixel, sample, dimension).
inline float sampleJitter(int x, int y, int sample, int dimension) {
  std::uint32_t h =
      hashBits(static_cast<std::uint32_t>(x) * 0x9E3779B1u ^ hashBits(static_cast<std::uint32_t>(y)));
  h = hashBits(h ^ static_cast<std::uint32_t>(sample * 2 + dimension) * 0x85EBCA77u);
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// Sub-pixel offset in [0,1)^2 of sample (i, j) of an n x n grid at pixel (x, y).
inline void gridSampleOffset(SamplerKind sampler, int n, int i, int j, int x, int y, float& dx, float& dy) {
  float jitterX = 0.5f, jitterY = 0.5f;
  if (sampler == SamplerKind::Stratified) {
    jitterX = sampleJitter(x, y, j * n + i, 0);
    jitterY = sampleJitter(x, y, j * n + i, 1);
  }
  dx = (static_cast<float>(i) + jitterX) / static_cast<float>(n);
  dy = (static_cast<float>(j) + jitterY) / static_cast<float>(n);
}

}  // namespace lancer
