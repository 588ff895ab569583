// Renders an image in tiles of 32x32 pixels: worker threads take tiles in a fixed order (left to right
// within a band of 32 rows, bands top to bottom) and trace every sample of every pixel. Per-pixel
// deterministic sampling makes the image bit-identical for any thread count. Finished bands go, in
// order, to a sink on the calling thread, so an image of any height needs memory for a few bands.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <variant>

#include "lancer/image/image.hpp"
#include "lancer/render/ao_integrator.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/feature_buffers.hpp"
#include "lancer/render/path_integrator.hpp"
#include "lancer/render/pixel_loop.hpp"  // kTileSize
#include "lancer/render/tracer.hpp"

namespace lancer {

struct RenderProgress {
  double fraction = 0;     // of pixels done
  std::uint64_t rays = 0;  // traced so far
  double seconds = 0;      // since the start
};

struct RenderOptions {
  int threads = 0;  // 0: all hardware threads
  // Called from the calling thread about every `progressInterval` seconds, and once at the end.
  std::function<void(const RenderProgress&)> onProgress;
  double progressInterval = 0.25;
  // Set by another thread (e.g. a signal handler) to stop early; the image is then incomplete.
  const std::atomic<bool>* cancel = nullptr;
  // Camera rays of 4x2-pixel blocks traced as packets by the integrators that can (PacketIntegrator,
  // integrator.hpp: the Whitted tracer, with its shadow rays); false traces every ray on its own.
  // The image is the same, to the bit.
  bool packets = true;
  // When set (the image's size), the integrators that report what their samples see first
  // (FeatureIntegrator, integrator.hpp: the path tracer) fill it for every pixel they render, from
  // those samples; Renderer::featuresFromSamples says whether this renderer's integrator does.
  FeatureBuffers* features = nullptr;
};

struct RenderStats {
  double seconds = 0;
  std::uint64_t rays = 0;
  double samplesPerPixel = 0;  // mean, as actually traced (adaptive sampling varies it)
  bool cancelled = false;
  int peakBufferedRows = 0;  // most image rows held at once in bands being traced or waiting for the sink
};

// A pixel came out NaN or infinite, whatever the integrator: never a picture with holes reported as
// success. renderBands checks every band, on the calling thread, before it reaches the sink, and
// throws this for its first bad pixel in scan order (the same pixel for any thread count); the CLI
// and Python report it as an InputError of the scene (extreme intensities overflow float), exit code 2.
class NonFiniteRenderError : public std::runtime_error {
 public:
  NonFiniteRenderError(int x, int y, const Rgba& value);
  int x, y;
};

// Receives rows [y0, y0 + band.height()) of the image, full width; bands come top to bottom, each
// once, on the thread that called renderBands. An exception from the sink stops the render (the
// workers finish their tiles) and propagates.
using BandSink = std::function<void(int y0, const Image& band)>;

// Consecutive bands of an image, from `first` (0: the top band); count < 0 means to the bottom. A
// cluster job renders a range per work item; the tiles, and so the pixels, are those of the whole image.
struct BandRange {
  int first = 0;
  int count = -1;
};

// The number of bands (rows of tiles) of an image `height` pixels high.
int bandCountOf(int height);

// What a frame needs, held together: the scene and its accelerator, the camera, the settings, and
// the integrator of the settings (integrator.hpp) built from them once (as pbrt-v4's integrator holds its
// aggregate, lights and camera, so that rendering takes only where the pixels go). The scene, accelerator and
// camera must outlive it.
class Renderer {
 public:
  Renderer(const Scene& scene, const Accelerator& accelerator, const Camera& camera,
           const RenderSettings& settings);

  // The image band by band into `sink`. When cancelled, the sink has received only some of the
  // bands (stats->cancelled is then true).
  void renderBands(const RenderOptions& options, const BandSink& sink, RenderStats* stats = nullptr,
                   BandRange range = {}) const;
  // The rows of `range` as one image (a cluster job's work item), full width.
  Image renderRows(BandRange range, const RenderOptions& options, RenderStats* stats = nullptr) const;
  // The whole image at once (animations, GIF output, tests): renderBands into one Image.
  Image renderImage(const RenderOptions& options, RenderStats* stats = nullptr) const;
  // renderImage, then with settings.denoise the denoiser (denoiser.hpp), guided by the features of the
  // render's own samples where the integrator reports them, else of renderFeatures' pass; `features`,
  // when given, receives the feature buffers (made for it even without denoising). A cancelled render
  // is returned as it is, not denoised.
  Image renderFinal(const RenderOptions& options, RenderStats* stats = nullptr,
                    FeatureBuffers* features = nullptr) const;
  // The albedo, normal and depth of the first surface of every pixel, averaged over an n x n grid of
  // its camera samples (the render's own grid, at most 4 x 4), rows in parallel: the same buffers
  // for any thread count. Primary rays only, no lighting: a fraction of a render's time.
  FeatureBuffers renderFeatures(int threads) const;
  // Whether the integrator fills RenderOptions::features from its own samples.
  bool featuresFromSamples() const;
  // Radiance of one pixel (all its samples), for `--pixel x,y` debugging and for tests.
  Rgba renderPixel(int x, int y, TraceCounters& counters, std::uint64_t& samplesTraced) const;

 private:
  const Camera& camera_;
  RenderSettings settings_;
  SceneQueries queries_;  // the feature buffers' camera rays, whatever the integrator
  // Chosen once per worker thread (std::visit), then driven by the pixel loop of its type
  // (pixel_loop.hpp), which samples each pixel as the integrator's capabilities say.
  std::variant<Tracer, PathIntegrator, AoIntegrator> integrator_;
};

// What goes into an 8- or 16-bit file: the radiance times 2^exposure through the settings' tone curve
// (a copy; the image itself when neither applies). EXR files take the radiance as it is.
Image displayImage(const Image& radiance, const RenderSettings& settings);

// The camera of a frame: `camera`'s view of the scene, for an image of the settings' size.
Camera makeCamera(const CameraSettings& camera, const Scene& scene, const RenderSettings& settings);

// How many bands renderBands keeps at most (being traced, or done and waiting for the sink): enough
// that `threads` workers (0: all hardware threads) always find tiles while the sink writes a band.
int bandWindow(int width, int threads);
// The bytes renderBands allocates for its bands: bandWindow bands of width x kTileSize pixels.
std::uint64_t bandMemoryBytes(int width, int height, int threads);

}  // namespace lancer
