// Classic adaptive supersampling (Whitted 1980): trace the corners of each pixel, and split a square
// into four only where its corner samples differ by more than a threshold, down to a maximum depth.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/image/image.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// Deepest subdivision for `samples`: the largest d with 4^d <= samples (so samples = 4 or 16 may
// reach the 2x2 or 4x4 grid of the regular sampler), capped at kMaxAdaptiveDepth.
inline constexpr int kMaxAdaptiveDepth = 5;
int adaptiveMaxDepth(int samples);

// One per worker thread: owns its scratch (allocated once, reused for every tile and pixel).
// A pixel's value is the area-weighted mean over its final squares of each square's corner mean,
// a box filter over the pixel like the regular grid's. Corner samples are traced at fixed positions,
// so the image is the same for any thread count: pixel corners are shared by the pixels of a tile
// (neighbouring tiles each trace their common border), sub-pixel points by the squares of a pixel.
// Defined for the Whitted tracer (adaptive_sampler.cpp instantiates it), the one deterministic integrator.
template <DeterministicIntegrator Integrator>
class AdaptiveSampler {
 public:
  // `packets`: with a PacketIntegrator, the pixel corners of a tile are traced in packets of 4x2, and
  // the midpoints of a split square in one packet.
  AdaptiveSampler(const Integrator& integrator, const Camera& camera, const RenderSettings& settings,
                  bool packets = false);

  // Renders pixels [x0, x1) x [y0, y1) into `band`, whose row 0 is image row bandY0; `samples`
  // counts the primary rays traced.
  void renderTile(int x0, int y0, int x1, int y1, Image& band, int bandY0, TraceCounters& counters,
                  std::uint64_t& samples);
  // One pixel on its own (its four corners traced here), for `--pixel` and tests.
  Rgba renderPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples);

 private:
  struct Sample {
    Vec3 color;
    float alpha;
  };
  Sample traceAt(float x, float y, TraceCounters& counters, std::uint64_t& samples) const;
  // The pixel corners of a tile into cornerRows_ (columns x rows from (x0, y0)).
  void traceCorners(int x0, int y0, int columns, int rows, TraceCounters& counters, std::uint64_t& samples);
  // Fills the lattice of the pixel from its four corners and returns the pixel's value.
  Rgba shadePixel(int x, int y, const Sample corners[4], TraceCounters& counters, std::uint64_t& samples);
  // Mean of the square with lower corner (i, j) on the pixel's lattice and side `size` (lattice units).
  Sample square(int i, int j, int size, TraceCounters& counters, std::uint64_t& samples);
  Sample& latticeSample(int i, int j, TraceCounters& counters, std::uint64_t& samples);
  // With packets: the untraced ones of the five lattice points that splitting the square with lower
  // corner (i, j) and side `size` needs, traced as one packet before the halves ask for them.
  void traceMidpoints(int i, int j, int size, TraceCounters& counters, std::uint64_t& samples);
  bool differ(const Sample& a, const Sample& b, const Sample& c, const Sample& d) const;

  const Integrator& integrator_;
  const Camera& camera_;
  bool compareAlpha_;
  bool packets_;
  float threshold_;
  int depth_;
  int side_;  // lattice points per pixel side: 2^depth + 1
  std::vector<Sample> lattice_;
  std::vector<std::uint32_t> latticeStamp_;  // == stamp_ when the lattice point is traced for this pixel
  std::uint32_t stamp_ = 0;
  int pixelX_ = 0, pixelY_ = 0;
  std::vector<Sample> cornerRows_;  // (tile width + 1) x (tile height + 1) pixel corners
};

}  // namespace lancer
