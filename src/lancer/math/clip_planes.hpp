// Cut views (`[[clip]]`): half-spaces that remove geometry for every ray. Their intersection is
// convex, so along any ray the kept part is one interval, found once per ray with no per-face test.
#pragma once

#include <limits>
#include <span>

#include "lancer/math/ray.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// Geometry on the side the normal points to (dot(p - point, normal) > 0) is removed.
struct ClipPlane {
  Vec3 point;   // scene space
  Vec3 normal;  // unit
};

// The part of a ray kept by a set of planes: t in [enter, exit]. `enterPlane` is the plane the ray
// crosses at `enter` (-1 when it starts inside the kept region), where a cap is drawn.
struct ClipInterval {
  float enter = 0;
  float exit = std::numeric_limits<float>::infinity();
  int enterPlane = -1;
  bool empty() const { return !(enter <= exit); }
};

ClipInterval clipRay(const Ray& ray, std::span<const ClipPlane> planes);

// True when p is removed by one of the planes.
bool isClipped(const Vec3& p, std::span<const ClipPlane> planes);

}  // namespace lancer
