// The environment as the path tracer and ambient occlusion see it: the radiance arriving from every
// direction (uniform, a gradient sky, or an equirectangular map turned about the scene's up), and
// for a map, importance sampling by its luminance (pbrt-v4 12.5: a piecewise-constant 2D
// distribution over the map, each cell weighted by sin(theta), the pdf per solid angle
// p(u, v) / (2 pi^2 sin(theta))). A uniform or gradient environment is found by the material's own
// samples (cosine-weighted for a diffuse face), so it needs no light sampling.
#pragma once

#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

class EnvironmentLight {
 public:
  EnvironmentLight() = default;  // black, nothing to sample
  explicit EnvironmentLight(const SceneEnvironment& environment);

  // Radiance arriving along -direction (unit direction pointing away from the scene).
  Vec3 radiance(const Vec3& direction) const;
  // Whether next-event estimation samples it (a map).
  bool sampled() const { return !marginal_.empty(); }
  // A direction by the map's luminance, its pdf per solid angle (0: none) and radiance.
  Vec3 sample(float u, float v, float& pdf, Vec3& radiance) const;
  float pdf(const Vec3& direction) const;
  bool black() const { return black_; }

 private:
  void mapCoordinates(const Vec3& direction, float& u, float& v) const;
  Vec3 mapDirection(float u, float v) const;

  SceneEnvironment environment_;
  bool black_ = true;
  Vec3 right_;
  std::vector<float> marginal_;     // cumulative over rows, marginal_[h] = 1
  std::vector<float> conditional_;  // per row, cumulative over its columns, each row ending at 1
  std::vector<float> rowWeight_;    // sum of a row's cells
  float total_ = 0;                 // sum of every cell
};

}  // namespace lancer
