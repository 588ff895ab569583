// What the first visible surface of each pixel is, for the denoiser and for EXR layers: its albedo,
// normal and distance, averaged over the pixel's camera samples. The path tracer reports them from the
// first bounce of its own samples (integrator.hpp, FeatureIntegrator); for the other integrators a
// primary-ray pass of its own (Renderer::renderFeatures) makes them, only when asked for (--denoise,
// --aovs).
#pragma once

#include <cstddef>
#include <vector>

#include "lancer/math/ray.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// Per pixel, rows top to bottom. Samples that see nothing count the background as albedo and a zero
// normal; depth averages the samples that hit and is +infinity where none did.
struct FeatureBuffers {
  int width = 0, height = 0;
  std::vector<Vec3> albedo;  // the colour the surface multiplies light by (kd, the field colour, edges)
  std::vector<Vec3> normal;  // world space, towards the viewer; not renormalised after averaging
  std::vector<float> depth;  // world units from the eye along the ray (orthographic: from the view plane)
  // The variance of the pixel's mean luminance, from the spread of its samples (the path tracer's);
  // negative where the pass that made the features did not know it.
  std::vector<float> variance;

  FeatureBuffers() = default;
  FeatureBuffers(int w, int h)
      : width(w),
        height(h),
        albedo(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)),
        normal(albedo.size()),
        depth(albedo.size()),
        variance(albedo.size(), -1.0f) {}
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
};

// The variance of the mean of `samples` values from their sum and the sum of their squares; negative
// (unknown) for a single sample.
inline float varianceOfMean(int samples, double sum, double squares) {
  if (samples < 2) return -1.0f;
  const double spread = squares - sum * sum / samples;
  return static_cast<float>((spread > 0 ? spread : 0.0) / (static_cast<double>(samples) * (samples - 1)));
}

// One camera sample's view of the first surface.
struct SurfaceFeatures {
  Vec3 albedo{0, 0, 0};
  Vec3 normal{0, 0, 0};
  float depth = 0;
  bool hit = false;
};

// The running sum of one pixel's samples' features, and the pixel's value in the buffers.
struct FeatureSum {
  Vec3 albedo{0, 0, 0}, normal{0, 0, 0};
  float depth = 0;
  int hits = 0;
  void add(const SurfaceFeatures& seen) {
    albedo += seen.albedo;
    normal += seen.normal;
    if (seen.hit) {
      depth += seen.depth;
      ++hits;
    }
  }
  // The mean of `samples` samples into pixel k of `buffers`.
  void store(FeatureBuffers& buffers, std::size_t k, int samples) const;
};

class SceneQueries;
class EdgePaint;
struct EnergySplit;

// The share of the light leaving a point that its colour multiplies: kd for the local part; the
// reflected and transmitted parts carry what they meet, not kd (Open Image Denoise's convention).
Vec3 featureAlbedo(const Vec3& kd, const EnergySplit& split);

// What `ray` sees first, as the integrators see it (cut views, caps, the shadow catcher, field
// colours, drawn edges), without any light. `background`: the albedo of a miss and of the catcher;
// `linearFieldColors`: field colours decoded to linear, as an sRGB render shows them.
SurfaceFeatures surfaceFeatures(const SceneQueries& queries, const EdgePaint& paint, const Ray& ray,
                                const Vec3& background, bool linearFieldColors);

}  // namespace lancer
