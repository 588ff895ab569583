#include "lancer/render/pixel_loop.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/image/pixel_encoding.hpp"
#include "lancer/image/tone_map.hpp"
#include "lancer/render/ao_integrator.hpp"
#include "lancer/render/path_integrator.hpp"
#include "lancer/render/pixel_sampler.hpp"
#include "lancer/render/tracer.hpp"

namespace lancer {

namespace {

// A linear luminance as the picture shows it, in [0, 1].
double shownLuminance(double luminance, const RenderSettings& settings) {
  float x = static_cast<float>(luminance * std::exp2(static_cast<double>(settings.exposure)));
  switch (settings.toneMap) {
    case ToneMap::None:
      break;
    case ToneMap::Filmic:
      x = filmicCurve(x);
      break;
    case ToneMap::Aces:
      x = acesCurve(x);
      break;
  }
  x = std::clamp(x, 0.0f, 1.0f);
  return settings.srgb ? srgbFromLinear(x) : x;
}

}  // namespace

int adaptiveFirstPass(int samples) {
  return std::min(samples, std::clamp(samples / 8, kAdaptiveFirstPassFewest, kAdaptiveFirstPassMost));
}

float displayedError(double luminance, double standardError, const RenderSettings& settings) {
  const double high = shownLuminance(luminance + standardError, settings);
  const double low = shownLuminance(std::max(0.0, luminance - standardError), settings);
  return static_cast<float>(0.5 * (high - low));
}

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
  } else {
    if (settings_.adaptiveNoise > 0.0f) {
      adaptiveTile(x0, y0, x1, y1, band, bandY0, counters, samples);
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
    if (settings_.adaptiveNoise > 0.0f) {
      // The pixel's error rounds look at its neighbours in its tile: render the tile, keep the pixel.
      const int x0 = x / kTileSize * kTileSize, y0 = y / kTileSize * kTileSize;
      const int x1 = std::min(x0 + kTileSize, settings_.width),
                y1 = std::min(y0 + kTileSize, settings_.height);
      Image tile(x1, y1 - y0);  // as a band: the image's columns, rows from y0
      std::uint64_t tileSamples = 0;
      adaptiveTile(x0, y0, x1, y1, tile, y0, counters, tileSamples);
      samples += static_cast<std::uint64_t>(
          tallies_[static_cast<std::size_t>((y - y0) * (x1 - x0) + (x - x0))].count);
      return tile.at(x, y - y0);
    }
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
template <RayIntegrator Integrator>
void PixelLoop<Integrator>::addSamples(int x, int y, int end, PixelTally& tally,
                                       TraceCounters& counters) const {
  for (; tally.count < end; ++tally.count) {
    SampleStream stream(x, y, static_cast<std::uint32_t>(tally.count));
    float dx, dy;
    stream.next2D(dx, dy);
    const Ray ray = camera_.generateRay(static_cast<float>(x) + dx, static_cast<float>(y) + dy);
    TraceResult result;
    if constexpr (FeatureIntegrator<Integrator>) {
      if (features_ != nullptr) {
        SurfaceFeatures seen;
        result = integrator_.li(ray, stream, counters, &seen);
        tally.features.add(seen);
      } else {
        result = integrator_.li(ray, stream, counters);
      }
    } else {
      result = integrator_.li(ray, stream, counters);
    }
    tally.sum += result.color;
    tally.alphaSum += result.alpha;
    const double luminance = 0.2126 * result.color.x + 0.7152 * result.color.y + 0.0722 * result.color.z;
    tally.luminanceSum += luminance;
    tally.luminanceSquares += luminance * luminance;
  }
}

template <RayIntegrator Integrator>
Rgba PixelLoop<Integrator>::finishPixel(int x, int y, const PixelTally& tally) const {
  const int n = tally.count;
  if (features_ != nullptr) {
    const std::size_t k = features_->index(x, y);
    tally.features.store(*features_, k, n);
    // Each pixel's own count: the denoiser weighs pixels by these, whatever their samples.
    features_->variance[k] = varianceOfMean(n, tally.luminanceSum, tally.luminanceSquares);
  }
  const float weight = 1.0f / static_cast<float>(n);
  const float alpha = settings_.transparentBackground ? tally.alphaSum * weight : 1.0f;
  return toRgba(tally.sum * weight, alpha);
}

// The noise test runs every 8 samples from the 16th; a dark pixel is measured against 1/64 of full
// scale, or it might never stop.
template <RayIntegrator Integrator>
Rgba PixelLoop<Integrator>::streamPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) const {
  constexpr int kBatch = 8, kMinSamples = 16;
  constexpr double kDarkest = 1.0 / 64.0;
  PixelTally tally;
  if (settings_.noise <= 0.0f) {
    addSamples(x, y, settings_.samples, tally, counters);
  } else {
    while (tally.count < settings_.samples) {
      const int n = tally.count + 1;
      addSamples(x, y, n, tally, counters);
      if (n >= kMinSamples && n % kBatch == 0) {
        const double mean = tally.luminanceSum / n;
        const double variance = std::max(0.0, (tally.luminanceSquares - tally.luminanceSum * mean) / (n - 1));
        if (std::sqrt(variance / n) <= settings_.noise * std::max(mean, kDarkest)) break;
      }
    }
  }
  samples += static_cast<std::uint64_t>(tally.count);
  return finishPixel(x, y, tally);
}

// Rounds over the tile (as Cycles' adaptive sampling, and Mitsuba's and pbrt's error-driven samplers):
// every pixel takes a first pass; then, while some pixel's error is above the target, each pixel whose
// largest error among itself and its neighbours (3 x 3, inside the tile) is above it takes more
// samples: as many as its error says it needs, n (error / target)^2, at least kAdaptiveRoundMin and
// at most as many again as it has, never beyond `samples`. The neighbours guard a pixel whose few
// samples happened to agree (all missing a small light) against stopping early. Every pixel's errors
// are measured before a round adds samples, and the tiles are fixed, so the samples each pixel takes
// are the same for any thread count; its samples are the first of its own stream, so its value is a
// plain render's at its count.
template <RayIntegrator Integrator>
void PixelLoop<Integrator>::adaptiveTile(int x0, int y0, int x1, int y1, Image& band, int bandY0,
                                         TraceCounters& counters, std::uint64_t& samples) {
  const int width = x1 - x0, height = y1 - y0;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  tallies_.assign(pixels, PixelTally{});
  roundError_.assign(pixels, 0.0f);
  const int most = settings_.samples;
  const double target = settings_.adaptiveNoise;
  const int firstPass = adaptiveFirstPass(most);
  const auto tallyAt = [&](int i, int j) -> PixelTally& {
    return tallies_[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(i)];
  };
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) addSamples(x0 + i, y0 + j, firstPass, tallyAt(i, j), counters);
  for (;;) {
    for (PixelTally& tally : tallies_) {
      const double mean = tally.luminanceSum / tally.count;
      const float variance = varianceOfMean(tally.count, tally.luminanceSum, tally.luminanceSquares);
      tally.error =
          variance < 0.0f ? 0.0f : displayedError(mean, std::sqrt(static_cast<double>(variance)), settings_);
    }
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        float largest = 0.0f;
        for (int v = std::max(0, j - 1); v <= std::min(height - 1, j + 1); ++v)
          for (int u = std::max(0, i - 1); u <= std::min(width - 1, i + 1); ++u)
            largest = std::max(largest, tallyAt(u, v).error);
        roundError_[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(i)] = largest;
      }
    bool more = false;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        PixelTally& tally = tallyAt(i, j);
        const double error = roundError_[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                                         static_cast<std::size_t>(i)];
        if (tally.count >= most || error <= target) continue;
        const double needed = std::ceil(tally.count * (error / target) * (error / target));
        const int end = static_cast<int>(std::min<double>(
            most, std::clamp<double>(needed, tally.count + kAdaptiveRoundMin, 2.0 * tally.count)));
        addSamples(x0 + i, y0 + j, end, tally, counters);
        more = true;
      }
    if (!more) break;
  }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const PixelTally& tally = tallyAt(i, j);
      samples += static_cast<std::uint64_t>(tally.count);
      band.at(x0 + i, y0 + j - bandY0) = finishPixel(x0 + i, y0 + j, tally);
    }
}

template class PixelLoop<Tracer>;
template class PixelLoop<PathIntegrator>;
template class PixelLoop<AoIntegrator>;

}  // namespace lancer
