// A ray with its origin, direction and the reciprocal direction that slab tests need.
// Rays live in scene space (float, relative to the scene's origin) and are never heap-allocated.
#pragma once

#include "lancer/math/vec3.hpp"

namespace lancer {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // not necessarily unit length; t is measured in units of |direction|
  Vec3 invDirection;

  Ray() = default;
  Ray(const Vec3& o, const Vec3& d)
      : origin(o), direction(d), invDirection{1.0f / d.x, 1.0f / d.y, 1.0f / d.z} {}

  Vec3 at(float t) const { return origin + direction * t; }
};

}  // namespace lancer
