// The one pixel loop: the pixels of a tile, each the mean of its samples' answers from an integrator
// (integrator.hpp), for every integrator alike (Mitsuba's render_block, pbrt-v4's EvaluatePixelSample).
#pragma once

#include <cstdint>
#include <optional>
#include <variant>

#include "lancer/image/image.hpp"
#include "lancer/render/adaptive_sampler.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// Where a pixel's samples fall follows what the integrator is (integrator.hpp):
// - a deterministic one is sampled at the settings' sampler's points: the regular or stratified
//   n x n grid (n = round(sqrt(samples))), or adaptive supersampling (adaptive_sampler.hpp); with
//   packets and a PacketIntegrator, the grid's samples of 4x2-pixel blocks go as one packet each;
// - a Monte Carlo one at the points of its pixel's sample stream (sample_sequence.hpp): `samples`
//   of them, or fewer once the pixel's relative error is below `noise`; with feature buffers and a
//   FeatureIntegrator, each pixel's features are the mean of what its samples saw first.
// The compiler makes one loop per integrator: no virtual call per ray. One per worker thread (the
// adaptive sampler's scratch is its own); the integrator, camera and settings must outlive it.
template <RayIntegrator Integrator>
class PixelLoop {
 public:
  // `packets`: trace camera rays as packets where the integrator can (the image is the same).
  // `features` (the image's size), for a FeatureIntegrator: receives the features of every pixel rendered.
  PixelLoop(const Integrator& integrator, const Camera& camera, const RenderSettings& settings, bool packets,
            FeatureBuffers* features = nullptr);

  // Pixels [x0, x1) x [y0, y1) into `band`, whose row 0 is image row bandY0; `samples` counts the
  // camera rays traced.
  void renderTile(int x0, int y0, int x1, int y1, Image& band, int bandY0, TraceCounters& counters,
                  std::uint64_t& samples);
  // One pixel on its own (single rays), for `--pixel x,y` and tests: the value renderTile gives it.
  Rgba renderPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples);

 private:
  Rgba gridPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) const;
  // The grid's samples of the block [x0, x0 + 4) x [y0, y0 + 2) inside [.., x1) x [.., y1), one
  // packet per sample position.
  void gridBlock(int x0, int y0, int x1, int y1, Image& band, int bandY0, TraceCounters& counters,
                 std::uint64_t& samples) const;
  Rgba streamPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) const;

  // The adaptive sampler, when the settings choose it, for a deterministic integrator; nothing else.
  template <typename I>
  struct AdaptiveOf {
    using type = std::monostate;
  };
  template <DeterministicIntegrator I>
  struct AdaptiveOf<I> {
    using type = std::optional<AdaptiveSampler<I>>;
  };
  using Adaptive = typename AdaptiveOf<Integrator>::type;

  const Integrator& integrator_;
  const Camera& camera_;
  const RenderSettings& settings_;
  bool packets_;
  FeatureBuffers* features_;
  int gridSide_;  // n of the n x n grid
  Adaptive adaptive_;
};

}  // namespace lancer
