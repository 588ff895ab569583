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
  float exitRate = 0;  // the exit plane's dot(direction, normal) (> 0); 0 when no plane ends the ray
  bool empty() const { return !(enter <= exit); }
};

// The kept interval of `ray` (t in units of |direction|).
inline ClipInterval clipRay(const Ray& ray, std::span<const ClipPlane> planes) {
  ClipInterval interval;
  for (int i = 0; i < static_cast<int>(planes.size()); ++i) {
    const ClipPlane& plane = planes[static_cast<std::size_t>(i)];
    // Signed height of the origin above the plane and its rate of change along the ray.
    const float height = dot(ray.origin - plane.point, plane.normal);
    const float rate = dot(ray.direction, plane.normal);
    if (rate == 0.0f) {
      if (height > 0.0f) interval.exit = -1.0f;  // parallel, entirely on the removed side
      continue;
    }
    const float crossing = -height / rate;
    if (rate < 0.0f) {  // going down into the kept side: kept from the crossing on
      if (crossing > interval.enter) {
        interval.enter = crossing;
        interval.enterPlane = i;
      }
    } else if (crossing < interval.exit) {  // going up out of it: kept until the crossing
      interval.exit = crossing;
      interval.exitRate = rate;
    }
  }
  return interval;
}

// True when p is removed by one of the planes.
inline bool isClipped(const Vec3& p, std::span<const ClipPlane> planes) {
  for (const ClipPlane& plane : planes)
    if (dot(p - plane.point, plane.normal) > 0.0f) return true;
  return false;
}

}  // namespace lancer
