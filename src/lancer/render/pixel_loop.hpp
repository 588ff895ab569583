// The one pixel loop: the pixels of a tile, each the mean of its samples' answers from an integrator
// (integrator.hpp), for every integrator alike (Mitsuba's render_block, pbrt-v4's EvaluatePixelSample).
#pragma once

#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "lancer/image/image.hpp"
#include "lancer/render/adaptive_sampler.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

inline constexpr int kTileSize = 32;  // pixels on a tile's side; a band is kTileSize rows

// Adaptive rounds (`adaptiveNoise`): the first pass takes an eighth of `samples`, at least two (a
// spread needs two) and at most eight; a later round adds at least kAdaptiveRoundMin samples to a
// pixel that still needs some. With --denoise, a first pass of 2 of 8 or 16 samples measured best at
// 1080p (docs/lighting.md): most of a picture is floor and background that needs no more.
inline constexpr int kAdaptiveFirstPassFewest = 2;
inline constexpr int kAdaptiveFirstPassMost = 8;
inline constexpr int kAdaptiveRoundMin = 4;
int adaptiveFirstPass(int samples);

// The standard error of a pixel's displayed luminance, as a fraction of white: the spread of its mean
// `luminance` (linear) by `standardError` through the exposure, the tone curve and the encoding of
// `settings` (a symmetric difference, so clipped whites and the sRGB curve's steep darks count as
// the picture shows them).
float displayedError(double luminance, double standardError, const RenderSettings& settings);

// Where a pixel's samples fall follows what the integrator is (integrator.hpp):
// - a deterministic one is sampled at the settings' sampler's points: the regular or stratified
//   n x n grid (n = round(sqrt(samples))), or adaptive supersampling (adaptive_sampler.hpp); with
//   packets and a PacketIntegrator, the grid's samples of 4x2-pixel blocks go as one packet each;
// - a Monte Carlo one at the points of its pixel's sample stream (sample_sequence.hpp): `samples`
//   of them, or fewer once the pixel's relative error is below `noise`; or, with `adaptiveNoise`, in
//   rounds over the tile: a first pass of a few samples each, then more samples for the pixels whose
//   displayed error (or a neighbour's) is still above it, up to `samples`; with feature buffers and a
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

  // What a pixel's samples have added up to so far.
  struct PixelTally {
    Vec3 sum{0, 0, 0};
    float alphaSum = 0;
    double luminanceSum = 0, luminanceSquares = 0;
    FeatureSum features;
    int count = 0;
    float error = 0;  // displayedError after the last round
  };
  // Samples [tally.count, end) of pixel (x, y) into its tally.
  void addSamples(int x, int y, int end, PixelTally& tally, TraceCounters& counters) const;
  // The tally's pixel value, and its features and variance when features are wanted.
  Rgba finishPixel(int x, int y, const PixelTally& tally) const;
  // The tile in adaptive rounds (`adaptiveNoise`); tallies_ keeps its pixels' tallies until the next tile.
  void adaptiveTile(int x0, int y0, int x1, int y1, Image& band, int bandY0, TraceCounters& counters,
                    std::uint64_t& samples);

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
  std::vector<PixelTally> tallies_;  // adaptive rounds: the tile's pixels, row by row
  std::vector<float> roundError_;    // adaptive rounds: the largest error around each pixel
};

}  // namespace lancer
