#include "lancer/render/renderer.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <vector>

#include "lancer/image/tone_map.hpp"
#include "lancer/render/denoiser.hpp"
#include "lancer/render/pixel_loop.hpp"
#include "lancer/render/pixel_sampler.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {
namespace {

int tilesAcross(int pixels) { return (pixels + kTileSize - 1) / kTileSize; }

// The bands in flight and the hand-over between workers and the calling thread. Band b lives in
// slot b % window; a worker may start a tile of band b only once band b - window has gone to the
// sink, which bounds memory to `window` bands. Tiles are claimed in order, so every tile of a band
// below the one a waiting worker holds is already being traced: the wait always ends.
class BandWindow {
 public:
  BandWindow(int width, int height, int firstBand, int window)
      : width_(width),
        height_(height),
        firstBand_(firstBand),
        tilesX_(tilesAcross(width)),
        slots_(static_cast<std::size_t>(window)) {}

  // Blocks until band `band` may be traced, then returns its pixels (allocated by its first tile),
  // or nullptr once the render is stopping.
  Image* enter(int band) {
    std::unique_lock lock(mutex_);
    slotFreed_.wait(lock, [&] { return stopping_ || band < flushed_ + windowSize(); });
    if (stopping_) return nullptr;
    Slot& slot = slotOf(band);
    if (slot.pixels.empty()) {
      const int rows = std::min(kTileSize, height_ - (firstBand_ + band) * kTileSize);
      slot.pixels = Image(width_, rows);
      slot.tilesLeft = tilesX_;
      bufferedRows_ += rows;
      peakBufferedRows_ = std::max(peakBufferedRows_, bufferedRows_);
    }
    return &slot.pixels;
  }

  void tileDone(int band) {
    std::lock_guard lock(mutex_);
    if (--slotOf(band).tilesLeft == 0) bandDone_.notify_all();
  }

  // The next band in order once all its tiles are traced, or nullptr after `timeout` (to let the
  // caller report progress and notice a cancel).
  const Image* waitForNext(std::chrono::duration<double> timeout) {
    std::unique_lock lock(mutex_);
    const auto ready = [&] {
      const Slot& slot = slotOf(flushed_);
      return !slot.pixels.empty() && slot.tilesLeft == 0;
    };
    if (!bandDone_.wait_for(lock, timeout, ready)) return nullptr;
    return &slotOf(flushed_).pixels;
  }

  // The sink has taken the next band: free its slot for band `flushed + window`.
  void release() {
    std::lock_guard lock(mutex_);
    Slot& slot = slotOf(flushed_);
    bufferedRows_ -= slot.pixels.height();
    slot.pixels = Image();
    ++flushed_;
    slotFreed_.notify_all();
  }

  // Wakes and turns away every waiting worker (done, cancelled, or the sink threw).
  void stop() {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    slotFreed_.notify_all();
  }

  int flushed() const { return flushed_; }  // calling thread only
  int peakBufferedRows() const {
    std::lock_guard lock(mutex_);
    return peakBufferedRows_;
  }

 private:
  struct Slot {
    Image pixels;
    int tilesLeft = 0;
  };
  int windowSize() const { return static_cast<int>(slots_.size()); }
  Slot& slotOf(int band) { return slots_[static_cast<std::size_t>(band % windowSize())]; }

  int width_, height_, firstBand_, tilesX_;  // bands are counted from firstBand_
  std::vector<Slot> slots_;
  mutable std::mutex mutex_;
  std::condition_variable bandDone_;   // a band's last tile finished
  std::condition_variable slotFreed_;  // a band went to the sink, or the render stops
  int flushed_ = 0;                    // bands handed to the sink
  bool stopping_ = false;
  int bufferedRows_ = 0, peakBufferedRows_ = 0;
};

// Stops the workers when the calling thread leaves renderBands, also by an exception from the sink,
// before the jthreads join.
struct StopOnExit {
  BandWindow& bands;
  ~StopOnExit() { bands.stop(); }
};

}  // namespace

NonFiniteRenderError::NonFiniteRenderError(int px, int py, const Rgba& value)
    : std::runtime_error(fmt::format(
          "pixel {},{} came out non-finite (rgb {} {} {}), so no image was written: look for extreme light "
          "intensities or material values, and trace the pixel with --pixel {},{}",
          px, py, value.r, value.g, value.b, px, py)),
      x(px),
      y(py) {}

namespace {

// Throws NonFiniteRenderError for the first pixel of `band` (rows from y0) that is NaN or infinite.
void requireFinite(const Image& band, int y0) {
  for (int y = 0; y < band.height(); ++y) {
    const std::span<const Rgba> row = band.row(y);
    float sum = 0;  // NaN or infinite as soon as one value is (+inf + -inf is NaN)
    for (const Rgba& p : row) sum += p.r + p.g + p.b + p.a;
    if (std::isfinite(sum)) continue;
    for (int x = 0; x < band.width(); ++x) {
      const Rgba& p = row[static_cast<std::size_t>(x)];
      if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b) || !std::isfinite(p.a))
        throw NonFiniteRenderError(x, y0 + y, p);
    }
  }
}

}  // namespace

int bandWindow(int width, int threads) {
  // At least two tiles per worker beyond the band the sink is writing; at least three bands so a
  // slow sink (PNG deflate) overlaps tracing.
  const int tilesX = tilesAcross(width);
  const int wanted = 2 * resolveThreadCount(threads);
  return std::max(3, (wanted + tilesX - 1) / tilesX + 1);
}

std::uint64_t bandMemoryBytes(int width, int height, int threads) {
  const std::uint64_t rows = static_cast<std::uint64_t>(
      std::min(bandWindow(width, threads) * kTileSize, tilesAcross(height) * kTileSize));
  return rows * static_cast<std::uint64_t>(width) * sizeof(Rgba);
}

namespace {

template <typename Variant>
auto makeIntegrator(const Scene& scene, const Accelerator& accelerator, const Camera& camera,
                    const RenderSettings& settings) {
  switch (settings.integrator) {
    case IntegratorKind::Path:
      return Variant(std::in_place_type<PathIntegrator>, scene, accelerator, settings, camera);
    case IntegratorKind::AmbientOcclusion:
      return Variant(std::in_place_type<AoIntegrator>, scene, accelerator, settings, camera);
    case IntegratorKind::Whitted:
      break;
  }
  return Variant(std::in_place_type<Tracer>, scene, accelerator, settings, camera);
}

}  // namespace

Camera makeCamera(const CameraSettings& camera, const Scene& scene, const RenderSettings& settings) {
  return Camera(camera, scene.geometry.origin, scene.geometry.bounds, settings.width, settings.height);
}

Renderer::Renderer(const Scene& scene, const Accelerator& accelerator, const Camera& camera,
                   const RenderSettings& settings)
    : camera_(camera),
      settings_(settings),
      queries_(scene, accelerator),
      integrator_(makeIntegrator<decltype(integrator_)>(scene, accelerator, camera, settings)) {}

Rgba Renderer::renderPixel(int x, int y, TraceCounters& counters, std::uint64_t& samplesTraced) const {
  return std::visit(
      [&](const auto& integrator) {
        return PixelLoop(integrator, camera_, settings_, false).renderPixel(x, y, counters, samplesTraced);
      },
      integrator_);
}

int bandCountOf(int height) { return tilesAcross(height); }

FeatureBuffers Renderer::renderFeatures(int threads) const {
  constexpr int kMaxFeatureGrid = 4;
  const RenderSettings& settings = settings_;
  FeatureBuffers buffers(settings.width, settings.height);
  const int n = std::clamp(static_cast<int>(std::lround(std::sqrt(static_cast<double>(settings.samples)))), 1,
                           kMaxFeatureGrid);
  const EdgePaint paint(queries_.scene(), camera_.pixelFootprint());
  parallelFor(static_cast<std::size_t>(settings.height), threads, 4, [&](std::size_t row) {
    const int y = static_cast<int>(row);
    for (int x = 0; x < settings.width; ++x) {
      FeatureSum sum;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          float dx = 0.5f, dy = 0.5f;
          gridSampleOffset(settings.sampler, n, i, j, x, y, dx, dy);
          sum.add(surfaceFeatures(queries_, paint,
                                  camera_.generateRay(static_cast<float>(x) + dx, static_cast<float>(y) + dy),
                                  settings.background, settings.srgb));
        }
      sum.store(buffers, buffers.index(x, y), n * n);
    }
  });
  return buffers;
}

bool Renderer::featuresFromSamples() const {
  return std::visit(
      [](const auto& integrator) { return FeatureIntegrator<std::decay_t<decltype(integrator)>>; },
      integrator_);
}

void Renderer::renderBands(const RenderOptions& options, const BandSink& sink, RenderStats* stats,
                           BandRange range) const {
  using Clock = std::chrono::steady_clock;
  const Stopwatch stopwatch;
  const Camera& camera = camera_;
  const RenderSettings& settings = settings_;

  const int tilesX = tilesAcross(settings.width);
  const int firstBand = std::clamp(range.first, 0, tilesAcross(settings.height));
  const int bandsLeft = tilesAcross(settings.height) - firstBand;
  const int bandCount = range.count < 0 ? bandsLeft : std::min(range.count, bandsLeft);
  const int tileCount = tilesX * bandCount;
  const int threadCount = std::max(1, std::min(resolveThreadCount(options.threads), tileCount));
  BandWindow bands(settings.width, settings.height, firstBand,
                   std::max(1, std::min(bandWindow(settings.width, threadCount), bandCount)));
  std::atomic<int> nextTile{0};
  std::atomic<std::uint64_t> pixelsDone{0};
  std::atomic<std::uint64_t> raysTraced{0};
  std::atomic<std::uint64_t> samplesTraced{0};
  // A worker's exception stops the render and is rethrown on this thread.
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  const auto cancelled = [&] {
    return failed.load(std::memory_order_relaxed) ||
           (options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed));
  };

  // One dispatch on the integrator per worker; inside, the pixel loop of that integrator.
  const auto traceTiles = [&](const auto& integrator) {
    PixelLoop loop(integrator, camera, settings, options.packets, options.features);
    for (;;) {
      if (cancelled()) break;
      const int tile = nextTile.fetch_add(1, std::memory_order_relaxed);
      if (tile >= tileCount) break;
      const int band = tile / tilesX;
      Image* pixels = bands.enter(band);
      if (pixels == nullptr) break;
      const int bandY0 = (firstBand + band) * kTileSize;
      const int x0 = (tile % tilesX) * kTileSize;
      const int x1 = std::min(x0 + kTileSize, settings.width),
                y1 = std::min(bandY0 + kTileSize, settings.height);
      TraceCounters counters;
      std::uint64_t samples = 0;
      loop.renderTile(x0, bandY0, x1, y1, *pixels, bandY0, counters, samples);
      raysTraced.fetch_add(counters.rays, std::memory_order_relaxed);
      samplesTraced.fetch_add(samples, std::memory_order_relaxed);
      pixelsDone.fetch_add(static_cast<std::uint64_t>(x1 - x0) * static_cast<std::uint64_t>(y1 - bandY0),
                           std::memory_order_relaxed);
      bands.tileDone(band);
    }
  };
  auto worker = [&] {
    try {
      std::visit(traceTiles, integrator_);
    } catch (...) {
      if (!failed.exchange(true)) failure = std::current_exception();
      bands.stop();
    }
  };

  const double totalPixels =
      static_cast<double>(settings.width) *
      std::max(0, std::min(settings.height, (firstBand + bandCount) * kTileSize) - firstBand * kTileSize);
  auto report = [&] {
    if (!options.onProgress) return;
    RenderProgress progress;
    progress.fraction = static_cast<double>(pixelsDone.load(std::memory_order_relaxed)) / totalPixels;
    progress.rays = raysTraced.load(std::memory_order_relaxed);
    progress.seconds = stopwatch.seconds();
    options.onProgress(progress);
  };
  {
    std::vector<std::jthread> workers;
    workers.reserve(static_cast<std::size_t>(threadCount));
    const StopOnExit stopOnExit{bands};  // destroyed before `workers` joins them
    for (int t = 0; t < threadCount; ++t) workers.emplace_back(worker);
    // Short waits: a cancel flag set by a signal handler notifies nobody.
    const auto interval = std::chrono::duration<double>(options.progressInterval);
    const auto poll = std::min(interval, std::chrono::duration<double>(0.02));
    auto lastReport = Clock::now();
    while (bands.flushed() < bandCount && !cancelled()) {
      if (const Image* band = bands.waitForNext(poll)) {
        requireFinite(*band, (firstBand + bands.flushed()) * kTileSize);
        sink((firstBand + bands.flushed()) * kTileSize, *band);
        bands.release();
      }
      if (options.onProgress && Clock::now() - lastReport >= interval) {
        lastReport = Clock::now();
        report();
      }
    }
  }
  if (failed.load()) std::rethrow_exception(failure);
  report();

  if (stats != nullptr) {
    stats->seconds = stopwatch.seconds();
    stats->rays = raysTraced.load();
    stats->samplesPerPixel = totalPixels > 0 ? static_cast<double>(samplesTraced.load()) / totalPixels : 0;
    stats->cancelled = bands.flushed() < bandCount;
    stats->peakBufferedRows = bands.peakBufferedRows();
  }
}

Image Renderer::renderRows(BandRange range, const RenderOptions& options, RenderStats* stats) const {
  const int first = std::clamp(range.first, 0, bandCountOf(settings_.height));
  const int last = range.count < 0 ? bandCountOf(settings_.height)
                                   : std::min(bandCountOf(settings_.height), first + range.count);
  const int y0 = first * kTileSize;
  Image rows(settings_.width, std::max(0, std::min(settings_.height, last * kTileSize) - y0));
  renderBands(
      options, [&](int bandY0, const Image& band) { rows.pasteTile(band, 0, bandY0 - y0); }, stats,
      BandRange{first, last - first});
  return rows;
}

Image Renderer::renderImage(const RenderOptions& options, RenderStats* stats) const {
  Image image(settings_.width, settings_.height);
  renderBands(
      options, [&](int y0, const Image& band) { image.pasteTile(band, 0, y0); }, stats);
  return image;
}

Image Renderer::renderFinal(const RenderOptions& options, RenderStats* stats,
                            FeatureBuffers* features) const {
  RenderStats own;
  RenderStats& done = stats != nullptr ? *stats : own;
  const bool wanted = settings_.denoise || features != nullptr;
  const bool fromSamples = wanted && featuresFromSamples();
  FeatureBuffers buffers;
  RenderOptions traced = options;
  if (fromSamples) {
    buffers = FeatureBuffers(settings_.width, settings_.height);
    traced.features = &buffers;
  }
  Image image = renderImage(traced, &done);
  if (done.cancelled || !wanted) return image;
  if (!fromSamples) buffers = renderFeatures(options.threads);
  if (settings_.denoise) {
    DenoiseOptions denoiseOptions;
    denoiseOptions.threads = options.threads;
    image = denoise(image, buffers, denoiseOptions);
  }
  if (features != nullptr) *features = std::move(buffers);
  return image;
}

Image displayImage(const Image& radiance, const RenderSettings& settings) {
  Image shown = radiance;
  applyToneMap(shown, settings.toneMap, settings.exposure);
  return shown;
}

}  // namespace lancer
