// Axis-aligned bounding boxes: scene framing, kd-tree cells and the ray/slab test.
#pragma once

#include <cmath>
#include <limits>

#include "lancer/math/ray.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

template <typename T>
struct AabbT {
  Vec3T<T> lower{std::numeric_limits<T>::max(), std::numeric_limits<T>::max(), std::numeric_limits<T>::max()};
  Vec3T<T> upper{-std::numeric_limits<T>::max(), -std::numeric_limits<T>::max(),
                 -std::numeric_limits<T>::max()};

  bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
  void extend(const Vec3T<T>& p) {
    lower = min(lower, p);
    upper = max(upper, p);
  }
  void extend(const AabbT& b) {
    lower = min(lower, b.lower);
    upper = max(upper, b.upper);
  }
  Vec3T<T> extent() const { return empty() ? Vec3T<T>{} : upper - lower; }
  Vec3T<T> center() const { return (lower + upper) * T(0.5); }
  int longestAxis() const {
    Vec3T<T> e = extent();
    return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  }
  T surfaceArea() const {
    Vec3T<T> e = extent();
    return T(2) * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

using Aabb = AabbT<float>;
using Aabbd = AabbT<double>;

// The box grown by a relative margin, so that a ray clipped to it keeps the hits that rounding puts
// on its faces (the accelerators' scene boxes).
inline Aabb paddedBounds(const Aabb& box) {
  if (box.empty()) return box;
  const float pad = 1e-5f * maxComponent(box.extent()) + 1e-30f;
  Aabb padded = box;
  for (int axis = 0; axis < 3; ++axis) {
    padded.lower[axis] -= pad + 1e-6f * std::abs(box.lower[axis]);
    padded.upper[axis] += pad + 1e-6f * std::abs(box.upper[axis]);
  }
  return padded;
}

// Slab test (Kay & Kajiya); returns the entry/exit parameters clipped to [tMin, tMax].
inline bool intersectAabb(const Aabb& box, const Ray& ray, float tMin, float tMax, float& tEnter,
                          float& tExit) {
  for (int axis = 0; axis < 3; ++axis) {
    float t0 = (box.lower[axis] - ray.origin[axis]) * ray.invDirection[axis];
    float t1 = (box.upper[axis] - ray.origin[axis]) * ray.invDirection[axis];
    if (t0 > t1) std::swap(t0, t1);
    // NaN (0 * inf when the origin lies on a slab face of a parallel ray) must not shrink the span.
    tMin = t0 > tMin ? t0 : tMin;
    tMax = t1 < tMax ? t1 : tMax;
  }
  tEnter = tMin;
  tExit = tMax;
  return tMin <= tMax;
}

}  // namespace lancer
