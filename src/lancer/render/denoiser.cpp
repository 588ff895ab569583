#include "lancer/render/denoiser.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// Below this an albedo channel is not divided out (black paint, a black background).
constexpr float kMinAlbedo = 0.01f;
// The B3-spline taps of the à-trous transform (Dammertz et al., section 3).
constexpr float kKernel[5] = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};

// The guide of one pixel, ready for the weights.
struct Guide {
  Vec3 normal;  // unit, or zero where the pixel saw nothing
  Vec3 albedo;
  float depth;      // +infinity where nothing was hit
  float gradientX;  // |d depth / dx|, |d depth / dy| in world units per pixel (0 on a miss)
  float gradientY;
};

std::vector<Guide> makeGuides(const FeatureBuffers& f) {
  std::vector<Guide> guides(f.albedo.size());
  const auto depthAt = [&](int x, int y) { return f.depth[f.index(x, y)]; };
  // One-sided where a neighbour is missing or off the image: the slope of the surface itself.
  const auto slope = [](float before, float here, float after) {
    const bool b = std::isfinite(before), a = std::isfinite(after);
    if (a && b)
      return 0.5f * std::min(std::abs(after - here) + std::abs(here - before),
                             2.0f * std::min(std::abs(after - here), std::abs(here - before)));
    if (a) return std::abs(after - here);
    if (b) return std::abs(here - before);
    return 0.0f;
  };
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const std::size_t k = f.index(x, y);
      Guide& g = guides[k];
      const float n = length(f.normal[k]);
      g.normal = n > 1e-6f ? f.normal[k] * (1.0f / n) : Vec3{0, 0, 0};
      g.albedo = f.albedo[k];
      g.depth = f.depth[k];
      g.gradientX = g.gradientY = 0;
      if (!std::isfinite(g.depth)) continue;
      g.gradientX =
          slope(x > 0 ? depthAt(x - 1, y) : kInf, g.depth, x + 1 < f.width ? depthAt(x + 1, y) : kInf);
      g.gradientY =
          slope(y > 0 ? depthAt(x, y - 1) : kInf, g.depth, y + 1 < f.height ? depthAt(x, y + 1) : kInf);
    }
  return guides;
}

// The weight the features give tap q of centre p at pixel offset (dx, dy): SVGF's w_n and w_z, and a
// Gaussian in albedo. Returns the factor outside the exponential (w_n, or 0 across a silhouette
// against the background) and adds the exponents of the others to `exponent`, so that a tap takes
// one exp.
float featureWeight(const Guide& p, const Guide& q, int dx, int dy, const DenoiseOptions& options,
                    float& exponent) {
  const bool pHit = std::isfinite(p.depth), qHit = std::isfinite(q.depth);
  if (pHit != qHit) return 0.0f;
  const Vec3 da = p.albedo - q.albedo;
  exponent += dot(da, da) / (options.albedoSigma * options.albedoSigma);
  if (!pHit) return 1.0f;
  float cosine = std::max(0.0f, dot(p.normal, q.normal));
  float w = cosine;
  // cosine^128 by squaring (the default power); other powers use pow.
  if (options.normalPower == 128.0f) {
    for (int i = 0; i < 7; ++i) w *= w;
  } else {
    w = std::pow(cosine, options.normalPower);
  }
  const float expected = options.depthSigma * (p.gradientX * static_cast<float>(std::abs(dx)) +
                                               p.gradientY * static_cast<float>(std::abs(dy))) +
                         1e-4f * p.depth;
  exponent += std::abs(p.depth - q.depth) / expected;
  return w;
}

// Pixels whose 2x2 block lies on one smooth surface: there the diagonal detail is noise alone.
bool smoothBlock(const Guide* g[4]) {
  for (int i = 1; i < 4; ++i) {
    if (std::isfinite(g[0]->depth) != std::isfinite(g[i]->depth)) return false;
    const Vec3 da = g[0]->albedo - g[i]->albedo;
    if (dot(da, da) > 1e-4f) return false;
    if (std::isfinite(g[0]->depth) && dot(g[0]->normal, g[i]->normal) < 0.99f) return false;
  }
  return true;
}

float estimateNoiseOf(const std::vector<Vec3>& light, const std::vector<Guide>& guides, int width,
                      int height) {
  std::vector<float> details;
  details.reserve(light.size());
  const auto at = [&](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x;
  };
  for (int y = 0; y + 1 < height; y += 2)
    for (int x = 0; x + 1 < width; x += 2) {
      const std::size_t k[4] = {at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y + 1)};
      const Guide* g[4] = {&guides[k[0]], &guides[k[1]], &guides[k[2]], &guides[k[3]]};
      if (!smoothBlock(g)) continue;
      // The finest diagonal Haar detail of each channel: a smooth gradient cancels, pixel noise of
      // deviation s leaves a detail of deviation s.
      const Vec3 d = (light[k[0]] - light[k[1]] - light[k[2]] + light[k[3]]) * 0.5f;
      // A block of exactly equal pixels has no noise to measure (the background, a floor the shadow
      // catcher sees unshadowed): where such blocks are most of the picture, counting them would put
      // the median at 0 and leave the rendered part as noisy as it came.
      if (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f) continue;
      details.insert(details.end(), {std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    }
  if (details.empty()) return 0.0f;
  const auto middle = details.begin() + static_cast<std::ptrdiff_t>(details.size() / 2);
  std::nth_element(details.begin(), middle, details.end());
  return *middle / 0.6745f;  // the median absolute deviation of a normal distribution
}

// Demodulated radiance and the albedo it was divided by (1 where the albedo is too dark).
void demodulate(const Image& image, const FeatureBuffers& f, std::vector<Vec3>& light,
                std::vector<Vec3>& divisor) {
  light.resize(f.albedo.size());
  divisor.resize(f.albedo.size());
  const auto safe = [](float a) { return a > kMinAlbedo ? a : 1.0f; };
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const std::size_t k = f.index(x, y);
      const Vec3& a = f.albedo[k];
      divisor[k] = {safe(a.x), safe(a.y), safe(a.z)};
      const Rgba& c = image.at(x, y);
      light[k] = {c.r / divisor[k].x, c.g / divisor[k].y, c.b / divisor[k].z};
    }
}

}  // namespace

float estimateNoise(const Image& image, const FeatureBuffers& features) {
  std::vector<Vec3> light;
  light.reserve(features.albedo.size());
  for (const Rgba& p : image.pixels()) light.push_back(p.rgb());
  return estimateNoiseOf(light, makeGuides(features), features.width, features.height);
}

Image denoise(const Image& noisy, const FeatureBuffers& features, const DenoiseOptions& options) {
  if (features.width != noisy.width() || features.height != noisy.height())
    throw std::invalid_argument("denoise: the feature buffers' size differs from the image's");
  const int width = noisy.width(), height = noisy.height();
  const std::vector<Guide> guides = makeGuides(features);
  std::vector<Vec3> light, divisor;
  demodulate(noisy, features, light, divisor);
  // Measured on the radiance itself, and colours compared at the centre's albedo below: dividing by a
  // dark albedo (a dark background) multiplies the noise, which a global level would not follow.
  std::vector<Vec3> radiance;
  radiance.reserve(light.size());
  for (const Rgba& c : noisy.pixels()) radiance.push_back(c.rgb());
  // A floor keeps the colour weight finite on a noiseless image (it then keeps equal colours only).
  const float noise = std::max(estimateNoiseOf(radiance, guides, width, height), 1e-5f);

  std::vector<Vec3> filtered(light.size());
  for (int pass = 0; pass < options.passes; ++pass) {
    const int step = 1 << pass;
    const float sigma = options.colorSigma * noise / static_cast<float>(step);
    const float colorScale = 1.0f / (2.0f * 3.0f * sigma * sigma);  // per channel: the mean of three
    parallelFor(static_cast<std::size_t>(height), options.threads, 2, [&](std::size_t row) {
      const int y = static_cast<int>(row);
      for (int x = 0; x < width; ++x) {
        const std::size_t p = features.index(x, y);
        Vec3 sum{0, 0, 0};
        float weightSum = 0;
        for (int j = -2; j <= 2; ++j) {
          const int qy = y + j * step;
          if (qy < 0 || qy >= height) continue;
          for (int i = -2; i <= 2; ++i) {
            const int qx = x + i * step;
            if (qx < 0 || qx >= width) continue;
            const std::size_t q = features.index(qx, qy);
            const Vec3 dc = (light[q] - light[p]) * divisor[p];
            float exponent = dot(dc, dc) * colorScale;
            const float factor = featureWeight(guides[p], guides[q], i * step, j * step, options, exponent);
            // Below e^-30 a tap cannot move the sum: skip its exp.
            if (factor < 1e-12f || exponent > 30.0f) continue;
            const float w = kKernel[i + 2] * kKernel[j + 2] * factor * std::exp(-exponent);
            sum += light[q] * w;
            weightSum += w;
          }
        }
        filtered[p] = weightSum > 0.0f ? sum * (1.0f / weightSum) : light[p];
      }
    });
    light.swap(filtered);
  }

  Image result(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t k = features.index(x, y);
      const Vec3 c = light[k] * divisor[k];
      result.at(x, y) = toRgba(c, noisy.at(x, y).a);
    }
  return result;
}

}  // namespace lancer
