// Mesh faces with `emission` as lights for next-event estimation: a distribution over their
// triangles by area times emitted power, built once per render, and the pdf the reverse question
// needs (a path that hit an emissive face: how likely was light sampling to pick that point).
//
// Estimator: a triangle t is chosen with probability A_t P_t / sum(A P) (P: the mean of the
// emission's channels), a point on it uniformly, so the density per area is P_t / sum(A P) on every
// emissive face; per solid angle from a point at distance d, p = (P_t / sum(A P)) d^2 / |cos_l|.
// Faces emit on both sides, as a path that meets either side counts their emission.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/render/light_sampling.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

class EmissiveFaces {
 public:
  EmissiveFaces() = default;  // none
  explicit EmissiveFaces(const Scene& scene);

  bool empty() const { return triangles_.empty(); }
  std::size_t triangleCount() const { return triangles_.size(); }

  // A point of an emissive face seen from `point`, by (u, v) in [0, 1)^2: `sample.target` is just
  // off the face towards `point`, `weight` its radiance over the pdf per solid angle. False when the
  // point lies in the face's plane.
  bool sample(const Vec3& point, float u, float v, LightSample& sample) const;

  // The pdf per solid angle with which sample() picks the point of `face` at `distance` from the
  // viewer along a direction of cosine `cosLight` with the face's normal; 0 for a face it never picks.
  float pdf(std::uint32_t face, float distance, float cosLight) const;

 private:
  struct Triangle {
    Vec3 a, ab, ac;
    Vec3 normal;  // unit, the face's
    Vec3 emission;
  };
  float areaDensity(const Vec3& emission) const;

  const Scene* scene_ = nullptr;
  std::vector<Triangle> triangles_;
  std::vector<float> cumulative_;  // over triangles_, ending at 1
  float totalPower_ = 0;           // sum of area x power
};

}  // namespace lancer
