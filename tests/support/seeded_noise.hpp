// Gaussian noise that is the same on every run and platform (Box-Muller on the renderer's per-pixel
// hash, unlike std::normal_distribution): the denoiser's tests and its benchmark add it to clean
// renders whose truth they know. Header-only so that bench/ can use it without GoogleTest.
#pragma once

#include <algorithm>
#include <cmath>

#include "lancer/image/image.hpp"
#include "lancer/render/pixel_sampler.hpp"

namespace lancer::test {

// A standard normal deviate for one pixel and channel.
inline float seededGaussian(int x, int y, int channel) {
  const float u1 = std::max(sampleJitter(x, y, channel, 0), 1e-7f), u2 = sampleJitter(x, y, channel, 1);
  return std::sqrt(-2.0f * std::log(u1)) * std::cos(6.2831853f * u2);
}

// `clean` plus noise of deviation `sigma` in every channel.
inline Image withSeededNoise(const Image& clean, float sigma) {
  Image noisy = clean;
  for (int y = 0; y < clean.height(); ++y)
    for (int x = 0; x < clean.width(); ++x) {
      Rgba& p = noisy.at(x, y);
      p.r += sigma * seededGaussian(x, y, 0);
      p.g += sigma * seededGaussian(x, y, 1);
      p.b += sigma * seededGaussian(x, y, 2);
    }
  return noisy;
}

}  // namespace lancer::test
