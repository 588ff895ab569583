// Renders a whole image: the image is cut into tiles, worker threads take tiles in a fixed order
// and trace every sample of every pixel. Per-pixel deterministic sampling makes the image
// bit-identical for any thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "lancer/image/image.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/tracer.hpp"

namespace lancer {

struct RenderProgress {
  double fraction = 0;      // of pixels done
  std::uint64_t rays = 0;   // traced so far
  double seconds = 0;       // since the start
};

struct RenderOptions {
  int threads = 0;  // 0: all hardware threads
  // Called from the calling thread about every `progressInterval` seconds, and once at the end.
  std::function<void(const RenderProgress&)> onProgress;
  double progressInterval = 0.25;
  // Set by another thread (e.g. a signal handler) to stop early; the image is then incomplete.
  const std::atomic<bool>* cancel = nullptr;
};

struct RenderStats {
  double seconds = 0;
  std::uint64_t rays = 0;
  double samplesPerPixel = 0;  // mean, as actually traced (adaptive sampling varies it)
  bool cancelled = false;
};

Image renderImage(const Scene& scene, const Accelerator& accelerator, const Camera& camera,
                  const RenderSettings& settings, const RenderOptions& options, RenderStats* stats = nullptr);

// Radiance of one pixel (all its samples), for `--pixel x,y` debugging and for tests.
Rgba renderPixel(const Tracer& tracer, const Camera& camera, const RenderSettings& settings, int x, int y,
                 TraceCounters& counters, std::uint64_t& samplesTraced);

}  // namespace lancer
