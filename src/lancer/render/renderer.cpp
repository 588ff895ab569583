#include "lancer/render/renderer.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <thread>
#include <vector>

#include "lancer/render/adaptive_sampler.hpp"
#include "lancer/render/pixel_sampler.hpp"

namespace lancer {
namespace {

constexpr int kTileSize = 32;

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

}  // namespace

Rgba renderPixel(const Tracer& tracer, const Camera& camera, const RenderSettings& settings, int x, int y,
                 TraceCounters& counters, std::uint64_t& samplesTraced) {
  if (settings.sampler == SamplerKind::Adaptive)
    return AdaptiveSampler(tracer, camera, settings).renderPixel(x, y, counters, samplesTraced);
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(settings.samples)))));
  const bool parallelView = camera.projection() == Projection::Orthographic;
  Vec3 sum{0, 0, 0};
  float alphaSum = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      float dx = 0.5f, dy = 0.5f;
      gridSampleOffset(settings.sampler, n, i, j, x, y, dx, dy);
      const Ray ray = camera.generateRay(static_cast<float>(x) + dx, static_cast<float>(y) + dy);
      const TraceResult result = tracer.tracePrimary(ray, parallelView, counters);
      sum += result.color;
      alphaSum += result.alpha;
    }
  }
  samplesTraced += static_cast<std::uint64_t>(n * n);
  const float weight = 1.0f / static_cast<float>(n * n);
  const float alpha = settings.transparentBackground ? alphaSum * weight : 1.0f;
  return toRgba(sum * weight, alpha);
}

Image renderImage(const Scene& scene, const Accelerator& accelerator, const Camera& camera,
                  const RenderSettings& settings, const RenderOptions& options, RenderStats* stats) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  Image image(settings.width, settings.height);
  const Tracer tracer(scene, accelerator, settings, camera.pixelFootprint());

  const int tilesX = (settings.width + kTileSize - 1) / kTileSize;
  const int tilesY = (settings.height + kTileSize - 1) / kTileSize;
  const int tileCount = tilesX * tilesY;
  std::atomic<int> nextTile{0};
  std::atomic<std::uint64_t> pixelsDone{0};
  std::atomic<std::uint64_t> raysTraced{0};
  std::atomic<std::uint64_t> samplesTraced{0};
  std::atomic<int> workersRunning{0};

  auto worker = [&] {
    std::optional<AdaptiveSampler> adaptive;
    if (settings.sampler == SamplerKind::Adaptive) adaptive.emplace(tracer, camera, settings);
    for (;;) {
      if (options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed)) break;
      const int tile = nextTile.fetch_add(1, std::memory_order_relaxed);
      if (tile >= tileCount) break;
      const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
      const int x1 = std::min(x0 + kTileSize, settings.width), y1 = std::min(y0 + kTileSize, settings.height);
      TraceCounters counters;
      std::uint64_t samples = 0;
      if (adaptive) {
        adaptive->renderTile(x0, y0, x1, y1, image, counters, samples);
      } else {
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x)
            image.at(x, y) = renderPixel(tracer, camera, settings, x, y, counters, samples);
      }
      raysTraced.fetch_add(counters.rays, std::memory_order_relaxed);
      samplesTraced.fetch_add(samples, std::memory_order_relaxed);
      pixelsDone.fetch_add(static_cast<std::uint64_t>(x1 - x0) * static_cast<std::uint64_t>(y1 - y0),
                           std::memory_order_relaxed);
    }
    workersRunning.fetch_sub(1, std::memory_order_release);
  };

  const int threadCount = std::min(resolveThreadCount(options.threads), std::max(tileCount, 1));
  const double totalPixels = static_cast<double>(settings.width) * settings.height;
  auto report = [&] {
    if (!options.onProgress) return;
    RenderProgress progress;
    progress.fraction = static_cast<double>(pixelsDone.load(std::memory_order_relaxed)) / totalPixels;
    progress.rays = raysTraced.load(std::memory_order_relaxed);
    progress.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    options.onProgress(progress);
  };
  {
    workersRunning.store(threadCount);
    std::vector<std::jthread> workers;
    workers.reserve(static_cast<std::size_t>(threadCount));
    for (int t = 0; t < threadCount; ++t) workers.emplace_back(worker);
    if (options.onProgress) {
      const auto interval = std::chrono::duration<double>(options.progressInterval);
      auto lastReport = Clock::now();
      while (workersRunning.load(std::memory_order_acquire) > 0) {
        std::this_thread::sleep_for(std::min(interval, std::chrono::duration<double>(0.02)));
        if (Clock::now() - lastReport >= interval) {
          lastReport = Clock::now();
          report();
        }
      }
    }
  }
  report();

  if (stats != nullptr) {
    stats->seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats->rays = raysTraced.load();
    stats->samplesPerPixel = static_cast<double>(samplesTraced.load()) / totalPixels;
    stats->cancelled = options.cancel != nullptr && options.cancel->load() && pixelsDone.load() < totalPixels;
  }
  return image;
}

}  // namespace lancer
