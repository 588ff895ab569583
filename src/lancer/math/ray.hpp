// A ray with its origin, direction and the reciprocal direction that slab tests need.
// Rays live in scene space (float, relative to the scene's origin) and are never heap-allocated.
#pragma once

#include <utility>

#include "lancer/math/vec3.hpp"

namespace lancer {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // not necessarily unit length; t is measured in units of |direction|
  Vec3 invDirection;
  // The watertight triangle test's frame (Woop, Benthin & Wald 2013, section 3): kz is the axis along
  // which the direction is largest, and the shear maps the direction to (0, 0, 1).
  int kx = 0, ky = 1, kz = 2;
  float shearX = 0, shearY = 0, shearZ = 1;

  Ray() = default;
  Ray(const Vec3& o, const Vec3& d)
      : origin(o), direction(d), invDirection{1.0f / d.x, 1.0f / d.y, 1.0f / d.z} {
    const float ax = d.x < 0 ? -d.x : d.x, ay = d.y < 0 ? -d.y : d.y, az = d.z < 0 ? -d.z : d.z;
    kz = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    const float dz = kz == 0 ? d.x : (kz == 1 ? d.y : d.z);
    if (dz < 0.0f) std::swap(kx, ky);  // keeps the triangles' winding in the sheared frame
    shearZ = 1.0f / dz;
    shearX = (kx == 0 ? d.x : (kx == 1 ? d.y : d.z)) * shearZ;
    shearY = (ky == 0 ? d.x : (ky == 1 ? d.y : d.z)) * shearZ;
  }

  Vec3 at(float t) const { return origin + direction * t; }
};

}  // namespace lancer
