#include "lancer/render/clip_planes.hpp"

namespace lancer {

ClipInterval clipRay(const Ray& ray, std::span<const ClipPlane> planes) {
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
    }
  }
  return interval;
}

bool isClipped(const Vec3& p, std::span<const ClipPlane> planes) {
  for (const ClipPlane& plane : planes)
    if (dot(p - plane.point, plane.normal) > 0.0f) return true;
  return false;
}

}  // namespace lancer
