#include "lancer/render/pixel_loop.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/render/ao_integrator.hpp"
#include "lancer/render/path_integrator.hpp"
#include "lancer/render/pixel_sampler.hpp"
#include "lancer/render/tracer.hpp"

namespace lancer {

template <RayIntegrator Integrator>
PixelLoop<Integrator>::PixelLoop(const Integrator& integrator, const Camera& camera,
                                 const RenderSettings& settings, bool packets, FeatureBuffers* features)
    : integrator_(integrator),
      camera_(camera),
      settings_(settings),
      packets_(packets && PacketIntegrator<Integrator>),
      features_(FeatureIntegrator<Integrator> ? features : nullptr),
      gridSide_(
          std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(settings.samples)))))) {
  if constexpr (DeterministicIntegrator<Integrator>) {
    if (settings.sampler == SamplerKind::Adaptive) adaptive_.emplace(integrator, camera, settings, packets_);
  }
}

template <RayIntegrator Integrator>
void PixelLoop<Integrator>::renderTile(int x0, int y0, int x1, int y1, Image& band, int bandY0,
                                       TraceCounters& counters, std::uint64_t& samples) {
  if constexpr (DeterministicIntegrator<Integrator>) {
    if (adaptive_) {
      adaptive_->renderTile(x0, y0, x1, y1, band, bandY0, counters, samples);
      return;
    }
    if (packets_) {
      for (int y = y0; y < y1; y += 2)
        for (int x = x0; x < x1; x += 4) gridBlock(x, y, x1, y1, band, bandY0, counters, samples);
      return;
    }
  }
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      if constexpr (DeterministicIntegrator<Integrator>)
        band.at(x, y - bandY0) = gridPixel(x, y, counters, samples);
      else
        band.at(x, y - bandY0) = streamPixel(x, y, counters, samples);
    }
}

template <RayIntegrator Integrator>
Rgba PixelLoop<Integrator>::renderPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) {
  if constexpr (DeterministicIntegrator<Integrator>) {
    if (settings_.sampler == SamplerKind::Adaptive)
      return AdaptiveSampler<Integrator>(integrator_, camera_, settings_)
          .renderPixel(x, y, counters, samples);
    return gridPixel(x, y, counters, samples);
  } else {
    return streamPixel(x, y, counters, samples);
  }
}

template <RayIntegrator Integrator>
Rgba PixelLoop<Integrator>::gridPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) const {
  const int n = gridSide_;
  SampleStream unused(x, y, 0);  // a deterministic integrator draws nothing from it
  Vec3 sum{0, 0, 0};
  float alphaSum = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      float dx = 0.5f, dy = 0.5f;
      gridSampleOffset(settings_.sampler, n, i, j, x, y, dx, dy);
      const Ray ray = camera_.generateRay(static_cast<float>(x) + dx, static_cast<float>(y) + dy);
      const TraceResult result = integrator_.li(ray, unused, counters);
      sum += result.color;
      alphaSum += result.alpha;
    }
  }
  samples += static_cast<std::uint64_t>(n * n);
  const float weight = 1.0f / static_cast<float>(n * n);
  const float alpha = settings_.transparentBackground ? alphaSum * weight : 1.0f;
  return toRgba(sum * weight, alpha);
}

template <RayIntegrator Integrator>
void PixelLoop<Integrator>::gridBlock(int x0, int y0, int x1, int y1, Image& band, int bandY0,
                                      TraceCounters& counters, std::uint64_t& samples) const {
  if constexpr (PacketIntegrator<Integrator>) {
    constexpr int kBlockWidth = 4;
    static_assert(kPacketSize % kBlockWidth == 0);
    const int n = gridSide_;
    std::uint32_t active = 0;
    for (int p = 0; p < kPacketSize; ++p) {
      if (x0 + p % kBlockWidth < x1 && y0 + p / kBlockWidth < y1) active |= 1u << p;
    }
    Vec3 sum[kPacketSize] = {};
    float alphaSum[kPacketSize] = {};
    Ray rays[kPacketSize];
    TraceResult results[kPacketSize];
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        for (int p = 0; p < kPacketSize; ++p) {
          if ((active >> p & 1u) == 0) continue;
          const int x = x0 + p % kBlockWidth, y = y0 + p / kBlockWidth;
          float dx = 0.5f, dy = 0.5f;
          gridSampleOffset(settings_.sampler, n, i, j, x, y, dx, dy);
          camera_.generateRay(static_cast<float>(x) + dx, static_cast<float>(y) + dy, rays[p]);
        }
        integrator_.liPacket(rays, active, results, counters);
        for (int p = 0; p < kPacketSize; ++p) {
          if ((active >> p & 1u) == 0) continue;
          sum[p] += results[p].color;
          alphaSum[p] += results[p].alpha;
        }
      }
    }
    const float weight = 1.0f / static_cast<float>(n * n);
    for (int p = 0; p < kPacketSize; ++p) {
      if ((active >> p & 1u) == 0) continue;
      samples += static_cast<std::uint64_t>(n * n);
      const float alpha = settings_.transparentBackground ? alphaSum[p] * weight : 1.0f;
      band.at(x0 + p % kBlockWidth, y0 + p / kBlockWidth - bandY0) = toRgba(sum[p] * weight, alpha);
    }
  }
}

// A box filter over the pixel: the first two dimensions of each sample's stream place its camera ray.
// The noise test runs every 8 samples from the 16th; a dark pixel is measured against 1/64 of full
// scale, or it might never stop.
template <RayIntegrator Integrator>
Rgba PixelLoop<Integrator>::streamPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) const {
  constexpr int kBatch = 8, kMinSamples = 16;
  constexpr double kDarkest = 1.0 / 64.0;
  Vec3 sum{0, 0, 0};
  float alphaSum = 0;
  double luminanceSum = 0, luminanceSquares = 0;
  FeatureSum featureSum;
  int n = 0;
  while (n < settings_.samples) {
    SampleStream stream(x, y, static_cast<std::uint32_t>(n));
    float dx, dy;
    stream.next2D(dx, dy);
    const Ray ray = camera_.generateRay(static_cast<float>(x) + dx, static_cast<float>(y) + dy);
    TraceResult result;
    if constexpr (FeatureIntegrator<Integrator>) {
      if (features_ != nullptr) {
        SurfaceFeatures seen;
        result = integrator_.li(ray, stream, counters, &seen);
        featureSum.add(seen);
      } else {
        result = integrator_.li(ray, stream, counters);
      }
    } else {
      result = integrator_.li(ray, stream, counters);
    }
    sum += result.color;
    alphaSum += result.alpha;
    const double luminance = 0.2126 * result.color.x + 0.7152 * result.color.y + 0.0722 * result.color.z;
    luminanceSum += luminance;
    luminanceSquares += luminance * luminance;
    ++n;
    if (settings_.noise > 0.0f && n >= kMinSamples && n % kBatch == 0) {
      const double mean = luminanceSum / n;
      const double variance = std::max(0.0, (luminanceSquares - luminanceSum * mean) / (n - 1));
      if (std::sqrt(variance / n) <= settings_.noise * std::max(mean, kDarkest)) break;
    }
  }
  samples += static_cast<std::uint64_t>(n);
  if (features_ != nullptr) {
    const std::size_t k = features_->index(x, y);
    featureSum.store(*features_, k, n);
    features_->variance[k] = varianceOfMean(n, luminanceSum, luminanceSquares);
  }
  const float weight = 1.0f / static_cast<float>(n);
  const float alpha = settings_.transparentBackground ? alphaSum * weight : 1.0f;
  return toRgba(sum * weight, alpha);
}

template class PixelLoop<Tracer>;
template class PixelLoop<PathIntegrator>;
template class PixelLoop<AoIntegrator>;

}  // namespace lancer
